// The homework's clip through the one path (two-blocks.toml, MechanismClipFrames): the
// frames drawn are the ones the clip encodes, the same whichever buffer; two goldens
// pixel for pixel; marks scale with the frame; a following camera's grid stays put in the
// world and streaks over the frame's interval; the panel's angles in degrees; the bodies
// stay above the equations' band.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/panel_data.hpp"
#include "render/cairo_util.hpp"
#include "render/frame_layout.hpp"
#include "render/mechanism_forces.hpp"
#include "render/overlays.hpp"
#include "render/render_test_support.hpp"
#include "render/scene_painter.hpp"
#include "scene/mechanism_scene.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {
namespace fs = std::filesystem;

/// The homework as `linkage render` draws it by default: two-blocks.toml as shipped.
struct TwoBlocks {
  sym::System system{load_mechanism("two-blocks")};
  GiNaC::exmap initial = sym::checked_initial_state(system).state;
};
const TwoBlocks& two_blocks() {
  static const TwoBlocks made;
  return made;
}

/// Its default clip (the file's title and trail, the light theme), `duration` s at
/// width x height and 30 fps.
MechanismClip homework_clip(int width, int height, double duration, const std::string& theme = "light") {
  const Mechanism& mechanism = two_blocks().system.mechanism();
  MechanismClip clip;
  clip.settings.width = width;
  clip.settings.height = height;
  clip.settings.duration = duration;
  clip.settings.title = mechanism.picture.title;
  clip.simulation.duration = duration;
  clip.trails = mechanism.picture.trails;
  clip.theme = load_theme(theme, {}, "theme");
  return clip;
}

bool is(const test::Rgb8& pixel, const Rgba& colour) { return test::colour_distance(pixel, test::rgb8(colour)) == 0; }

TEST(TwoBlocksClip, FramesAreTheOnesTheClipEncodes) {
  test::TempDir dir;
  MechanismClip clip = homework_clip(320, 180, 0.2);
  clip.frames = dir / "frames";
  const ClipResult made = produce_mechanism_clip(two_blocks().system, two_blocks().initial, clip);
  ASSERT_EQ(made.stats.png_files_written, 6);
  ClipResult result;
  MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
  ASSERT_EQ(frames.count(), 6);
  Frame frame(320, 180);
  for (std::size_t k = 0; k < 6; ++k) {
    frames.draw(k, frame);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.png", k);
    EXPECT_EQ(test::read_png_file(dir / "frames" / name).pixels, frame.pixels) << k;
  }
  EXPECT_EQ(frames.stats().frames_drawn, 6);
  EXPECT_EQ(result.stats.samples, made.stats.samples);
}

TEST(TwoBlocksClip, SameInputsSamePixelsWhicheverBuffer) {
  const MechanismClip clip = homework_clip(640, 360, 0.5);
  ClipResult result;
  MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
  Frame a(640, 360), b(640, 360);
  frames.draw(12, a);
  frames.draw(6, b);  // something else in between
  frames.draw(12, b);
  EXPECT_EQ(a.pixels, b.pixels);
  frames.draw(6, a);
  EXPECT_NE(a.pixels, b.pixels);
  Frame wrong(320, 180);
  EXPECT_THROW(frames.draw(0, wrong), Error);
}

