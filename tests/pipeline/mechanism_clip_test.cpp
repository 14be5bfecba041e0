// Any mechanism's clip: its geometry, its camera, force arrows with their labels and
// legend, loads, trails, stills of every shipped mechanism and a short MP4, decoded back.
#include "pipeline/mechanism_clip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include "columns/mechanism_columns.hpp"
#include "core/error.hpp"
#include "encode/encode_test_support.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip_support.hpp"
#include "render/cairo_util.hpp"
#include "render/mechanism_forces.hpp"
#include "render/mechanism_painter.hpp"
#include "render/scene_painter.hpp"
#include "render/text.hpp"
#include "render/xml_check.hpp"
#include "scene/arrow_scale.hpp"
#include "scene/mechanism_scene.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using test::test_mechanism;

MechanismClip small_still(const std::string& out) {
  MechanismClip clip;
  clip.settings.width = 160;
  clip.settings.height = 90;
  clip.settings.fps = 30;
  clip.settings.at = 0.5;
  clip.simulation.duration = 0.5;
  clip.theme = load_theme("light", {}, "theme");
  clip.out = out;
  return clip;
}

MechanismMotion sampled(const sym::System& system, double duration, double step) {
  MechanismSimulation simulation(system, sym::checked_initial_state(system).state, [&] {
    SimulationOptions o;
    o.duration = duration;
    return o;
  }());
  MechanismMotion motion;
  const auto count = static_cast<long>(std::lround(duration / step));
  for (long i = 0; i <= count; ++i) {
    const double t = std::min(duration, static_cast<double>(i) * step);
    motion.times.push_back(t);
    motion.samples.emplace_back();
    simulation.sample(t, simulation.state_at(t), motion.samples.back());
  }
  return motion;
}

TEST(MechanismClip, EveryShippedMechanismGivesAStillThatIsNotBlank) {
  test::TempDir dir;
  std::size_t written = 0;
  for (const std::string& name : shipped_mechanism_names()) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const auto out = dir / (name + ".png");
    const ClipResult result =
        produce_mechanism_clip(system, sym::checked_initial_state(system).state, small_still(out.string()));
    EXPECT_EQ(result.stats.png_files_written, 1);
    ASSERT_TRUE(std::filesystem::exists(out));
    const test::DecodedPng png = test::decode_png(out);
    ASSERT_EQ(png.width, 160U);
    ASSERT_EQ(png.height, 90U);
    // Distinct colours, and the bodies' fills in the middle of the frame, not at the edge.
    std::set<std::uint32_t> colours, inner;
    for (std::uint32_t y = 0; y < png.height; ++y)
      for (std::uint32_t x = 0; x < png.width; ++x) {
        const std::uint8_t* p = &png.rgba[4 * (y * png.width + x)];
        const auto colour = static_cast<std::uint32_t>(p[0] << 16 | p[1] << 8 | p[2]);
        colours.insert(colour);
        if (x > png.width / 8 && x < 7 * png.width / 8 && y > png.height / 8 && y < 7 * png.height / 8)
          inner.insert(colour);
      }
    EXPECT_GT(colours.size(), 20U);
    EXPECT_GT(inner.size(), 10U);
    // No temporary left beside it.
    EXPECT_EQ(test::entries(dir.path()).size(), ++written);
  }
}

TEST(MechanismClip, FourBarClipDecodesWithEveryFrame) {
  test::TempDir dir;
  const sym::System system(load_mechanism("four-bar"));
  MechanismClip clip;
  clip.settings.width = 320;
  clip.settings.height = 180;
  clip.settings.fps = 30;
  clip.settings.duration = 0.5;
  clip.simulation.duration = 0.5;
  clip.theme = load_theme("light", {}, "theme");
  clip.trails = {"3.B"};
  clip.out = dir / "four-bar.mp4";
  long drawn = 0;
  const ClipResult result = produce_mechanism_clip(system, sym::checked_initial_state(system).state, clip,
                                                   [&](ClipStage stage, long done, long) {
                                                     if (stage == ClipStage::draw) drawn = done;
                                                   });
  EXPECT_EQ(drawn, 15);
  EXPECT_TRUE(result.stats.encoder_opened);
  const test::DecodedVideo video = test::decode_video(*clip.out);
  EXPECT_EQ(video.times.size(), 15U);
  EXPECT_NEAR(video.stream_duration, 0.5, 1e-9);
  EXPECT_EQ(video.width, 320);
  EXPECT_EQ(video.height, 180);
  EXPECT_EQ(test::entries(dir.path()), std::vector<std::string>{"four-bar.mp4"});
}

// A clip keeps a fixed camera's backdrop and the title's pixels from frame to frame: each
// frame drawn after the others is byte for byte the frame drawn first by a fresh clip.
TEST(MechanismClip, FramesDrawnAfterOthersAreTheFramesDrawnAlone) {
  for (const std::string name : {"four-bar", "two-blocks"}) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const GiNaC::exmap initial = sym::checked_initial_state(system).state;
    const MechanismClip clip = test::small_clip(system);
    ClipResult result;
    MechanismClipFrames frames(system, initial, clip, result);
    ASSERT_EQ(frames.count(), 30);
    Frame after(640, 360);
    for (std::size_t k = 0; k < 30; ++k) {
      frames.draw(k, after);
      if (k % 7 != 3) continue;
      ClipResult unused;
      MechanismClipFrames fresh(system, initial, clip, unused);
      Frame alone(640, 360);
      fresh.draw(k, alone);
      EXPECT_EQ(after.pixels, alone.pixels) << "frame " << k;
    }
  }
}

// GIF and WebM by extension: every frame decodes, and each matches the PNG frame drawn
// for it (the --frames sequence of the same run) on average over the picture.
TEST(MechanismClip, GifAndWebmClipsMatchTheirDrawnFrames) {
  const sym::System system(load_mechanism("four-bar"));
  for (const std::string name : {"four-bar.gif", "four-bar.webm"}) {
    test::TempDir dir;
    MechanismClip clip;
    clip.settings.width = 320;
    clip.settings.height = 180;
    clip.settings.fps = 30;
    clip.settings.duration = 0.5;
    clip.simulation.duration = 0.5;
    clip.theme = load_theme("light", {}, "theme");
    clip.trails = {"3.B"};
    clip.out = dir / name;
    clip.frames = dir / "frames";
    const ClipResult result = produce_mechanism_clip(system, sym::checked_initial_state(system).state, clip);
    EXPECT_EQ(result.encoder, name.ends_with(".gif") ? "gif" : "libvpx-vp9");
    const test::DecodedVideo video = test::decode_video(*clip.out);
    EXPECT_EQ(video.codec, name.ends_with(".gif") ? "gif" : "vp9");
    EXPECT_EQ(video.width, 320);
    EXPECT_EQ(video.height, 180);
    const std::vector<std::string> pngs = test::entries(*clip.frames);  // frame_00000.png ... in order
    ASSERT_EQ(pngs.size(), 15U);
    ASSERT_EQ(video.rgb.size(), 15U) << name;
    // Mean |difference| per channel between decoded frame k and drawn frame j.
    auto error = [&](std::size_t k, std::size_t j) {
      const test::DecodedPng png = test::decode_png(*clip.frames / pngs[j]);
      double total = 0;
      for (std::size_t p = 0; p < 320U * 180U; ++p)
        for (std::size_t c = 0; c < 3; ++c) total += std::abs(int{video.rgb[k][3 * p + c]} - int{png.rgba[4 * p + c]});
      return total / (320.0 * 180.0 * 3.0);
    };
    for (std::size_t k = 0; k < video.rgb.size(); ++k) {
      // Mostly flat theme colours: within a level or two on average (WebM's limited-range
      // YUV moves white by a level or two everywhere; the HUD's panel of text, a fifth of
      // this small frame, adds about half a level: 3.14 measured), and closer to its own
      // drawing than to the next one (the links move between frames).
      const double own = error(k, k);
      EXPECT_LT(own, name.ends_with(".gif") ? 2.0 : 3.5) << name << " frame " << k;
      if (k + 1 < video.rgb.size()) {
        EXPECT_LT(own, error(k, k + 1)) << name << " frame " << k;
      }
    }
  }
}

TEST(MechanismClip, RejectsUnknownTrailPoints) {
  test::TempDir dir;
  const sym::System system(load_mechanism("four-bar"));
  MechanismClip clip = small_still((dir / "x.png").string());
  clip.trails = {"3.Q"};
  test::expect_error([&] { clip.validate(system); }, ExitCode::bad_input, "valid: A, B");
  clip.trails = {"9.A"};
  test::expect_error([&] { clip.validate(system); }, ExitCode::bad_input, "valid: ground, 2, 3, 4");
  EXPECT_TRUE(test::entries(dir.path()).empty());
}

