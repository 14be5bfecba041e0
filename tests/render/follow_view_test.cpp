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
  RenderSettings settings = small_follow();
  settings.speed = 1e-4;  // a shutter interval too short to streak: crisp lines where the world has them
  ClipRenderer renderer(p, motion, settings, theme, "Case 3");
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

// The grey of a pixel on white: how much of the (black) grid covers it, 0 .. 1.
double ink(const test::Rgb8& pixel) { return 1.0 - pixel.r / 255.0; }

// At 30 fps a line moves g t / 30 per frame: more than half a spacing above ~3 m/s. Each
// horizontal line is drawn as a band from where it was at t - 1/30 s to where it is at t,
// most opaque at t, so what the eye matches from frame to frame moves the right way.
TEST(FollowView, GridLinesStreakOverTheFramesShutterInterval) {
  const Params p;
  State s0;
  s0.theta1_dot = 0;
  s0.theta2_dot = 0;
  s0.x1_dot = 0;
  const Motion motion = test::closed_form_motion(p, s0, 31, 1.0 / 30, true);
  Theme theme = load_theme("light", {}, "--theme");
  theme.grid = {0, 0, 0, 1};  // black on white: the grey level is the coverage
  RenderSettings settings = small_follow();
  settings.elements.hide(Element::blocks);
  settings.elements.hide(Element::com);
  settings.elements.hide(Element::pin);
  settings.elements.hide(Element::trail);
  settings.elements.hide(Element::gravity);
  settings.elements.hide(Element::pin_force);
  settings.elements.hide(Element::labels);
  settings.elements.hide(Element::legend);
  ClipRenderer renderer(p, motion, settings, theme, "Case 3");
  const double spacing = renderer.grid().spacing.metres();
  Frame frame(settings.width, settings.height);
  const int column = 250;  // clear of the labels (left), the legend (bottom) and the insets (right)
  for (const std::size_t k : {std::size_t{3}, std::size_t{12}, std::size_t{30}}) {
    SCOPED_TRACE(k);
    renderer.draw(k, frame);
    const Camera now = renderer.camera_at(k), then = renderer.shutter_camera_at(k);
    // G fell -v dt - g dt^2 / 2 in the interval (v its velocity now): the camera with it.
    const double vy = system_com_velocity(motion.samples[k].state).y(), dt = 1.0 / 30;
    EXPECT_NEAR(then.centre().y() - now.centre().y(), -vy * dt - 0.5 * p.g * dt * dt, 1e-9);
    const double band = (then.centre().y() - now.centre().y()) * now.scale();  // px each line moved up
    ASSERT_GT(band, 1.0);
    // Every line between the frame's top and bottom thirds: dark where it is now, and the
    // band below it (where it was) covered, fading with age.
    const View visible = now.visible();
    int lines = 0;
    for (double y = spacing * std::ceil(visible.ymin / spacing); y < visible.ymax; y += spacing) {
      const double row_now = now.to_pixels({0.0, y}).y(), row_then = then.to_pixels({0.0, y}).y();
      EXPECT_NEAR(row_then - row_now, band, 1e-6);
      if (row_now < 90 || row_then > 330 || row_then - row_now > 0.9 * spacing * now.scale()) continue;
      ++lines;
      const double head = ink(test::rgb_at(frame, column, static_cast<int>(row_now + 1)));
      const double middle = ink(test::rgb_at(frame, column, static_cast<int>(0.5 * (row_now + row_then))));
      const double tail = ink(test::rgb_at(frame, column, static_cast<int>(row_then - 1)));
      EXPECT_GT(head, 0.05);
      EXPECT_GT(middle, 0.0);
      EXPECT_GT(head, middle);
      EXPECT_GE(middle, tail);
      // Above the newest end, no ink of this line (the gap to the next line's band).
      EXPECT_LT(ink(test::rgb_at(frame, column, static_cast<int>(row_now - 3))), head);
    }
    if (k == 3) {
      EXPECT_GE(lines, 2);
    }
  }
  // The band's opacity: the still line's ink spread over it, never below half a spacing's worth.
  EXPECT_DOUBLE_EQ(grid_streak_opacity(0.5, 1, 100), 1.0);
  EXPECT_DOUBLE_EQ(grid_streak_opacity(3, 1, 100), 0.5);
  EXPECT_DOUBLE_EQ(grid_streak_opacity(400, 1, 100), 0.125);  // four lines' bands overlap
}

TEST(FollowView, PathInsetShowsTheWholePathAheadAtTimeZero) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 61, 0.1, true);
  Theme theme = load_theme("light", {}, "--theme");
  theme.text_muted = {1, 0, 1, 1};  // the dotted path ahead (and the inset's words)
  theme.trail = {0, 1, 1, 1};       // the path behind
  RenderSettings settings = small_follow();
  settings.duration = 10;
  ClipRenderer renderer(p, motion, settings, theme, "Case 3");
  const PathInset& inset = renderer.path_inset();
  Frame frame(settings.width, settings.height);
  const auto count = [&](const Rgba& colour, double from, double to) {  // on the path, between these fractions
    int n = 0;
    for (std::size_t i = 0; i < inset.path.size(); ++i) {
      const double f = static_cast<double>(i) / static_cast<double>(inset.path.size() - 1);
      if (f < from || f > to) continue;
      const Vec2 at = inset.to_pixels(inset.path[i]);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          // Tinted towards the colour (antialiased thin dots blend with the panel): its
          // zero channel well below the others.
          const test::Rgb8 c = test::rgb_at(frame, static_cast<int>(at.x()) + dx, static_cast<int>(at.y()) + dy);
          n += colour.g == 0 ? (c.g < 200 && c.r > 220 && c.b > 220) : (c.r < 200 && c.g > 220 && c.b > 220);
        }
    }
    return n;
  };
  renderer.draw(0, frame);
  EXPECT_GT(count(theme.text_muted, 0.2, 1.0), 10);  // the parabola to come, dotted
  EXPECT_EQ(count(theme.trail, 0.2, 1.0), 0);        // nothing travelled yet
  renderer.draw(60, frame);                          // t = 6 s of 10: G has fallen 36% of the way
  EXPECT_GT(count(theme.trail, 0.2, 0.55), 0);
  EXPECT_EQ(count(theme.trail, 0.7, 1.0), 0);
  EXPECT_GT(count(theme.text_muted, 0.7, 1.0), 5);
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