// The homework's clip at t = 2 s, 640x360, every element but the equations (and a print
// still fit with axes at 0.5 s): compared pixel for pixel with tests/data/render/. After
// a deliberate change of the look, regenerate with:
// LINKAGE_UPDATE_GOLDENS=1 build/test_pipeline --gtest_filter='TwoBlocksGolden*'
void check_golden(const std::string& name, const MechanismClip& clip, std::size_t index) {
  ClipResult result;
  MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
  Frame frame(clip.settings.width, clip.settings.height);
  frames.draw(index, frame);
  const fs::path golden = fs::path(LINKAGE_SOURCE_DIR) / "tests/data/render" / (name + ".png");
  if (const char* update = std::getenv("LINKAGE_UPDATE_GOLDENS"); update != nullptr && std::string(update) == "1") {
    test::write_png_file(frame, golden);
    GTEST_SKIP() << "wrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; see the comment above check_golden";
  const Frame expected = test::read_png_file(golden);
  ASSERT_EQ(expected.width, frame.width);
  ASSERT_EQ(expected.height, frame.height);
  long differing = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      if (test::colour_distance(test::rgb_at(frame, x, y), test::rgb_at(expected, x, y)) != 0) ++differing;
  if (differing > 0) {
    const fs::path actual = fs::temp_directory_path() / (name + ".actual.png");
    test::write_png_file(frame, actual);
    ADD_FAILURE() << differing << " pixels differ from " << golden << "; this run's picture: " << actual;
  }
}

TEST(TwoBlocksGolden, LightFollowEveryElement) {
  MechanismClip clip = homework_clip(640, 360, 61 / 30.0);
  clip.settings.elements = ElementSet::all();
  clip.settings.elements.hide(Element::equations);
  check_golden("two_blocks_light_follow_640x360", clip, 60);
}

TEST(TwoBlocksGolden, PrintFitWithAxes) {
  MechanismClip clip = homework_clip(640, 360, 16 / 30.0, "print");
  clip.settings.camera_chosen = true;
  clip.settings.camera = CameraMode::fit;
  clip.settings.elements.show(Element::axes);
  check_golden("two_blocks_print_fit_640x360", clip, 15);
}

// The scene of the homework: each block a rectangle of its true size turned by its angle,
// the pin drawn where both blocks put P, and P's trail fading over its window to end at P.
TEST(TwoBlocksScene, BlocksHaveTheirTrueSizeAndTurnThePinIsAtPAndItsTrailEndsThere) {
  const sym::System& system = two_blocks().system;
  std::vector<double> times;
  for (int k = 0; k <= 120; ++k) times.push_back(k / 30.0);
  SimulationOptions options;
  options.duration = 4;
  ClipResult result;
  const MechanismMotion motion = sample_mechanism_motion(system, two_blocks().initial, options, times, 1, result);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {geometry.resolve("1.P", "trail")}, 2.0);
  MechanismDrawList list;
  const double L = 0.3, w = 0.1, D = L / 2 - 0.04;  // two-blocks.toml's L, w and D = L/2 - b
  const double pi = std::numbers::pi;
  for (const std::size_t k : {std::size_t{0}, std::size_t{45}, std::size_t{120}}) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const std::vector<double>& pose = motion.samples[k].pose;
    ASSERT_EQ(list.outlines.size(), 2U);
    for (const MechanismDrawList::Outline& outline : list.outlines) {
      const std::size_t b = outline.body;
      const Vec2 centre(pose[3 * b], pose[3 * b + 1]);
      const double theta = pose[3 * b + 2];
      ASSERT_EQ(outline.points.size(), 4U);
      const std::vector<Vec2>& c = outline.points;
      std::vector<double> sides{(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[3] - c[2]).norm(), (c[0] - c[3]).norm()};
      std::sort(sides.begin(), sides.end());
      EXPECT_NEAR(sides[0], w, 1e-12);
      EXPECT_NEAR(sides[1], w, 1e-12);
      EXPECT_NEAR(sides[2], L, 1e-12);
      EXPECT_NEAR(sides[3], L, 1e-12);
      const Vec2 along = (c[1] - c[0]).norm() > (c[2] - c[1]).norm() ? c[1] - c[0] : c[2] - c[1];
      const double turn = std::remainder(std::atan2(along.y(), along.x()) - theta, pi);
      EXPECT_NEAR(turn, 0, 1e-12) << "block " << b + 1;
      EXPECT_NEAR(((c[0] + c[2]) / 2 - centre).norm(), 0, 1e-12);
    }
    std::vector<Vec2> pins;
    for (const MechanismDrawList::Marker& marker : list.markers)
      if (marker.kind == MechanismDrawList::Marker::Kind::pin) pins.push_back(marker.at);
    ASSERT_EQ(pins.size(), 1U);
    for (std::size_t b = 0; b < 2; ++b)
      EXPECT_NEAR((pins[0] - Vec2(pose[3 * b], pose[3 * b + 1])).norm(), D, 1e-9) << "block " << b + 1;
    const MechanismDrawList::Line& trail = list.lines.back();
    ASSERT_EQ(trail.kind, MechanismDrawList::Line::Kind::trail);
    ASSERT_EQ(trail.fade.size(), trail.points.size());
    EXPECT_NEAR((trail.points.back() - pins[0]).norm(), 0, 1e-12);
    EXPECT_DOUBLE_EQ(trail.fade.back(), 1.0);
    for (std::size_t j = 1; j < trail.fade.size(); ++j) EXPECT_GT(trail.fade[j], trail.fade[j - 1]);
    if (k == 120) {  // t = 4 s: the last 2 s are 61 samples, the oldest fully faded
      EXPECT_EQ(trail.points.size(), 61U);
      EXPECT_NEAR(trail.fade.front(), 0.0, 1e-12);
      EXPECT_GT(trail.points.front().y() - trail.points.back().y(), 2 * 9.81);  // the world's: it fell
    }
  }
}