TEST(MechanismClip, PanelPlotsTheContractsColumnsInWords) {
  test::TempDir dir;
  const sym::System system(load_mechanism("four-bar"));
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  const auto force = std::find_if(all.begin(), all.end(), [](const MechanismColumn& c) {
    return c.quantity == MechanismQuantity::force && c.name.ends_with(".force_x");
  });
  ASSERT_NE(force, all.end());
  SimulationOptions options;
  options.duration = 0.5;
  ClipResult result;
  PanelData panel;
  const MechanismMotion motion =
      sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, {0.0, 0.25, 0.5}, 1, result,
                              {}, {"2.theta", force->name}, &panel);
  ASSERT_EQ(panel.curves.size(), 2u);
  EXPECT_EQ(panel.curves[0].label, "angle θ of body 2");
  EXPECT_EQ(panel.curves[0].unit, "rad");
  EXPECT_EQ(panel.curves[1].unit, "N");
  EXPECT_NE(panel.curves[1].label.find("force of joint"), std::string::npos);
  const auto theta = std::find_if(all.begin(), all.end(), [](const MechanismColumn& c) { return c.name == "2.theta"; });
  ASSERT_NE(theta, all.end());
  // Sampled between the frames too; each frame's own sample is the panel's at its time.
  ASSERT_GE(panel.t.size(), 4000u);
  const std::vector<double> frames{0.0, 0.25, 0.5};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = panel_index(panel, frames[k]);
    EXPECT_EQ(panel.t[i], frames[k]);
    EXPECT_EQ(panel.curves[0].values[i], motion.samples[k].pose[theta->index]);
    EXPECT_EQ(panel.curves[1].values[i], motion.samples[k].force[force->index]);
  }
  EXPECT_TRUE(std::is_sorted(panel.t.begin(), panel.t.end()));
  // A still with the panel; an unknown column is refused naming the valid ones.
  MechanismClip clip = small_still((dir / "panel.png").string());
  clip.settings.width = 480;
  clip.settings.height = 270;
  clip.settings.panel = {"2.theta"};
  clip.settings.captions = {{0.0, "The crank turns"}};
  (void)produce_mechanism_clip(system, sym::checked_initial_state(system).state, clip);
  EXPECT_EQ(test::entries(dir.path()), std::vector<std::string>{"panel.png"});
  clip.settings.panel = {"2.thet"};
  test::expect_error([&] { clip.validate(system); }, ExitCode::bad_input, "did you mean '2.theta'");
}

// D6: the panel's curve is the table's, not the frames'. Over the four-bar's default 10 s
// at 30 frames per second, O2's force peaks at 5.63 and -14.60 N (simulate --every
// 0.0005); sampled at the frames only the panel read 4.60 and -13.19 N. Its peaks are
// the table's to within 1 %; so are those of a point's column (the coupler point's ay).
TEST(MechanismClip, PanelPeaksAreTheTablesPeaks) {
  const sym::System system(load_mechanism("four-bar"));
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  SimulationOptions options;
  options.duration = 10;
  std::vector<double> frames;
  for (int k = 0; k <= 300; ++k) frames.push_back(k / 30.0);
  ClipResult result;
  PanelData panel;
  (void)sample_mechanism_motion(system, initial, options, frames, 1, result, {}, {"O2.force_x", "3.P.ay"}, &panel);
  ASSERT_EQ(panel.curves.size(), 2u);
  // The table at a fine step: simulate --every 0.0005.
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  const std::vector<MechanismColumn> columns{find_mechanism_column(all, "O2.force_x", "test"),
                                             find_mechanism_column(all, "3.P.ay", "test")};
  MechanismSimulation table(system, initial, options);
  eval::MechanismSample sample;
  std::vector<double> high(2, -1e300), low(2, 1e300);
  for (int k = 0; k <= 20000; ++k) {
    const double t = k * 0.0005;
    const Eigen::VectorXd y = table.state_at(t);
    table.sample(t, y, sample, true);
    for (std::size_t c = 0; c < 2; ++c) {
      high[c] = std::max(high[c], column_value(columns[c], t, y, sample, table.origin()));
      low[c] = std::min(low[c], column_value(columns[c], t, y, sample, table.origin()));
    }
  }
  EXPECT_NEAR(high[0], 5.63, 0.01);
  EXPECT_NEAR(low[0], -14.60, 0.01);
  for (std::size_t c = 0; c < 2; ++c) {
    const auto [lo, hi] = std::minmax_element(panel.curves[c].values.begin(), panel.curves[c].values.end());
    EXPECT_NEAR(*hi, high[c], 0.01 * std::fabs(high[c])) << panel.curves[c].label;
    EXPECT_NEAR(*lo, low[c], 0.01 * std::fabs(low[c])) << panel.curves[c].label;
  }
}

TEST(MechanismColumns, UnitsInPlotMarkup) {
  MechanismColumn c;
  c.unit = "kg m^2/s";
  EXPECT_EQ(column_unit_markup(c), "kg m^{2}/s");
  c.unit = "rad/s^2";
  EXPECT_EQ(column_unit_markup(c), "rad/s^{2}");
  c.unit = "N m";
  EXPECT_EQ(column_unit_markup(c), "N m");
}

TEST(MechanismScene, RodOutlineSpansItsLength) {
  const sym::System system(load_mechanism("four-bar"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  ASSERT_EQ(geometry.bodies[1].shape, Shape::rod);
  EXPECT_DOUBLE_EQ(geometry.bodies[1].length, 0.3);
  const std::vector<double> pose = {0, 0, 0, 0.1, -0.2, 0.7, 0, 0, 0};
  const std::vector<Vec2> outline = body_outline(geometry.bodies[1], pose, 1);
  const Vec2 axis(std::cos(0.7), std::sin(0.7));
  double lo = 1e9, hi = -1e9, wide = 0;
  for (const Vec2& p : outline) {
    const Vec2 r = p - Vec2(0.1, -0.2);
    lo = std::min(lo, r.dot(axis));
    hi = std::max(hi, r.dot(axis));
    wide = std::max(wide, std::fabs(r.dot(Vec2(-axis.y(), axis.x()))));
  }
  EXPECT_NEAR(hi - lo, 0.3, 1e-12);
  EXPECT_NEAR(2 * wide, 0.3 / 12, 1e-12);
}

TEST(MechanismScene, SpringRunsBetweenItsAttachmentPoints) {
  const sym::System system(load_mechanism("spring-pendulum"));
  const MechanismMotion motion = sampled(system, 0.3, 0.1);
  const MechanismScene scene(mechanism_geometry(system), motion, {});
  EXPECT_TRUE(scene.geometry().grounded());
  MechanismDrawList list;
  for (std::size_t k = 0; k < motion.samples.size(); ++k) {
    scene.frame(k, list);
    const auto& pose = motion.samples[k].pose;
    int springs = 0;
    for (const MechanismDrawList::Line& line : list.lines) {
      if (line.kind != MechanismDrawList::Line::Kind::spring) continue;
      ++springs;
      EXPECT_NEAR((line.points.front() - Vec2(0, 0)).norm(), 0, 1e-12);             // ground.O
      EXPECT_NEAR((line.points.back() - Vec2(pose[0], pose[1])).norm(), 0, 1e-12);  // 1.C, the centre
    }
    EXPECT_EQ(springs, 1);
  }
}

TEST(MechanismScene, FixedViewHoldsEveryCornerOverTheMotion) {
  for (const char* name : {"four-bar", "slider-crank", "triple-pendulum"}) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = sampled(system, 1.0, 0.05);
    const MechanismScene scene(mechanism_geometry(system), motion, {});
    ASSERT_TRUE(scene.geometry().grounded());
    const Camera camera(view_of(scene.view_bounds(), 0.1), 320, 180);
    for (std::size_t k = 0; k < motion.samples.size(); ++k)
      for (std::size_t i = 0; i < scene.geometry().bodies.size(); ++i)
        for (const Vec2& p : body_outline(scene.geometry().bodies[i], motion.samples[k].pose, i)) {
          const Vec2 px = camera.to_pixels(p);
          EXPECT_TRUE(px.x() >= 0 && px.x() <= 320 && px.y() >= 0 && px.y() <= 180) << p.transpose();
        }
    // No arrow is drawn longer than the cap, a quarter of the mechanism's extent.
    double longest = 0;
    MechanismDrawList list;
    for (std::size_t k = 0; k < motion.samples.size(); ++k) {
      scene.frame(k, list);
      for (const MechanismDrawList::Arrow& arrow : list.arrows) longest = std::max(longest, arrow.vector.norm());
    }
    EXPECT_NEAR(scene.arrow_cap(), 0.25 * scene.extent(), 1e-12 * scene.extent());
    EXPECT_LE(longest, scene.arrow_cap() * (1 + 1e-12));
    EXPECT_GT(longest, 0.1 * scene.extent());
  }
}

TEST(MechanismScene, TwoBlocksFloatAndLabelForcesByTheirAliasAndBody) {
  const sym::System system(load_mechanism("two-blocks"));
  const MechanismMotion motion = sampled(system, 0.2, 0.1);
  const MechanismGeometry geometry = mechanism_geometry(system);
  ElementSet joints_only = ElementSet::defaults();
  joints_only.hide(Element::gravity);  // the joint's pair alone
  const MechanismScene scene(geometry, motion, {geometry.resolve("1.P", "--trail")}, 2.0, {}, joints_only);
  EXPECT_FALSE(scene.geometry().grounded());
  MechanismDrawList list;
  scene.frame(2, list);
  ASSERT_EQ(list.arrows.size(), 2U);
  // Named as the file's [aliases] name the force (P.force_x = F_x): the homework's labels.
  EXPECT_EQ(list.arrows[0].label, "F on 1");
  EXPECT_EQ(list.arrows[1].label, "\u2212F on 2");
  EXPECT_NEAR((list.arrows[0].vector + list.arrows[1].vector).norm(), 0, 1e-12);
  ASSERT_FALSE(list.lines.empty());
  EXPECT_EQ(list.lines.back().points.size(), 3U);  // the trail through every sample so far
}

// The pipeline's own sampling: frames at `fps` over `duration`, trails 4 steps a frame.
MechanismMotion clip_motion(const sym::System& system, double duration, double fps, int trail_steps = 1) {
  std::vector<double> times;
  for (long k = 0; k <= std::lround(duration * fps); ++k) times.push_back(static_cast<double>(k) / fps);
  SimulationOptions options;
  options.duration = duration;
  ClipResult result;
  return sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, times, trail_steps, result);
}

