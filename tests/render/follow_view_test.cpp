// What a camera following the fall shows: grid lines fixed in the world streaming past,
// the lab-frame inset with G moving along its parabola, and trails fading with age.
#include <gtest/gtest.h>

#include <cmath>

#include "model/kinematics.hpp"
#include "render/clip_renderer.hpp"
#include "render/scene_painter.hpp"
#include "render_test_support.hpp"

namespace linkage {
namespace {

RenderSettings small_follow() {
  RenderSettings s;
  s.width = 640;
  s.height = 360;
  s.camera = CameraMode::follow;
  return s;
}

bool is(const test::Rgb8& pixel, const Rgba& colour) { return test::colour_distance(pixel, test::rgb8(colour)) == 0; }

// Rows where most of the frame's width has the grid's exact colour: the horizontal lines.
std::vector<int> grid_rows(const Frame& frame, const Rgba& grid) {
  std::vector<int> rows;
  for (int y = 0; y < frame.height; ++y) {
    int n = 0;
    for (int x = 0; x < frame.width; ++x) n += is(test::rgb_at(frame, x, y), grid) ? 1 : 0;
    if (n > frame.width * 2 / 5) rows.push_back(y);
  }
  return rows;
}

TEST(FollowView, GridLinesStayAtWorldHeightsWhileTheBlocksFall) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 121, 1.0 / 30, true);
  Theme theme = load_theme("light", {}, "--theme");
  theme.grid = {1, 0, 1, 1};  // unique
  ClipRenderer renderer(p, motion, small_follow(), theme, "Case 3");
  const double spacing = renderer.grid().spacing.metres();
  EXPECT_TRUE(renderer.grid().name_every);
  Frame frame(640, 360);
  std::vector<double> middle;  // the height of the line nearest G at each time: what its label says
  for (const std::size_t k : {std::size_t{0}, std::size_t{60}, std::size_t{120}}) {
    SCOPED_TRACE(k);
    renderer.draw(k, frame);
    const Camera camera = renderer.camera_at(k);
    const std::vector<int> rows = grid_rows(frame, theme.grid);
    ASSERT_GE(rows.size(), 3u);  // a handful of lines in view
    for (const int row : rows) {
      const double y = camera.to_world({0.0, row + 0.5}).y();
      const double off = y - spacing * std::round(y / spacing);
      EXPECT_LT(std::fabs(off) * camera.scale(), 1.0) << "row " << row << " is at y = " << y << " m";
    }
    int nearest = rows.front();
    for (const int row : rows)
      if (std::abs(row - 180) < std::abs(nearest - 180)) nearest = row;
    middle.push_back(spacing * std::round(camera.to_world({0.0, nearest + 0.5}).y() / spacing));
  }
  // The lines the frame shows change by the distance G fell (about g t^2 / 2: 19 m at
  // 2 s, 77 m at 4 s), to within a line and a half (the one nearest G may be behind a body).
  const auto fallen = [&](std::size_t k) {
    return system_com(motion.samples[0].state).y() - system_com(motion.samples[k].state).y();
  };
  EXPECT_GT(fallen(60), 15.0);
  EXPECT_NEAR(middle[0] - middle[1], fallen(60), 1.5 * spacing);
  EXPECT_NEAR(middle[0] - middle[2], fallen(120), 1.5 * spacing);
}

TEST(FollowView, InsetMarkerMovesAlongThePathOfG) {
  const Params p;
  State s0;  // not turning, so the closed-form motion's G is exactly a projectile's
  s0.theta1_dot = 0;
  s0.theta2_dot = 0;
  const Motion motion = test::closed_form_motion(p, s0, 121, 1.0 / 30, true);
  Theme theme = load_theme("light", {}, "--theme");
  theme.com = {0, 1, 1, 1};  // unique
  RenderSettings settings = small_follow();
  settings.duration = 10;
  ClipRenderer renderer(p, motion, settings, theme, "Case 3");
  const PathInset& inset = renderer.path_inset();
  ASSERT_FALSE(inset.inset.rect.empty());
  EXPECT_EQ(inset.inset.caption, "path of the centre of mass, 0\u201310 s");
  ASSERT_GE(inset.path.size(), 2u);
  // The whole parabola: from G at t = 0 down g 10^2 / 2.
  const Vec2 g0 = system_com(motion.samples.front().state);
  const Vec2 v0 = system_com_velocity(motion.samples.front().state);
  EXPECT_NEAR((inset.path.front() - g0).norm(), 0, 1e-12);
  EXPECT_NEAR(inset.path.back().y(), g0.y() + 10 * v0.y() - 0.5 * p.g * 100, 1e-9);

  Frame frame(settings.width, settings.height);
  std::vector<Vec2> marks;
  for (const std::size_t k : {std::size_t{0}, std::size_t{60}, std::size_t{120}}) {
    SCOPED_TRACE(k);
    const Vec2 g = system_com(motion.samples[k].state);
    // G lies on the drawn path (a path point falls on each of these times).
    double nearest = 1e300;
    for (const Vec2& q : inset.path) nearest = std::min(nearest, (q - g).norm());
    EXPECT_LT(nearest, 1e-9);
    const Vec2 at = inset.to_pixels(g);
    const Rect& plot = inset.inset.plot;
    EXPECT_TRUE(at.x() >= plot.x && at.x() <= plot.x + plot.width && at.y() >= plot.y &&
                at.y() <= plot.y + plot.height);
    renderer.draw(k, frame);
    int found = 0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx)
        found += is(test::rgb_at(frame, static_cast<int>(at.x()) + dx, static_cast<int>(at.y()) + dy), theme.com);
    EXPECT_GT(found, 3) << "no marker at G in the inset";
    if (!marks.empty()) {
      EXPECT_GT(at.y(), marks.back().y() + 3);  // lower in the inset than before
    }
    if (k == 120) {
      // 78 m below where it started, and the place at t = 0 is clear.
      EXPECT_GT(at.y(), marks.front().y() + 12);
      int left = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          left +=
              is(test::rgb_at(frame, static_cast<int>(marks.back().x()) + dx, static_cast<int>(marks.back().y()) + dy),
                 theme.com);
      EXPECT_EQ(left, 0);
    }
    marks.push_back(at);
  }
}

TEST(FollowView, TrailOpacityFallsWithTheSquareOfItsFade) {
  const Theme theme = load_theme("light", {}, "--theme");
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 1.0), theme.trail.a);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 0.5), 0.25 * theme.trail.a);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, -0.2), 0.0);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 1.5), theme.trail.a);
}

// A fit camera over a long fall shows the blocks a few pixels long: an inset shows them
// at a size that reads, its magnification in the caption.
TEST(FollowView, FitOverALongFallInsetsTheBodies) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 91, 1.0 / 30, true);
  RenderSettings settings = small_follow();
  settings.camera = CameraMode::fit;
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  ASSERT_FALSE(renderer.bodies_inset().rect.empty());
  EXPECT_TRUE(renderer.path_inset().inset.rect.empty());
  EXPECT_NE(renderer.bodies_inset().caption.find("enlarged"), std::string::npos);
  // A short motion fits the blocks large enough: no inset.
  const Motion brief = test::closed_form_motion(p, State{}, 4, 1.0 / 30, true);
  ClipRenderer near(p, brief, settings, load_theme("light", {}, "--theme"), "Case 3");
  EXPECT_TRUE(near.bodies_inset().rect.empty());
}

}  // namespace
}  // namespace linkage