// Nearest distance from the box to the segment a-b (pixels), sampled finely.
double distance(const Rect& r, const Vec2& a, const Vec2& b) {
  double nearest = 1e300;
  for (int i = 0; i <= 200; ++i) {
    const Vec2 p = a + (b - a) * (i / 200.0);
    const double dx = std::max({r.x - p.x(), 0.0, p.x() - r.x - r.width});
    const double dy = std::max({r.y - p.y(), 0.0, p.y() - r.y - r.height});
    nearest = std::min(nearest, std::hypot(dx, dy));
  }
  return nearest;
}

// The free-body view of the homework, ten seconds every quarter second (the pair turns
// through every angle): "F on 1" and "−F on 2" each plainly nearer its own arrow than
// the other's (or led to its head by a line), and no block's edge enters the legend.
TEST(TwoBlocksScene, FreeBodyViewNamesSitAtTheirOwnArrowsAndBodiesClearTheLegend) {
  std::vector<double> times;
  for (int k = 0; k <= 40; ++k) times.push_back(0.25 * k);
  SimulationOptions options;
  options.duration = 10;
  ClipResult result;
  const MechanismMotion motion =
      sample_mechanism_motion(two_blocks().system, two_blocks().initial, options, times, 1, result);
  const Theme theme = load_theme("light", {}, "theme");
  for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
    SCOPED_TRACE(width);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    DrawStyle style;
    style.theme = &theme;
    style.u = DrawStyle::unit_for(width, height);
    MechanismScene scene(mechanism_geometry(two_blocks().system), motion, {}, 2.0, {}, ElementSet::defaults(), true);
    const Camera first = mechanism_camera(scene, settings, CameraMode::follow);
    scene.set_shortest_arrow(shortest_labelled_arrow_px(style) / first.scale(),
                             stretched_arrow_px(style) / first.scale());
    const cairo::SurfacePtr surface = cairo::image_surface(width, height);
    const cairo::ContextPtr cr = cairo::context(surface.get());
    MechanismDrawList list;
    for (std::size_t k = 0; k < times.size(); ++k) {
      SCOPED_TRACE("t = " + std::to_string(times[k]));
      scene.frame(k, list);
      const Camera camera = first.centred_at(scene.centroid(k));
      const ForceLayout layout = layout_forces(cr.get(), style, camera, list, width, height, {});
      ASSERT_FALSE(layout.legend.empty());
      for (const MechanismDrawList::Outline& outline : list.outlines)
        for (std::size_t i = 0; i < outline.points.size(); ++i) {
          const Vec2 a = camera.to_pixels(outline.points[i]);
          const Vec2 b = camera.to_pixels(outline.points[(i + 1) % outline.points.size()]);
          EXPECT_GT(distance(layout.legend, a, b), 0.0) << "block " << outline.body + 1;
        }
      std::vector<std::pair<std::string, std::pair<Vec2, Vec2>>> arrows;
      for (std::size_t i = 0; i < list.arrows.size(); ++i)
        if (list.arrows[i].kind == MechanismDrawList::Arrow::Kind::joint)
          arrows.push_back({list.arrows[i].label, {layout.arrows[i].a, layout.arrows[i].b}});
      ASSERT_EQ(arrows.size(), 2U);
      int named = 0;
      for (const PlacedLabel& label : layout.labels)
        for (std::size_t own = 0; own < 2; ++own) {
          if (label.text.rfind(arrows[own].first, 0) != 0) continue;
          ++named;
          const auto& [a, b] = arrows[own].second;
          const auto& [c, d] = arrows[1 - own].second;
          if (label.leader) {  // moved off: its line leads to its own arrow's head
            EXPECT_LT((label.head - b).norm(), 1.0) << label.text;
            continue;
          }
          const double mine = distance(label.box, a, b), other = distance(label.box, c, d);
          // Plainly nearer its own: by at least a few pixels, not a tie.
          EXPECT_LT(mine + 3, other) << label.text << ": " << mine << " px from its arrow, " << other
                                     << " px from the other";
        }
      EXPECT_EQ(named, 2);
    }
  }
}