// The clip's fixed camera: the view of every sample and arrow, a band on top for the title.
Camera clip_camera(const MechanismScene& scene, int width, int height) {
  View view = view_of(scene.view_bounds(), 0.1);
  view.ymax += 0.1 * (view.ymax - view.ymin);
  return {view, width, height};
}

// The pipeline's camera at sample k: fixed for a grounded mechanism, else following.
Camera frame_camera(const MechanismScene& scene, std::size_t k, int width, int height) {
  if (scene.geometry().grounded()) return clip_camera(scene, width, height);
  const Camera camera(view_around(scene.centroid(0), 1.1 * scene.view_reach()), width, height);
  return camera.centred_at(scene.centroid(k));
}

// One frame of a 4 s clip as the pipeline lays it out (its camera, its arrow threshold).
struct LaidOutFrame {
  const std::string& name;
  int width, height;
  std::size_t k;
  const DrawStyle& style;
  const Camera& camera;
  const MechanismDrawList& list;
  const ForceLayout& layout;
};

// The drawing style of a frame `width` x `height` in `theme`.
DrawStyle style_at(const Theme& theme, int width, int height) {
  DrawStyle style;
  style.theme = &theme;
  style.u = DrawStyle::unit_for(width, height);
  return style;
}

// Every `stride`th frame of each mechanism in `names`, at 1280x720 and at --quality
// low's 854x480, laid out under a title box.
void for_each_laid_out_frame(const std::vector<std::string>& names, std::size_t stride,
                             const std::function<void(const LaidOutFrame&)>& check) {
  const Theme theme = load_theme("light", {}, "theme");
  for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{854, 480}}) {
    const DrawStyle style = style_at(theme, width, height);
    const cairo::SurfacePtr surface = cairo::image_surface(width, height);
    const cairo::ContextPtr cr = cairo::context(surface.get());
    const Rect title{0, 0, 0.6 * width, 0.07 * height};
    for (const std::string& name : names) {
      const sym::System system(load_mechanism(name));
      const MechanismMotion motion = clip_motion(system, 4.0, 30);
      MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, {});
      const double scale = frame_camera(scene, 0, width, height).scale();
      scene.set_shortest_arrow(shortest_labelled_arrow_px(style) / scale, stretched_arrow_px(style) / scale);
      MechanismDrawList list;
      for (std::size_t k = 0; k < motion.samples.size(); k += stride) {
        SCOPED_TRACE(name + " at " + std::to_string(width) + " frame " + std::to_string(k));
        scene.frame(k, list);
        const Camera camera = frame_camera(scene, k, width, height);
        const ForceLayout layout = layout_forces(cr.get(), style, camera, list, width, height, {title});
        EXPECT_FALSE(overlaps(layout.legend, title));
        check({name, width, height, k, style, camera, list, layout});
      }
    }
  }
}

// --show acceleration in free fall: a ≈ g, so each block's acceleration arrow leaves its
// centre of mass along its weight's. Laid out, the weight stays at G and the acceleration
// sits beside it, the two heads apart (a head's width and a shaft's), each labelled.
TEST(MechanismForces, AnAccelerationAlongTheWeightIsDrawnBesideIt) {
  const Theme theme = load_theme("light", {}, "theme");
  const sym::System system(load_mechanism("two-blocks"));
  std::vector<double> times;
  for (int k = 0; k <= 30; ++k) times.push_back(k / 30.0);
  SimulationOptions options;
  options.duration = 1;
  ClipResult result;
  const MechanismMotion motion = sample_mechanism_motion(system, sym::checked_initial_state(system).state, options,
                                                         times, 1, result, {}, {}, nullptr, {}, true);
  ElementSet shown = ElementSet::defaults();
  shown.show(Element::acceleration);
  const MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, {}, shown);
  for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{854, 480}}) {
    const DrawStyle style = style_at(theme, width, height);
    const cairo::SurfacePtr surface = cairo::image_surface(width, height);
    const cairo::ContextPtr cr = cairo::context(surface.get());
    MechanismDrawList list;
    scene.frame(30, list);
    const Camera camera = frame_camera(scene, 30, width, height);
    const ForceLayout layout = layout_forces(cr.get(), style, camera, list, width, height, {});
    std::size_t pairs = 0;
    for (std::size_t g = 0; g < list.arrows.size(); ++g) {
      if (list.arrows[g].kind != MechanismDrawList::Arrow::Kind::gravity) continue;
      for (std::size_t a = 0; a < list.arrows.size(); ++a) {
        const MechanismDrawList::Arrow& acceleration = list.arrows[a];
        if (acceleration.kind != MechanismDrawList::Arrow::Kind::acceleration ||
            acceleration.body != list.arrows[g].body || acceleration.label.find('.') != std::string::npos)
          continue;
        SCOPED_TRACE(acceleration.label);
        ++pairs;
        EXPECT_NEAR((acceleration.tail - list.arrows[g].tail).norm(), 0, 1e-12);  // both from G
        EXPECT_NEAR((layout.arrows[g].a - camera.to_pixels(list.arrows[g].tail)).norm(), 0, 1e-9);
        const double apart = 2 * style.arrow_head_half_width() + style.arrow_width() - 1e-9;
        EXPECT_GE((layout.arrows[a].a - layout.arrows[g].a).norm(), apart);
        EXPECT_GE((layout.arrows[a].b - layout.arrows[g].b).norm(), apart);
        for (const std::size_t i : {g, a}) {
          const auto labelled = std::find_if(layout.labels.begin(), layout.labels.end(),
                                             [&](const PlacedLabel& l) { return l.text == list.arrows[i].label; });
          EXPECT_NE(labelled, layout.labels.end()) << list.arrows[i].label;
        }
      }
    }
    EXPECT_EQ(pairs, 2U);
  }
}

// The centres of mass's symbol in the legend (the homework clip's row): at the end of a
// row with room for it, so the legend is no larger (a row of its own left the floating
// pairs' legend no place clear of the bodies in the test below); painted inside the
// legend in the homework's frames, and only when the symbols are drawn.
TEST(MechanismForces, TheCentresOfMassSymbolSitsInTheLegendAtNoCostOfRoom) {
  const Theme theme = load_theme("light", {}, "theme");
  const sym::System system(load_mechanism("two-blocks"));
  const MechanismMotion motion = clip_motion(system, 1.0, 30);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {geometry.resolve("1.P", "trail")}, 2.0, {});
  const DrawStyle style = style_at(theme, 1280, 720);
  MechanismDrawList list;
  scene.frame(30, list);
  EXPECT_TRUE(list.legend.com);
  list.legend.note = "the view follows the centre of mass; the grid stays put";
  const Camera camera = frame_camera(scene, 30, 1280, 720);
  const auto legend_pixels = [&](bool com, Rect& legend) {
    MechanismDrawList drawn = list;
    drawn.legend.com = com;
    const cairo::SurfacePtr surface = cairo::image_surface(1280, 720);
    const cairo::ContextPtr cr = cairo::context(surface.get());
    const ForceLayout layout = layout_forces(cr.get(), style, camera, drawn, 1280, 720, {});
    paint_forces(cr.get(), style, camera, drawn, layout);
    cairo_surface_flush(surface.get());
    legend = layout.legend;
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    std::vector<unsigned char> inside;
    for (auto y = static_cast<int>(legend.y); y < static_cast<int>(legend.y + legend.height); ++y)
      inside.insert(inside.end(), data + y * stride + 4 * static_cast<int>(legend.x),
                    data + y * stride + 4 * static_cast<int>(legend.x + legend.width));
    return inside;
  };
  Rect with, without;
  const std::vector<unsigned char> shown = legend_pixels(true, with), hidden = legend_pixels(false, without);
  ASSERT_FALSE(with.empty());
  EXPECT_EQ(with.x, without.x);
  EXPECT_EQ(with.y, without.y);
  EXPECT_EQ(with.width, without.width);
  EXPECT_EQ(with.height, without.height);
  EXPECT_NE(shown, hidden);
  // Hidden centres of mass: no symbol, no entry.
  ElementSet bare = ElementSet::defaults();
  bare.hide(Element::com);
  const MechanismScene plain(geometry, motion, {}, 2.0, {}, bare);
  plain.frame(30, list);
  EXPECT_FALSE(list.legend.com);
}

