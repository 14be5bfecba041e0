#include "render/clip_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/error.hpp"
#include "model/kinematics.hpp"
#include "render_test_support.hpp"

namespace linkage {
namespace {

// The light theme with the colours under test made unique, so a pixel of that exact
// colour can only come from that element.
Theme marked_theme() {
  Theme theme = load_theme("light", {}, "--theme");
  theme.pin_fill = {1, 0, 1, 1};     // magenta
  theme.pin_force = {0, 0.8, 0, 1};  // pure green
  theme.gravity = {0, 0, 0.8, 1};    // pure blue
  return theme;
}

RenderSettings small_settings() {
  RenderSettings s;
  s.width = 640;
  s.height = 360;
  return s;
}

bool is(const test::Rgb8& pixel, const Rgba& colour) { return test::colour_distance(pixel, test::rgb8(colour)) == 0; }

TEST(ClipRenderer, PinIsDrawnWhereTheCameraProjectsP) {
  const Params p;
  const State s;
  const Motion motion = test::still_motion(p, s, true);
  const Theme theme = marked_theme();
  for (const CameraMode mode : {CameraMode::follow, CameraMode::fit}) {
    RenderSettings settings = small_settings();
    settings.camera = mode;
    ClipRenderer renderer(p, motion, settings, theme, "Case 3");
    Frame frame(settings.width, settings.height);
    renderer.draw(0, frame);
    const Vec2 expected = renderer.camera_at(0).to_pixels(derive(p, s).pin);
    // The centroid of the magenta disc (pixel centres at +0.5).
    double sx = 0, sy = 0, n = 0;
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x)
        if (is(test::rgb_at(frame, x, y), theme.pin_fill)) {
          sx += x + 0.5;
          sy += y + 0.5;
          ++n;
        }
    ASSERT_GT(n, 4) << "no pin drawn";
    EXPECT_NEAR(sx / n, expected.x(), 0.35);
    EXPECT_NEAR(sy / n, expected.y(), 0.35);
  }
}

// True when a pixel of the 3x3 block around `at` has exactly `colour` (antialiased
// edges of a slanted line blend, its core does not).
bool near(const Frame& frame, const Vec2& at, const Rgba& colour) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (is(test::rgb_at(frame, static_cast<int>(at.x()) + dx, static_cast<int>(at.y()) + dy), colour)) return true;
  return false;
}

TEST(ClipRenderer, ForceArrowsPointTheRightWay) {
  const Params p;
  State s;
  s.theta1_dot = 2.0;  // a pin force well away from zero
  const Motion motion = test::still_motion(p, s, true);
  const Theme theme = marked_theme();
  RenderSettings settings;  // 1280x720: lines several pixels wide
  settings.elements.hide(Element::labels);
  ClipRenderer renderer(p, motion, settings, theme, "Case 3");
  Frame frame(settings.width, settings.height);
  renderer.draw(0, frame);
  if (const auto folder = test::picture_folder(); !folder.empty()) test::write_png_file(frame, folder / "arrows.png");
  const Camera camera = renderer.camera_at(0);
  const DrawStyle style{&theme, DrawStyle::unit_for(settings.width, settings.height)};

  const Vec2 force = test::pin_force_at(p, s);  // from the Case 3 solve, independent of the scene
  const double length = force.norm() * renderer.scene_options().arrow_scales[0].metres_per_unit * camera.scale();
  ASSERT_GT(length, 4 * style.arrow_head_length());
  const Vec2 pin = camera.to_pixels(derive(p, s).pin);
  for (const double sign : {1.0, -1.0}) {  // F on block 1, -F on block 2
    const Vec2 world_direction = sign * force.normalized();
    const Vec2 direction(world_direction.x(), -world_direction.y());  // y down in pixels
    const Vec2 normal(-direction.y(), direction.x());
    // The shaft runs from P along the force...
    for (double f = 0.25; f <= 0.65; f += 0.05)
      EXPECT_TRUE(near(frame, pin + f * length * direction, theme.pin_force)) << sign << " " << f;
    // ...the head, wider than the shaft, is at its far end...
    const double off = 0.43 * style.arrow_head_half_width();
    const Vec2 head = pin + (length - 0.6 * style.arrow_head_length()) * direction;
    EXPECT_TRUE(near(frame, head + off * normal, theme.pin_force)) << sign;
    EXPECT_TRUE(near(frame, head - off * normal, theme.pin_force)) << sign;
    const Vec2 shaft = pin + 0.4 * length * direction;
    EXPECT_FALSE(near(frame, shaft + off * normal, theme.pin_force)) << sign;
    EXPECT_FALSE(near(frame, shaft - off * normal, theme.pin_force)) << sign;
    // ...and nothing lies beyond the tip.
    EXPECT_FALSE(near(frame, pin + (length + 4) * direction, theme.pin_force)) << sign;
  }
  // Gravity points down from each centre of mass.
  const BodyState b = body_state(p, s);
  for (const Vec2& c : {Vec2(b.x1, b.y1), Vec2(b.x2, b.y2)}) {
    const Vec2 at = camera.to_pixels(c);
    const double weight = p.m * p.g * renderer.scene_options().arrow_scales[1].metres_per_unit * camera.scale();
    EXPECT_TRUE(near(frame, at + Vec2(0, 0.5 * weight), theme.gravity));
    EXPECT_FALSE(near(frame, at - Vec2(0, 0.5 * weight), theme.gravity));
  }
}