// Draws frame `index` (and saves it for a person to look at); returns the pin's footprint
// in pixels: those that differ between the frame with the blocks and the pin alone and
// with the blocks alone.
long pin_pixels(const std::string& name, MechanismClip clip, std::size_t index) {
  Frame frame(clip.settings.width, clip.settings.height), without(clip.settings.width, clip.settings.height);
  ClipResult result;
  if (const auto folder = test::picture_folder(); !folder.empty()) {
    MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
    frames.draw(index, frame);
    test::write_png_file(frame, folder / (name + ".png"));
  }
  clip.settings.elements = ElementSet::none();
  clip.settings.elements.show(Element::blocks);
  MechanismClipFrames blocks(two_blocks().system, two_blocks().initial, clip, result);
  blocks.draw(index, without);
  clip.settings.elements.show(Element::pin);
  MechanismClipFrames pinned(two_blocks().system, two_blocks().initial, clip, result);
  pinned.draw(index, frame);
  long count = 0;
  for (std::size_t i = 0; i < frame.pixels.size(); i += 4)
    count += std::equal(frame.pixels.begin() + static_cast<std::ptrdiff_t>(i),
                        frame.pixels.begin() + static_cast<std::ptrdiff_t>(i + 4),
                        without.pixels.begin() + static_cast<std::ptrdiff_t>(i))
                 ? 0
                 : 1;
  return count;
}

// Lines, marks and text scale with the frame, so a clip reads the same at 480p and 4K.
TEST(TwoBlocksClip, MarksScaleWithTheFrameInEveryTheme) {
  for (const char* theme : {"light", "dark", "print"}) {
    MechanismClip clip = homework_clip(1280, 720, 61 / 30.0, theme);
    clip.settings.elements.show(Element::velocity);
    EXPECT_GT(pin_pixels(std::string("two_blocks_") + theme, clip, 60), 20) << theme;
  }
  const long small = pin_pixels("two_blocks_480p", homework_clip(854, 480, 61 / 30.0), 60);
  const long large = pin_pixels("two_blocks_4k", homework_clip(3840, 2160, 61 / 30.0), 60);
  // The pin's disc grows with the frame's height squared (4.5^2), its antialiased rim aside.
  EXPECT_NEAR(static_cast<double>(large) / static_cast<double>(small), 4.5 * 4.5, 0.25 * 4.5 * 4.5)
      << small << " px at 480p, " << large << " px at 4K";
}

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

/// The spacing of the grid a following camera draws (mechanism_painter: 5 lines).
double follow_spacing(const Camera& camera, int width, int height) {
  return grid_spacing_for(camera, width, height, 5).metres();
}