// Every `every`th frame of a 4 s clip at 10 frames a second of each mechanism in `names`
// (with its [picture]'s title and trails, as `linkage render` draws it) at every size the
// tool offers: --quality low, medium and high, and a lesson's draft (480x270), as
// produce_mechanism_clip draws it. Frames of a 4k clip are a 1080p one's at twice the unit.
void for_each_drawn_frame(const std::vector<std::string>& names, std::size_t every,
                          const std::function<void(const LaidOutFrame&)>& check) {
  const Theme theme = load_theme("light", {}, "theme");
  for (const auto& [width, height] :
       {std::pair{854, 480}, std::pair{1280, 720}, std::pair{1920, 1080}, std::pair{480, 270}}) {
    for (const std::string& name : names) {
      const sym::System system(load_mechanism(name));
      const Picture& picture = system.mechanism().picture;
      MechanismClip clip;
      clip.settings.width = width;
      clip.settings.height = height;
      clip.settings.fps = 10;
      clip.settings.duration = 4;
      clip.settings.title = picture.title.empty() ? system.mechanism().title : picture.title;
      clip.simulation.duration = 4;
      clip.trails = picture.trails;
      clip.theme = theme;
      ClipResult result;
      MechanismClipFrames frames(system, sym::checked_initial_state(system).state, clip, result);
      const DrawStyle style = style_at(theme, width, height);
      Frame frame(width, height);
      for (std::size_t k = 0; k < static_cast<std::size_t>(frames.count()); k += every) {
        SCOPED_TRACE(name + " at " + std::to_string(width) + "x" + std::to_string(height) + " frame " +
                     std::to_string(k));
        frames.draw(k, frame);
        check({name, width, height, k, style, frames.camera(k), frames.list(), frames.layout()});
      }
    }
  }
}

// Issue 23 D1: the legend over the triple pendulum's disc, a ladder sliding down a wall
// and the four-bar's "A on 2"; D5: a legend stating "1 cm = ..." with no scale bar. Issue
// 26: the coupled pendulums' swing covered every corner (the legend over a rod) and the
// springs' labels sat on their coils. Over a clip's frames at every size.
TEST(MechanismForces, TheLegendAndItsScaleBarCoverNothingDrawnAndLabelsKeepOffTheCoilsAtEverySize) {
  std::vector<std::string> names = shipped_mechanism_names();
  names.push_back(test_mechanism("ladder.toml"));
  std::size_t legends = 0, coils = 0;
  for_each_drawn_frame(names, 8, [&](const LaidOutFrame& f) {
    const ForceLayout& layout = f.layout;
    const auto box = [&](const std::vector<Vec2>& world) {
      Bounds b;
      for (const Vec2& p : world) b.include(f.camera.to_pixels(p));
      return Rect{b.min.x(), b.min.y(), b.max.x() - b.min.x(), b.max.y() - b.min.y()};
    };
    std::vector<Segment> springs;  // every spring's and dashpot's strokes, as drawn
    for (const MechanismDrawList::Line& line : f.list.lines)
      if (line.kind == MechanismDrawList::Line::Kind::spring || line.kind == MechanismDrawList::Line::Kind::dashpot)
        for (std::size_t i = 1; i < line.points.size(); ++i)
          springs.push_back({f.camera.to_pixels(line.points[i - 1]), f.camera.to_pixels(line.points[i])});
    coils += springs.empty() ? 0 : 1;
    for (const PlacedLabel& label : layout.labels) EXPECT_FALSE(touches(label.box, springs)) << label.text;
    for (const Rect& name : layout.body_labels) EXPECT_FALSE(touches(name, springs)) << "a body's name";
    if (layout.legend.empty()) return;
    ++legends;
    // D5: the legend's "1 cm = ..." has a scale bar to measure with: the grid's spacing.
    ASSERT_FALSE(layout.scale_bar.empty());
    const RoundLength spacing = grid_spacing_for(f.camera, f.width, f.height);
    EXPECT_NEAR(layout.scale_px, spacing.metres() * f.camera.scale(), 1e-9);
    EXPECT_EQ(layout.scale_label, describe_length(spacing.mantissa, spacing.exponent));
    EXPECT_FALSE(overlaps(layout.legend, layout.scale_bar));
    for (const Rect& legend : {layout.legend, layout.scale_bar}) {
      EXPECT_GE(legend.x, 0);
      EXPECT_GE(legend.y, 0);
      EXPECT_LE(legend.x + legend.width, f.width);
      EXPECT_LE(legend.y + legend.height, f.height);
      for (const MechanismDrawList::Outline& outline : f.list.outlines)
        EXPECT_FALSE(overlaps(legend, box(outline.points))) << "body " << outline.body;
      for (const Segment& arrow : layout.arrows)
        EXPECT_FALSE(
            overlaps(legend, Rect{std::min(arrow.a.x(), arrow.b.x()), std::min(arrow.a.y(), arrow.b.y()),
                                  std::fabs(arrow.b.x() - arrow.a.x()), std::fabs(arrow.b.y() - arrow.a.y())}));
      for (const MechanismDrawList::Marker& marker : f.list.markers)
        EXPECT_FALSE(overlaps(legend, box({marker.at}))) << "a joint";
      for (const MechanismDrawList::Line& line : f.list.lines) {
        const bool spring =
            line.kind == MechanismDrawList::Line::Kind::spring || line.kind == MechanismDrawList::Line::Kind::dashpot;
        EXPECT_FALSE(spring && overlaps(legend, box(line.points))) << "a spring";
      }
      for (const PlacedLabel& label : layout.labels) EXPECT_FALSE(overlaps(legend, label.box)) << label.text;
    }
  });
  EXPECT_GT(legends, 200U);
  EXPECT_GT(coils, 20U);  // the spring-pendulum's, the four-bar-spring's and the coupled pendulums' frames
}

// Issue 23 D12: the cart-pendulum's "P on rod" labels, there at 720p, gone at --quality
// low. Every frame labels the same arrows at 854x480 as at 1280x720.
TEST(MechanismForces, EveryQualityLabelsTheSameArrows) {
  std::vector<std::string> names = shipped_mechanism_names();
  names.push_back(test_mechanism("cart-pendulum.toml"));
  std::map<std::pair<std::string, std::size_t>, std::vector<std::string>> labelled[2];
  std::size_t p_labels = 0;
  for_each_laid_out_frame(names, 1, [&](const LaidOutFrame& f) {
    std::vector<std::string> texts;
    for (const PlacedLabel& label : f.layout.labels) {
      texts.push_back(label.text);
      p_labels += label.text.starts_with("P on rod") ? 1 : 0;
    }
    std::sort(texts.begin(), texts.end());
    labelled[f.width == 1280 ? 0 : 1][{f.name, f.k}] = texts;
  });
  ASSERT_EQ(labelled[0].size(), labelled[1].size());
  for (const auto& [frame, texts] : labelled[0])
    EXPECT_EQ(texts, labelled[1][frame]) << frame.first << " frame " << frame.second;
  EXPECT_GT(p_labels, 121U);  // "P on rod" in most of the cart-pendulum's 121 frames, at both sizes
}

// Issue 23 D3: joint A's two short arrows at `--trail 3.P --at 3` solid, under the pin
// circle and unlabelled, though the legend promises a dashed arrow with its value. With
// the clip's threshold every arrow drawn carries its label, and one too short for it is
// dashed and reaches past the pin.
TEST(MechanismForces, EveryArrowCarriesItsLabelAndAShortOneIsDashedPastThePin) {
  std::size_t dashed = 0;
  for_each_laid_out_frame(shipped_mechanism_names(), 2, [&](const LaidOutFrame& f) {
    EXPECT_EQ(f.layout.labels.size(), f.list.arrows.size() + f.list.torques.size() + f.list.joint_labels.size());
    for (const MechanismDrawList::Arrow& arrow : f.list.arrows) {
      const double px = arrow.vector.norm() * f.camera.scale();
      if (px == 0) continue;
      EXPECT_GE(px, shortest_labelled_arrow_px(f.style) * (1 - 1e-9)) << arrow.label;
      EXPECT_GT(px, 2 * f.style.pin_radius()) << arrow.label;  // out from under the pin circle
      if (arrow.stretched) {
        ++dashed;
        EXPECT_NE(arrow.label.find(" N"), std::string::npos) << arrow.label;  // its value
      }
    }
  });
  EXPECT_GT(dashed, 0U);
}