// The least length is compared with what is drawn, in pixels: an arrow reads as one down
// to a head's length (its head then 60% of full size). The fast-spin still at one scale
// (1 cm = 150 mN) drew a 302 mN pin force dashed at 1280x720 although its true length,
// about 19 px, shows a head and a shaft; below a head's length it is stretched, drawn 3
// heads long so the dashes show.
TEST(ClipRenderer, ArrowsAreStretchedOnlyWhenShorterThanAHeadOnScreen) {
  const Params p;
  Motion motion = test::still_motion(p, State{}, true);
  RenderSettings settings;
  settings.width = 1280;
  settings.height = 720;
  settings.arrow_scale.common = true;
  settings.arrow_scale.common_units_per_cm = 0.15;
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  const double scale = renderer.camera_at(0).scale();
  DrawStyle style;
  style.u = DrawStyle::unit_for(settings.width, settings.height);
  EXPECT_NEAR(renderer.scene_options().shortest_arrow * scale, style.arrow_head_length(), 1e-9);
  const auto pin_arrow = [&](double newtons) {
    motion.samples[0].pin_force = Vec2(newtons, 0.0);
    DrawList list;
    build_scene(p, renderer.scene_options(), motion, 0, list);
    for (const Arrow& arrow : list.arrows)
      if (arrow.kind == ArrowKind::pin_force) return arrow;
    ADD_FAILURE() << "no pin-force arrow";
    return Arrow{};
  };
  const Arrow seen = pin_arrow(0.302);
  const double true_px = 0.302 * (0.01 / 0.15) * scale;
  EXPECT_GT(true_px, style.arrow_head_length());
  EXPECT_LT(true_px, stretched_arrow_px(style));  // what the old least length (3 heads) stretched
  EXPECT_FALSE(seen.stretched);
  EXPECT_TRUE(seen.valued);  // at one scale the label gives the value
  EXPECT_NEAR(seen.vector.norm() * scale, true_px, 1e-9);
  const Arrow tiny = pin_arrow(0.05);  // 3 px at its scale
  EXPECT_TRUE(tiny.stretched);
  EXPECT_NEAR(tiny.vector.norm() * scale, stretched_arrow_px(style), 1e-9);
  EXPECT_NEAR(tiny.magnitude, 0.05, 1e-15);
}