// The camera follows the falling centre of mass; the grid lines are where the world has
// them (at the first frame, which has no earlier one to streak from: crisp lines; later
// frames' lines, streaking, in GridLinesStreakOverTheFramesShutterInterval).
TEST(TwoBlocksFollow, GridLinesStayAtWorldHeightsWhileTheBlocksFall) {
  MechanismClip clip = homework_clip(640, 360, 121 / 30.0);
  clip.theme.grid = {1, 0, 1, 1};  // unique
  ClipResult result;
  MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
  Frame frame(640, 360);
  frames.draw(0, frame);
  const Camera camera = frames.camera(0);
  const double spacing = follow_spacing(camera, 640, 360);
  const std::vector<int> rows = grid_rows(frame, clip.theme.grid);
  ASSERT_GE(rows.size(), 2u);  // a few lines in view
  for (const int row : rows) {
    const double y = camera.to_world({0.0, row + 0.5}).y();
    const double off = y - spacing * std::round(y / spacing);
    EXPECT_LT(std::fabs(off) * camera.scale(), 1.0) << "row " << row << " is at y = " << y << " m";
  }
  // The camera falls with the centre of mass (about g t^2 / 2: 19 m by 2 s, 77 m by 4 s)
  // at one zoom.
  EXPECT_GT(camera.centre().y() - frames.camera(60).centre().y(), 15.0);
  EXPECT_GT(frames.camera(60).centre().y() - frames.camera(120).centre().y(), 45.0);
  EXPECT_EQ(frames.camera(120).scale(), camera.scale());
}

// The grey of a pixel on white: how much of the (black) grid covers it, 0 .. 1.
double ink(const test::Rgb8& pixel) { return 1.0 - pixel.r / 255.0; }

// At 30 fps a line moves g t / 30 per frame: more than half a spacing above ~3 m/s. Each
// horizontal line is drawn as a band from where it was a frame earlier to where it is,
// most opaque now, so what the eye matches from frame to frame moves the right way.
TEST(TwoBlocksFollow, GridLinesStreakOverTheFramesShutterInterval) {
  MechanismClip clip = homework_clip(640, 360, 121 / 30.0);
  clip.theme.grid = {0, 0, 0, 1};  // black on white: the grey level is the coverage
  clip.trails.clear();
  for (const Element hidden : {Element::blocks, Element::com, Element::pin, Element::trail, Element::gravity,
                               Element::pin_force, Element::labels, Element::legend, Element::title, Element::hud})
    clip.settings.elements.hide(hidden);
  ClipResult result;
  MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
  Frame frame(640, 360);
  const int column = 250;  // clear of the grid's names (left) and the inset (right)
  for (const std::size_t k : {std::size_t{3}, std::size_t{12}, std::size_t{30}, std::size_t{60}, std::size_t{120}}) {
    SCOPED_TRACE(k);
    frames.draw(k, frame);
    const Camera now = frames.camera(k), then = frames.camera(k - 1);
    const double spacing = follow_spacing(now, 640, 360);
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

TEST(TwoBlocksFollow, TrailOpacityFallsWithTheSquareOfItsFade) {
  const Theme theme = load_theme("light", {}, "--theme");
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 1.0), theme.trail.a);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 0.5), 0.25 * theme.trail.a);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, -0.2), 0.0);
  EXPECT_DOUBLE_EQ(trail_alpha(theme, 1.5), theme.trail.a);
}