// Issue 23 D2: with crank 2 along coupler 3, "O2 on 2" and "A on 3" on one line, end to
// end, read as one arrow. As drawn, no arrow runs along another's line within two shaft
// widths, overlapping or nearer than a head's length end to end (a joint's equal and
// opposite pair from one point excepted).
TEST(MechanismForces, NoTwoArrowsAreDrawnOnOneLine) {
  std::size_t moved = 0;
  for_each_laid_out_frame(shipped_mechanism_names(), 1, [&](const LaidOutFrame& f) {
    const double gap = 1.9 * f.style.arrow_width(), apart = f.style.arrow_head_length();
    const std::vector<Segment>& arrows = f.layout.arrows;
    ASSERT_EQ(arrows.size(), f.list.arrows.size());
    for (std::size_t i = 0; i < arrows.size(); ++i) {
      moved += (arrows[i].a - f.camera.to_pixels(f.list.arrows[i].tail)).norm() > 1 ? 1 : 0;
      for (std::size_t j = 0; j < i; ++j) {
        const Segment &p = arrows[j], &q = arrows[i];
        const Vec2 dp = p.b - p.a, dq = q.b - q.a;
        if (dp.norm() < 1 || dq.norm() < 1 || (p.a - q.a).norm() < 1) continue;
        const Vec2 d = dp.normalized(), n(-d.y(), d.x());
        const bool parallel = std::fabs(d.x() * dq.normalized().y() - d.y() * dq.normalized().x()) < 0.1;
        const bool near = std::fabs((q.a - p.a).dot(n)) < gap && std::fabs((q.b - p.a).dot(n)) < gap;
        const double q0 = (q.a - p.a).dot(d), q1 = (q.b - p.a).dot(d);
        const double shared = std::min(dp.norm(), std::max(q0, q1)) - std::max(0.0, std::min(q0, q1));
        EXPECT_FALSE(parallel && near && shared > -apart) << f.list.arrows[j].label << " / " << f.list.arrows[i].label;
      }
    }
  });
  EXPECT_GT(moved, 0U);  // the four-bar's crank lies along its coupler in some frames
}

// Issue 23 D4: "cut short" and "dashed" listed with no such arrow in the frame.
TEST(MechanismForces, TheLegendListsOnlyTheArrowKindsTheFrameDraws) {
  constexpr int kWidth = 1280, kHeight = 720;
  const Theme theme = load_theme("light", {}, "theme");
  const DrawStyle style = style_at(theme, kWidth, kHeight);
  ArrowScaleRequest apart;
  apart.fixed = {{"joint", 50.0}, {"applied", 0.01}};  // joint forces short, applied ones long
  std::size_t without_cut = 0, without_dashed = 0, with_both = 0;
  for (const std::string& name : shipped_mechanism_names()) {
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = clip_motion(system, 4.0, 30);
    for (const ArrowScaleRequest& request : {ArrowScaleRequest{}, apart}) {
      MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, request);
      const double scale = frame_camera(scene, 0, kWidth, kHeight).scale();
      scene.set_shortest_arrow(least_visible_arrow_px(style) / scale, stretched_arrow_px(style) / scale);
      MechanismDrawList list;
      for (std::size_t k = 0; k < motion.samples.size(); ++k) {
        SCOPED_TRACE(name + " frame " + std::to_string(k));
        scene.frame(k, list);
        const auto any = [&](const auto& test) { return std::any_of(list.arrows.begin(), list.arrows.end(), test); };
        const bool cut = any([](const auto& a) { return a.cut; });
        const bool dashed = any([](const auto& a) { return a.stretched; });
        EXPECT_EQ(list.legend.cut, cut);
        EXPECT_EQ(list.legend.stretched, dashed);
        const bool joints = any([](const auto& a) { return a.kind == MechanismDrawList::Arrow::Kind::joint; });
        EXPECT_TRUE(!list.legend.joint || joints);
        const bool driver_torque =
            std::any_of(list.torques.begin(), list.torques.end(), [](const auto& t) { return t.driver; });
        for (const MechanismDrawList::Legend::Row& row : list.legend.rows)  // a driver's torque row: its arc
          EXPECT_TRUE(row.kind == MechanismDrawList::Arrow::Kind::driver && row.sweep > 0
                          ? driver_torque
                          : any([&](const auto& a) { return a.kind == row.kind; }))
              << static_cast<int>(row.kind);
        without_cut += cut ? 0 : 1;
        without_dashed += dashed ? 0 : 1;
        with_both += cut && dashed ? 1 : 0;
      }
    }
  }
  EXPECT_GT(without_cut, 0U);
  EXPECT_GT(without_dashed, 0U);
  EXPECT_GT(with_both, 0U);  // both rows are still listed when both kinds are drawn
}

// Issue 23: the four-bar's labels about half the homework clip's, unreadable from the
// back of a lecture hall. The homework draws arrow tags at 12 u and block names at 15 u, bold.
TEST(MechanismForces, LabelsAreAtTheHomeworkClipsSize) {
  const cairo::SurfacePtr surface = cairo::image_surface(16, 16);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  std::size_t labels = 0;
  for_each_laid_out_frame({"four-bar"}, 30, [&](const LaidOutFrame& f) {
    const auto tall = [&](double size) {
      const text::Metrics m = text::metrics(cr.get(), {size, true});
      return m.ascent + m.descent + 3 * f.style.u;  // the box's padding for the halo
    };
    ASSERT_EQ(f.layout.body_labels.size(), 3U);
    labels += f.layout.labels.size();
    for (const PlacedLabel& label : f.layout.labels)
      EXPECT_NEAR(label.box.height, tall(12 * f.style.u), 1e-9) << label.text;
    for (const Rect& body : f.layout.body_labels) EXPECT_NEAR(body.height, tall(15 * f.style.u), 1e-9);
  });
  EXPECT_GE(labels, 50U);
}