TEST(ClipRenderer, StaticLayersAreDrawnOnceForAClip) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 12, 1.0 / 30, true);
  RenderSettings settings = small_settings();
  ClipRenderer renderer(p, motion, settings, load_theme("dark", {}, "--theme"), "Case 3");
  std::vector<Frame> buffers(3, Frame(settings.width, settings.height));  // as a pipeline cycles them
  for (std::size_t k = 0; k < motion.samples.size(); ++k) renderer.draw(k, buffers[k % 3]);
  EXPECT_EQ(renderer.stats().frames_drawn, 12);
  EXPECT_EQ(renderer.stats().static_layer_draws, 4);  // background + grid, title, legend, scale bar
  EXPECT_GT(renderer.stats().trail_points_drawn, 12);

  // Without the trail no trail point is ever built; without title and legend only the
  // background is cached.
  RenderSettings bare = settings;
  bare.elements.hide(Element::trail);
  bare.elements.hide(Element::title);
  bare.elements.hide(Element::legend);
  ClipRenderer plain(p, motion, bare, load_theme("dark", {}, "--theme"), "Case 3");
  for (std::size_t k = 0; k < motion.samples.size(); ++k) plain.draw(k, buffers[k % 3]);
  EXPECT_EQ(plain.stats().trail_points_drawn, 0);
  EXPECT_EQ(plain.stats().static_layer_draws, 1);
}

TEST(ClipRenderer, SameInputsSamePixelsWhicheverBuffer) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 5, 0.1, true);
  RenderSettings settings = small_settings();
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  Frame a(settings.width, settings.height), b(settings.width, settings.height);
  renderer.draw(4, a);
  renderer.draw(2, b);  // something else in between
  renderer.draw(4, b);
  EXPECT_EQ(a.pixels, b.pixels);
  Frame wrong(320, 180);
  EXPECT_THROW(renderer.draw(0, wrong), Error);
}

// The spec's example at t = 2 s of a closed-form motion, 640x360, every element: compared
// pixel for pixel with tests/data/render/. After a deliberate change of the look,
// regenerate with: LINKAGE_UPDATE_GOLDENS=1 build/test_render --gtest_filter='Golden*'
void check_golden(const std::string& name, const RenderSettings& settings, const Motion& motion, std::size_t index) {
  const Params p;
  ClipRenderer renderer(p, motion, settings, load_theme(settings.theme, {}, "--theme"), "Case 3 \u00b7 dop853");
  Frame frame(settings.width, settings.height);
  renderer.draw(index, frame);
  const std::filesystem::path golden =
      std::filesystem::path(LINKAGE_SOURCE_DIR) / "tests/data/render" / (name + ".png");
  if (const char* update = std::getenv("LINKAGE_UPDATE_GOLDENS"); update != nullptr && std::string(update) == "1") {
    test::write_png_file(frame, golden);
    GTEST_SKIP() << "wrote " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; see the comment above check_golden";
  const Frame expected = test::read_png_file(golden);
  ASSERT_EQ(expected.width, frame.width);
  ASSERT_EQ(expected.height, frame.height);
  long differing = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      if (test::colour_distance(test::rgb_at(frame, x, y), test::rgb_at(expected, x, y)) != 0) ++differing;
  if (differing > 0) {
    const std::filesystem::path actual = std::filesystem::temp_directory_path() / (name + ".actual.png");
    test::write_png_file(frame, actual);
    ADD_FAILURE() << differing << " pixels differ from " << golden << "; this run's picture: " << actual;
  }
}

TEST(Golden, LightFollowEveryElement) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 61, 1.0 / 30, true);
  RenderSettings settings = small_settings();
  settings.elements = ElementSet::all();
  check_golden("light_follow_640x360", settings, motion, 60);
}

TEST(Golden, PrintFitWithAxes) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 16, 1.0 / 30, true);
  RenderSettings settings = small_settings();
  settings.theme = "print";
  settings.camera = CameraMode::fit;
  settings.elements.show(Element::axes);
  check_golden("print_fit_640x360", settings, motion, 15);
}

}  // namespace
}  // namespace linkage