TEST(TwoBlocksPanel, DegreesOnTheAxisDataAndInItsWords) {
  SimulationOptions options;
  options.duration = 0.2;
  ClipResult result;
  PanelData data;
  (void)sample_mechanism_motion(two_blocks().system, two_blocks().initial, options, {0.0, 0.1, 0.2}, 1, result, {},
                                {"1.theta", "1.theta_dot", "1.y"}, &data);
  ASSERT_EQ(data.curves.size(), 3U);
  ASSERT_EQ(data.curves[0].values[0], 0.1);  // rad, the file's initial angle
  const double rate = data.curves[1].values.back();
  const double height = data.curves[2].values.back();

  RenderSettings settings;
  settings.width = 854;
  settings.height = 480;
  settings.angles = AngleUnit::deg;
  const FrameLayout layout(settings, load_theme("light", {}, "theme"), data);
  const PanelData& shown = layout.panel();
  EXPECT_NEAR(shown.curves[0].values[0], 5.72958, 1e-5);  // 0.1 rad
  EXPECT_EQ(shown.curves[0].unit, "deg");
  EXPECT_NEAR(shown.curves[1].values.back(), rate * 180 / std::numbers::pi, 1e-12);
  EXPECT_EQ(shown.curves[1].unit, "deg/s");
  EXPECT_EQ(shown.curves[2].values.back(), height);  // metres stay metres
  EXPECT_EQ(shown.curves[2].unit, "m");

  // What the plot draws: the first point of θ1 at 5.7296 and the unit in the legend.
  const plot::Plot plot = panel_plot(shown, 0, false);
  ASSERT_FALSE(plot.series.empty());
  ASSERT_FALSE(plot.series[0].points.empty());
  EXPECT_NEAR(plot.series[0].points[0].y, 5.72958, 1e-5);
  EXPECT_NE(plot.series[0].name.find("(deg)"), std::string::npos) << plot.series[0].name;

  // In radians (the default) nothing changes.
  settings.angles = AngleUnit::rad;
  const FrameLayout plain(settings, load_theme("light", {}, "theme"), data);
  EXPECT_EQ(plain.panel().curves[0].values[0], 0.1);
  EXPECT_EQ(plain.panel().curves[0].unit, "rad");
}

// --show equations: the bodies stay in the scene above the band, at every time of a
// ten-second clip, with and without a panel.
TEST(TwoBlocksClip, BodiesStayClearOfTheEquationsBand) {
  const EquationsText case3{"Case 3: four equations in generalized coordinates, no pin force",
                            {
                                "    (1.3)  m D sin θ₁ ẍ₁ - m D cos θ₁ ÿ₁ + I θ̈₁ = m g D cos θ₁",
                                "    (2.3)  m D sin θ₂ ẍ₁ - m D cos θ₂ ÿ₁ + I θ̈₂ = m g D cos θ₂",
                                "    (3.3)  2 ẍ₁ - D sin θ₁ θ̈₁ - D sin θ₂ θ̈₂ = D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)",
                                "    (4.3)  2 ÿ₁ + D cos θ₁ θ̈₁ + D cos θ₂ θ̈₂ = D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g",
                            }};
  for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
    for (const bool panel : {false, true}) {
      SCOPED_TRACE(std::to_string(width) + (panel ? " with a panel" : ""));
      MechanismClip clip = homework_clip(width, height, 10.0);
      clip.settings.fps = 4;
      clip.settings.elements.show(Element::equations);
      clip.settings.equations = case3;
      clip.settings.captions = {{0.0, "The pin force is small next to the weight"}};
      if (panel) clip.settings.panel = {"1.theta"};
      const FrameLayout layout(clip.settings, clip.theme, PanelData{});
      const Rect band = layout.equations_rect();
      const Rect scene = layout.scene_rect();
      ASSERT_GT(band.height, 0);
      ClipResult result;
      MechanismClipFrames frames(two_blocks().system, two_blocks().initial, clip, result);
      Frame frame(width, height);
      for (std::size_t k = 0; k < static_cast<std::size_t>(frames.count()); ++k) {
        frames.draw(k, frame);
        const Camera camera = frames.camera(k);
        ASSERT_EQ(frames.list().outlines.size(), 2U);  // both blocks drawn
        for (const auto& outline : frames.list().outlines)
          for (const Vec2& corner : outline.points) {
            const Vec2 at = camera.to_pixels(corner) + Vec2(scene.x, scene.y);
            EXPECT_LT(at.y(), band.y) << "frame " << k << ": a corner reaches into the band";
            EXPECT_GT(at.y(), scene.y);
            EXPECT_GT(at.x(), scene.x);
            EXPECT_LT(at.x(), scene.x + scene.width);
          }
      }
    }
  }
}

}  // namespace
}  // namespace linkage