// Issue 23 D2: the four-bar's crank 2 hidden under coupler 3. Two bodies drawn one over
// the other: the lower one's edge must show through the upper one (and the upper's too).
TEST(MechanismPainter, ABodyUnderAnotherKeepsItsOutlineInSight) {
  constexpr int kWidth = 400, kHeight = 300;
  const Theme theme = load_theme("light", {}, "theme");
  DrawStyle style;
  style.theme = &theme;
  style.u = 2;
  MechanismDrawList list;
  list.shown = ElementSet::defaults();
  list.shown.hide(Element::grid);
  list.shown.hide(Element::axes);
  list.shown.hide(Element::hud);
  list.shown.hide(Element::title);
  const auto box = [](double x0, double y0, double x1, double y1) {
    return std::vector<Vec2>{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  };
  // A long rod (body 1, drawn first: larger) with a short one (body 0) across its lower edge.
  list.outlines.push_back({0, box(-0.5, -0.4, 0.5, 0.1), Shape::rectangle});
  list.outlines.push_back({1, box(-1.5, 0.0, 1.5, 0.5), Shape::rectangle});
  const Camera camera(View{-2, -1.5, 2, 1.5}, kWidth, kHeight);  // 100 px per metre
  const cairo::SurfacePtr surface = cairo::image_surface(kWidth, kHeight);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  paint_mechanism_frame(cr.get(), style, camera, list, {}, 0, kWidth, kHeight);
  cairo_surface_flush(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const auto distance_to = [&](const Vec2& world, const Rgba& colour) {
    const Vec2 p = camera.to_pixels(world);
    const unsigned char* px = data + static_cast<int>(p.y()) * stride + 4 * static_cast<int>(p.x());  // BGRA
    return std::abs(px[2] / 255.0 - colour.r) + std::abs(px[1] / 255.0 - colour.g) + std::abs(px[0] / 255.0 - colour.b);
  };
  // Body 1's lower edge (y = 0) inside body 0: drawn in body 1's edge colour.
  EXPECT_LT(distance_to({0.2, 0.0}, theme.block_edge[1]), 0.15);
  // Body 0's upper edge (y = 0.1) inside body 1: drawn in body 0's edge colour.
  EXPECT_LT(distance_to({0.2, 0.1}, theme.block_edge[0]), 0.15);
}

// Issue 23 D14: a slider's rail drawn only over the travel, through the body's centre,
// and the ground's hatch inside the moving cart. The rail runs along the guided body's
// underside past both its ends in every frame; a ground support no other joint uses sits
// at the rail's start, outside the body.
TEST(MechanismScene, ASlidersRailRunsUnderTheGuidedBodyOverItsWholeTravel) {
  for (const std::string& name : {std::string("slider-crank"), test_mechanism("cart-pendulum.toml")}) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = clip_motion(system, 4.0, 30);
    const MechanismGeometry geometry = mechanism_geometry(system);
    const MechanismScene scene(geometry, motion, {}, 2.0, {});
    const bool cart = name.ends_with("cart-pendulum.toml");
    const std::size_t guided = cart ? 0 : 2;  // the cart, the piston
    MechanismDrawList list;
    for (std::size_t k = 0; k < motion.samples.size(); ++k) {
      scene.frame(k, list);
      const auto rail = std::find_if(list.lines.begin(), list.lines.end(),
                                     [](const auto& l) { return l.kind == MechanismDrawList::Line::Kind::rail; });
      ASSERT_NE(rail, list.lines.end());
      ASSERT_EQ(rail->points.size(), 2U);
      const Vec2 a = rail->points[0], b = rail->points[1];
      const Vec2 along = (b - a).normalized(), across(-along.y(), along.x());
      const MechanismDrawList::Outline& body = list.outlines[guided];
      ASSERT_EQ(body.body, guided);
      double lowest = 1e300;
      for (const Vec2& p : body.points) {
        EXPECT_GE((p - a).dot(across), -1e-9) << "frame " << k << ": the body reaches below its rail";
        EXPECT_GE((p - a).dot(along), -1e-9) << "frame " << k << ": the body runs off the rail's start";
        EXPECT_LE((p - b).dot(along), 1e-9) << "frame " << k << ": the body runs off the rail's end";
        lowest = std::min(lowest, (p - a).dot(across));
      }
      EXPECT_NEAR(lowest, 0, 1e-9) << "frame " << k << ": the body rests on its rail";
      for (const MechanismDrawList::Marker& m : list.markers) {
        if (!cart || m.kind != MechanismDrawList::Marker::Kind::ground) continue;
        EXPECT_LT((m.at - a).norm(), 1e-12) << "frame " << k << ": the cart's ground support at the rail's start";
      }
    }
  }
}

TEST(MechanismForces, LabelsKeepClearOfEachOtherArrowsAndBodiesAndOnlyStubsGoUnlabelled) {
  constexpr int kWidth = 854, kHeight = 480;
  const Theme theme = load_theme("light", {}, "theme");
  const DrawStyle style = style_at(theme, kWidth, kHeight);
  const cairo::SurfacePtr surface = cairo::image_surface(kWidth, kHeight);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  ArrowScaleRequest own, common, apart;
  common.common = true;
  apart.fixed = {{"joint", 50.0}, {"applied", 0.01}};  // joint forces short, applied ones long
  std::size_t most = 0;
  for (const std::string& name : shipped_mechanism_names()) {
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = clip_motion(system, 4.0, 30);
    for (const ArrowScaleRequest* request : {&own, &common, &apart}) {
      SCOPED_TRACE(name + (request == &common ? ", common" : request == &apart ? ", apart" : ", default"));
      MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, *request);
      const double scale = frame_camera(scene, 0, kWidth, kHeight).scale();
      scene.set_shortest_arrow(least_visible_arrow_px(style) / scale, stretched_arrow_px(style) / scale);
      const Rect title{0, 0, 400, 30};
      MechanismDrawList list;
      // Every other frame, so the worst (the most and longest arrows) are among them.
      for (std::size_t k = 0; k < motion.samples.size(); k += 2) {
        SCOPED_TRACE(k);
        scene.frame(k, list);
        const Camera camera = frame_camera(scene, k, kWidth, kHeight);
        const ForceLayout layout = layout_forces(cr.get(), style, camera, list, kWidth, kHeight, {title});
        const auto& labels = layout.labels;
        most = std::max(most, labels.size());
        ASSERT_EQ(layout.arrows.size(), list.arrows.size());
        std::vector<Segment> arrows = layout.arrows, bodies;  // as drawn
        for (const MechanismDrawList::Outline& outline : list.outlines)
          for (std::size_t i = 0; outline.points.size() > 2 && i < outline.points.size(); ++i)
            bodies.push_back({camera.to_pixels(outline.points[i]),
                              camera.to_pixels(outline.points[(i + 1) % outline.points.size()]),
                              static_cast<int>(outline.body)});
        for (const Rect& body : layout.body_labels) EXPECT_FALSE(touches(body, arrows)) << "a body's name";
        for (std::size_t i = 0; i < layout.body_labels.size(); ++i)
          for (std::size_t j = i + 1; j < layout.body_labels.size(); ++j)
            EXPECT_FALSE(overlaps(layout.body_labels[i], layout.body_labels[j])) << "two bodies' names";
        for (std::size_t i = 0; i < labels.size(); ++i) {
          for (std::size_t j = i + 1; j < labels.size(); ++j)
            EXPECT_FALSE(overlaps(labels[i].box, labels[j].box)) << labels[i].text << " / " << labels[j].text;
          for (const Rect& body : layout.body_labels) EXPECT_FALSE(overlaps(labels[i].box, body)) << labels[i].text;
          EXPECT_FALSE(overlaps(labels[i].box, layout.legend)) << labels[i].text;
          EXPECT_FALSE(overlaps(labels[i].box, title)) << labels[i].text;
          EXPECT_FALSE(touches(labels[i].box, arrows)) << labels[i].text;
          EXPECT_FALSE(touches(labels[i].box, bodies)) << labels[i].text;
        }
        // A label is left out only when its arrow is shorter than the label is high.
        std::size_t unlabelled = 0;
        for (std::size_t a = 0; a < list.arrows.size(); ++a) {
          const MechanismDrawList::Arrow& arrow = list.arrows[a];
          const bool labelled = std::any_of(labels.begin(), labels.end(), [&](const PlacedLabel& l) {
            return l.text == arrow.label && (l.head - layout.arrows[a].b).norm() < 1e-9;
          });
          if (!labelled) {
            ++unlabelled;
            EXPECT_FALSE(arrow.stretched) << arrow.label;
            EXPECT_LT(arrow.vector.norm() * camera.scale(), labels.empty() ? 1e9 : labels.front().box.height)
                << arrow.label;
          }
        }
        // Every joint named too (the homework's P), clear of all the rest as above.
        EXPECT_EQ(labels.size() + unlabelled, list.arrows.size() + list.torques.size() + list.joint_labels.size());
      }
    }
  }
  EXPECT_GE(most, 5U);  // crowded frames were among them
}

TEST(MechanismScene, ArrowScalesAsAskedAndShortArrowsStretched) {
  const sym::System system(load_mechanism("slider-crank"));
  const MechanismMotion motion = clip_motion(system, 1.0, 30);
  ArrowScaleRequest request;
  request.fixed = {{"joint", 1000.0}};  // 1 cm = 1 kN: every joint force is a stub
  ElementSet joints_only = ElementSet::defaults();
  joints_only.hide(Element::gravity);  // gravity keeps a scale of its own
  MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, request, joints_only);
  EXPECT_NEAR(scene.force_scale(), 0.01 / 1000, 1e-18);
  MechanismDrawList list;
  scene.frame(3, list);
  EXPECT_EQ(list.legend.joint_scale, "1 cm = 1 kN");
  EXPECT_FALSE(list.legend.stretched);
  scene.set_shortest_arrow(0.05);
  scene.frame(3, list);
  EXPECT_TRUE(list.legend.stretched);
  ASSERT_FALSE(list.arrows.empty());
  for (const MechanismDrawList::Arrow& arrow : list.arrows) {
    EXPECT_TRUE(arrow.stretched) << arrow.label;
    EXPECT_NEAR(arrow.vector.norm(), 0.05, 1e-12) << arrow.label;
    EXPECT_NE(arrow.label.find(" N"), std::string::npos) << arrow.label;  // says its value
  }
}

TEST(MechanismScene, LegendScaleIsTheArrowsScaleAndATypicalFrameReads) {
  for (const char* name : {"four-bar", "slider-crank", "double-pendulum"}) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = clip_motion(system, 4.0, 30);
    ElementSet joints_only = ElementSet::defaults();
    joints_only.hide(Element::gravity);  // gravity keeps a scale of its own
    const MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, {}, joints_only);
    MechanismDrawList list;
    scene.frame(0, list);
    const MechanismDrawList::Legend& legend = list.legend;
    ASSERT_GT(legend.newtons, 0);
    EXPECT_TRUE(legend.joint);
    EXPECT_FALSE(legend.applied);
    const double ratio = legend.metres / legend.newtons;  // m per N, as the legend draws it
    EXPECT_NEAR(ratio, scene.force_scale(), 1e-12 * ratio);
    EXPECT_EQ(legend.value, format_quantity(legend.newtons, "N"));
    std::vector<double> largest;
    bool any_cut = false, legend_cut = false;
    for (std::size_t k = 0; k < motion.samples.size(); ++k) {
      scene.frame(k, list);
      legend_cut = legend_cut || list.legend.cut;  // the frame's legend: its own arrows
      double frame_largest = 0;
      for (const MechanismDrawList::Arrow& arrow : list.arrows) {
        const double length = arrow.vector.norm();
        frame_largest = std::max(frame_largest, length);
        if (arrow.cut) {
          any_cut = true;
          EXPECT_NEAR(length, scene.arrow_cap(), 1e-12);
          EXPECT_GT(arrow.force * ratio, scene.arrow_cap());
          EXPECT_NE(arrow.label.find(" N"), std::string::npos) << arrow.label;  // says its value
        } else {
          EXPECT_NEAR(length, arrow.force * ratio, 1e-12) << arrow.label;
        }
      }
      largest.push_back(frame_largest);
    }
    EXPECT_EQ(any_cut, legend_cut);
    // The median frame's longest arrow is a readable share of the mechanism (the four-bar's
    // was a hundredth with one scale for the peak).
    std::nth_element(largest.begin(), largest.begin() + static_cast<std::ptrdiff_t>(largest.size() / 2), largest.end());
    EXPECT_GT(largest[largest.size() / 2], scene.extent() / 12);
    EXPECT_LE(largest[largest.size() / 2], scene.extent() / 6 * (1 + 1e-12));
  }
}

TEST(MechanismScene, SpringDamperDrawsACoilBesideADashpot) {
  for (const double damping : {0.05, 0.0}) {
    SCOPED_TRACE(damping);
    Mechanism mechanism = load_mechanism("spring-pendulum");
    for (Parameter& p : mechanism.parameters)
      if (p.name == "c") p.value = damping;
    const sym::System system(mechanism);
    const MechanismMotion motion = sampled(system, 0.3, 0.1);
    const MechanismScene scene(mechanism_geometry(system), motion, {});
    MechanismDrawList list;
    scene.frame(2, list);
    const Vec2 a(0, 0), b(motion.samples[2].pose[0], motion.samples[2].pose[1]);
    const Vec2 unit = (b - a).normalized();
    // Which side of the line a-b a point is on, in metres.
    const auto side = [&](const Vec2& p) { return unit.x() * (p - a).y() - unit.y() * (p - a).x(); };
    int coils = 0, dashpot_lines = 0;
    double coil_side = 0, dashpot_side = 0;
    for (const MechanismDrawList::Line& line : list.lines) {
      if (line.kind == MechanismDrawList::Line::Kind::spring) {
        ++coils;
        EXPECT_GE(line.points.size(), 16U);  // the zig-zag
        for (const Vec2& p : line.points) coil_side += side(p);
      } else if (line.kind == MechanismDrawList::Line::Kind::dashpot) {
        ++dashpot_lines;
        for (const Vec2& p : line.points) dashpot_side += side(p);
      }
    }
    EXPECT_EQ(coils, 1);
    if (damping > 0) {
      EXPECT_GE(dashpot_lines, 3);             // the bars, the cylinder, the piston
      EXPECT_LT(coil_side * dashpot_side, 0);  // on opposite sides of the line between the ends
    } else {
      EXPECT_EQ(dashpot_lines, 0);
    }
  }
}

constexpr const char* kDriven = R"toml(title = "A driven pendulum"
gravity = "g"
[parameters]
g = 9.81
F0 = 0.5
Omega = 6
tau0 = 0.02
[ground]
points = { O = [0, 0] }
[[body]]
name = "1"
shape = "rod"
mass = 0.2
length = 0.4
points = { O = [-0.2, 0], E = [0.2, 0] }
[[joint]]
name = "O"
type = "pin"
bodies = ["ground", "1"]
points = ["O", "O"]
[[force]]
body = "1"
point = "E"
value = ["0", "-F0*sin(Omega*t)"]
[[torque]]
body = "1"
value = "tau0"
[initial]
"1" = { theta = -0.5 }
)toml";

TEST(MechanismScene, AppliedForceAndTorqueAreDrawnWithTheirValueAtTheFramesTime) {
  const sym::System system(read_mechanism(kDriven, "driven.toml"));
  const MechanismMotion motion = sampled(system, 0.5, 0.1);
  const MechanismScene scene(mechanism_geometry(system), motion, {});
  MechanismDrawList list;
  for (std::size_t k = 1; k < motion.samples.size(); ++k) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const double t = motion.times[k], force = -0.5 * std::sin(6 * t);
    EXPECT_TRUE(list.legend.applied);
    const auto applied = std::find_if(list.arrows.begin(), list.arrows.end(),
                                      [](const auto& a) { return a.kind == MechanismDrawList::Arrow::Kind::applied; });
    ASSERT_NE(applied, list.arrows.end());
    const auto& pose = motion.samples[k].pose;
    const Vec2 end = Vec2(pose[0], pose[1]) + 0.2 * Vec2(std::cos(pose[2]), std::sin(pose[2]));
    EXPECT_NEAR((applied->tail - end).norm(), 0, 1e-12);  // at the point E
    EXPECT_NEAR(applied->force, std::fabs(force), 1e-12);
    EXPECT_NEAR(applied->vector.x(), 0, 1e-12);
    EXPECT_GT(applied->vector.y() * force, 0);  // along the force
    EXPECT_EQ(applied->label, "F = " + format_quantity(std::fabs(force), "N"));
    ASSERT_EQ(list.torques.size(), 1U);
    EXPECT_GT(list.torques[0].sweep, 0);  // counter-clockwise, as tau0 > 0
    EXPECT_NEAR((list.torques[0].centre - Vec2(pose[0], pose[1])).norm(), 0, 1e-12);
    EXPECT_EQ(list.torques[0].label, "τ = 0.02 N m");
  }
}

TEST(MechanismClip, TrailsAreSampledFourTimesAFrameOrMore) {
  const sym::System system(load_mechanism("four-bar"));
  constexpr double kFps = 30;
  const MechanismMotion motion = clip_motion(system, 1.0, kFps, 4);
  ASSERT_GE(motion.trail_times.size(), 4 * (motion.times.size() - 1) + 1);
  for (const double t : motion.times)
    EXPECT_TRUE(std::find(motion.trail_times.begin(), motion.trail_times.end(), t) != motion.trail_times.end()) << t;
  ASSERT_EQ(motion.trail_poses.size(), motion.trail_times.size());
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {geometry.resolve("3.B", "--trail")}, 2.0);
  MechanismDrawList list;
  for (const std::size_t k : {std::size_t{1}, std::size_t{10}, motion.samples.size() - 1}) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const MechanismDrawList::Line& trail = list.lines.back();
    ASSERT_EQ(trail.kind, MechanismDrawList::Line::Kind::trail);
    EXPECT_GE(trail.points.size(), 4 * k + 1);  // every frame interval so far, 4 points each or more
    // It ends at the frame's own point, and its steps are a quarter of a frame's.
    EXPECT_NEAR((trail.points.back() - world_point(motion.samples[k].pose, geometry.resolve("3.B", ""))).norm(), 0,
                1e-12);
    const Vec2 frame_step = world_point(motion.samples[k].pose, geometry.resolve("3.B", "")) -
                            world_point(motion.samples[k - 1].pose, geometry.resolve("3.B", ""));
    const Vec2 last_step = trail.points.back() - trail.points[trail.points.size() - 2];
    EXPECT_LT(last_step.norm(), 0.4 * frame_step.norm());
    // It fades with age: 1 at the frame's point, 1 - age / 2 s before (drawn with
    // opacity fade squared, render/scene_painter.hpp trail_alpha).
    ASSERT_EQ(trail.fade.size(), trail.points.size());
    EXPECT_DOUBLE_EQ(trail.fade.back(), 1.0);
    EXPECT_NEAR(trail.fade.front(), 1.0 - (motion.times[k] - motion.trail_times.front()) / 2.0, 1e-9);
    for (std::size_t j = 1; j < trail.fade.size(); ++j) EXPECT_GT(trail.fade[j], trail.fade[j - 1]);
  }
}

// A fast crank's trail is a smooth circle, not a polygon of a few frames' points: the
// engine's crank pin at 10 rev/s covers 120 degrees a frame at 30 fps, and its trail turns
// at most 3 degrees from one sample to the next (kTrailTurn), over the whole cycle.
TEST(MechanismClip, AFastCranksTrailTurnsLittleBetweenSamples) {
  const sym::System system(load_mechanism("engine"));
  const MechanismMotion motion = clip_motion(system, 0.1, 30, 4);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const BodyPoint pin = geometry.resolve("crank.A", "--trail");
  ASSERT_GE(motion.trail_poses.size(), 120U);  // one cycle (0.1 s), 3 frames
  double worst = 0;
  for (std::size_t j = 2; j < motion.trail_poses.size(); ++j) {
    const Vec2 a = world_point(motion.trail_poses[j - 1], pin) - world_point(motion.trail_poses[j - 2], pin);
    const Vec2 b = world_point(motion.trail_poses[j], pin) - world_point(motion.trail_poses[j - 1], pin);
    worst = std::max(worst, std::fabs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b))));
  }
  EXPECT_GT(worst, 0);
  EXPECT_LE(worst, std::numbers::pi / 60 + 1e-9);
}

// A pin's torsional spring (four-bar-spring's at O4) is drawn as a spiral about the pin:
// its inner end fixed to bodies[0] (the ground), its outer end turning with bodies[1], so
// between two frames it winds by the rocker's turn.
TEST(MechanismClip, ATorsionalSpringIsASpiralAboutItsPinThatTurnsWithTheBody) {
  const sym::System system(load_mechanism("four-bar-spring"));
  const MechanismMotion motion = clip_motion(system, 0.3, 30);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {}, 2.0);
  const Vec2 pin = geometry.ground.back().second;  // O4
  std::vector<double> outer_angles;
  for (const std::size_t k : {std::size_t{0}, motion.samples.size() - 1}) {
    MechanismDrawList list;
    scene.frame(k, list);
    const auto spiral = std::find_if(list.lines.begin(), list.lines.end(), [&](const MechanismDrawList::Line& l) {
      return l.kind == MechanismDrawList::Line::Kind::spring && (l.points.front() - pin).norm() < 0.05;
    });
    ASSERT_NE(spiral, list.lines.end()) << "frame " << k;
    double last = 0;
    for (const Vec2& p : spiral->points) {  // outwards all the way
      EXPECT_GE((p - pin).norm(), last - 1e-12);
      last = (p - pin).norm();
    }
    const Vec2 end = spiral->points.back() - pin;
    outer_angles.push_back(std::atan2(end.y(), end.x()));
  }
  const double rocker = motion.samples.back().pose[3 * 2 + 2] - motion.samples.front().pose[3 * 2 + 2];
  EXPECT_GT(std::fabs(rocker), 0.01);
  EXPECT_NEAR(std::remainder(outer_angles[1] - outer_angles[0] - rocker, 2 * std::numbers::pi), 0, 1e-9);
}

// Issue 27: a rolling joint (rolling-disc's R1) is its line drawn as a surface along the
// axis, the disc's centre at the radius over it, and the contact point marked on it under
// the centre, in every frame.
TEST(MechanismClip, ARollingJointIsASurfaceWithTheContactPointMarked) {
  const sym::System system(load_mechanism("rolling-disc"));
  const MechanismMotion motion = clip_motion(system, 0.5, 10);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {}, 2.0);
  const double alpha = 0.03, r = 0.3;
  const Vec2 u(std::cos(alpha), -std::sin(alpha)), n(std::sin(alpha), std::cos(alpha));
  for (const std::size_t k : {std::size_t{0}, motion.samples.size() - 1}) {
    MechanismDrawList list;
    scene.frame(k, list);
    const Vec2 centre(motion.samples[k].pose[0], motion.samples[k].pose[1]), contact = centre - r * n;
    const auto surface = std::find_if(list.lines.begin(), list.lines.end(), [&](const MechanismDrawList::Line& l) {
      return l.kind == MechanismDrawList::Line::Kind::surface && std::fabs((l.points.front()).dot(n)) < 1e-12;
    });
    ASSERT_NE(surface, list.lines.end()) << "frame " << k;
    ASSERT_EQ(surface->points.size(), 2U);
    const Vec2 along = surface->points[1] - surface->points[0];
    EXPECT_NEAR(along.normalized().dot(u), 1, 1e-12);
    const double at = contact.dot(u);  // the contact point lies within the surface drawn
    EXPECT_LT(surface->points[0].dot(u), at);
    EXPECT_GT(surface->points[1].dot(u), at);
    EXPECT_TRUE(std::any_of(list.markers.begin(), list.markers.end(),
                            [&](const MechanismDrawList::Marker& m) {
                              return m.kind == MechanismDrawList::Marker::Kind::pin && (m.at - contact).norm() < 1e-12;
                            }))
        << "frame " << k;
  }
}

// Issue 23: every picture option on every shipped mechanism gives a still (SVG and PDF
// whole and all vector), and the draw list holds what the options say.
TEST(MechanismClip, EveryPictureOptionOnEveryShippedMechanism) {
  test::TempDir dir;
  using Kind = MechanismDrawList::Arrow::Kind;
  for (const std::string& name : shipped_mechanism_names()) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const GiNaC::exmap initial = sym::checked_initial_state(system).state;
    ElementSet shown = ElementSet::defaults();
    shown.show(Element::velocity);
    shown.show(Element::gravity);
    shown.hide(Element::legend);
    shown.hide(Element::labels);
    const MechanismGeometry geometry = mechanism_geometry(system);
    const MechanismMotion motion = clip_motion(system, 0.5, 30);
    const MechanismScene scene(geometry, motion, {}, 2.0, {}, shown);
    MechanismDrawList list;
    const std::size_t bodies = geometry.bodies.size(), k = 10;
    scene.frame(k, list);
    const auto count = [&](Kind kind) {
      return static_cast<std::size_t>(
          std::count_if(list.arrows.begin(), list.arrows.end(), [&](const auto& a) { return a.kind == kind; }));
    };
    EXPECT_EQ(count(Kind::gravity), bodies);  // every shipped mechanism has gravity
    std::size_t moving = 0;
    for (std::size_t i = 0; i < bodies; ++i)
      if (std::hypot(motion.samples[k].rates[3 * i], motion.samples[k].rates[3 * i + 1]) > 0) ++moving;
    EXPECT_EQ(count(Kind::velocity), moving);
    EXPECT_TRUE(list.labels.empty());
    for (const MechanismDrawList::Arrow& arrow : list.arrows) EXPECT_EQ(arrow.label, "");
    EXPECT_FALSE(list.shown.has(Element::legend));

    const std::vector<std::pair<std::string, std::function<void(MechanismClip&)>>> options{
        {"fbd", [](MechanismClip& c) { c.settings.free_body = true; }},
        {"follow",
         [](MechanismClip& c) {
           c.settings.camera_chosen = true;
           c.settings.camera = CameraMode::follow;
         }},
        {"fit",
         [](MechanismClip& c) {
           c.settings.camera_chosen = true;
           c.settings.camera = CameraMode::fit;
         }},
        {"shown", [&](MechanismClip& c) { c.settings.elements = shown; }},
        {"svg", [&](MechanismClip& c) { c.out = dir / (name + ".svg"); }},
        {"pdf", [&](MechanismClip& c) { c.out = dir / (name + ".pdf"); }},
    };
    for (const auto& [option, apply] : options) {
      SCOPED_TRACE(option);
      MechanismClip clip = small_still((dir / (name + "-" + option + ".png")).string());
      apply(clip);
      EXPECT_EQ(produce_mechanism_clip(system, initial, clip).stats.frames_drawn, 1);
      EXPECT_TRUE(std::filesystem::exists(*clip.out));
    }
    const std::string figure = test::read_text(dir / (name + ".svg"));
    EXPECT_EQ(test::xml_error(figure), "");
    EXPECT_NE(figure.find("width=\"160px\""), std::string::npos) << figure.substr(0, 300);
    EXPECT_EQ(figure.find("<image"), std::string::npos) << "a vector figure holds no bitmaps";
    // A filled outline per body at least, besides the background.
    std::size_t paths = 0;
    for (std::size_t at = figure.find("<path"); at != std::string::npos; at = figure.find("<path", at + 1)) ++paths;
    EXPECT_GT(paths, bodies);
    const std::string document = test::read_text(dir / (name + ".pdf"));
    EXPECT_EQ(document.rfind("%PDF-", 0), 0U);
    EXPECT_NE(document.find("%%EOF", document.size() - 8), std::string::npos);
  }
  EXPECT_EQ(test::entries(dir.path()).size(), 6 * shipped_mechanism_names().size());  // no temporary left
}

// Issue 25, Deliver 8: a still of driven-four-bar.toml draws the motor at O2 = (0, 0) in
// the theme's motor colour; the shipped four-bar (the same linkage, undriven) and the
// driven one with the motor hidden have none there. The SVG holds the motor's paths.
TEST(MechanismClip, ADriversMotorIsDrawnAtItsJointInTheMotorColour) {
  test::TempDir dir;
  const auto motor_pixels = [&](const std::string& mechanism, bool shown, const std::string& name) {
    const sym::System system(load_mechanism(mechanism));
    MechanismClip clip = small_still((dir / (name + ".png")).string());
    clip.settings.width = 640;
    clip.settings.height = 360;
    clip.settings.at = 1.0;
    clip.simulation.duration = 1.0;
    clip.settings.camera_chosen = true;
    clip.settings.camera = CameraMode::fixed;
    clip.settings.view = {-0.25, -0.2, 0.45, 0.35};
    if (!shown) clip.settings.elements.hide(Element::motor);
    produce_mechanism_clip(system, sym::checked_initial_state(system).state, clip);
    const test::DecodedPng png = test::decode_png(*clip.out);
    const Vec2 o2 = Camera(clip.settings.view, 640, 360).to_pixels(Vec2::Zero());
    const Rgba& motor = clip.theme.motor;
    int count = 0;
    for (std::uint32_t y = 0; y < png.height; ++y)
      for (std::uint32_t x = 0; x < png.width; ++x) {
        if (std::hypot(x - o2.x(), y - o2.y()) > 30) continue;
        const std::uint8_t* p = &png.rgba[4 * (y * png.width + x)];
        if (std::abs(p[0] - motor.r * 255) < 24 && std::abs(p[1] - motor.g * 255) < 24 &&
            std::abs(p[2] - motor.b * 255) < 24)
          ++count;
      }
    if (shown) {
      clip.out = dir / (name + ".svg");
      produce_mechanism_clip(system, sym::checked_initial_state(system).state, clip);
    }
    return count;
  };
  const std::string driven = test_mechanism("driven-four-bar.toml");
  EXPECT_GT(motor_pixels(driven, true, "driven"), 60);
  EXPECT_EQ(motor_pixels(driven, false, "hidden"), 0);
  EXPECT_EQ(motor_pixels("four-bar", true, "undriven"), 0);
  // Cairo writes a colour as rgb(R%,G%,B%), six decimals, trailing zeros dropped: the motor's,
  // in the driven figure only.
  const Rgba& motor = load_theme("light", {}, "theme").motor;
  const auto percent = [](double channel) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", channel * 100);
    std::string out = text;
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
    return out + "%";
  };
  const std::string colour = "rgb(" + percent(motor.r) + "," + percent(motor.g) + "," + percent(motor.b) + ")";
  const std::string figure = test::read_text(dir / "driven.svg");
  EXPECT_EQ(test::xml_error(figure), "");
  EXPECT_NE(figure.find(colour), std::string::npos) << colour;
  EXPECT_EQ(test::read_text(dir / "undriven.svg").find(colour), std::string::npos);
}

}  // namespace
}  // namespace linkage
