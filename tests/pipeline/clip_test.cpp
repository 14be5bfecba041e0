// The one render pipeline: a clip is a value, producing it is one call.
#include "pipeline/clip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "pipeline/panel_data.hpp"
#include "render/frame_layout.hpp"
#include "render/render_test_support.hpp"
#include "scene/motion.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {
namespace fs = std::filesystem;

Clip small_clip() {
  Clip clip;
  clip.settings.width = 64;
  clip.settings.height = 36;
  clip.settings.fps = 10;
  clip.settings.duration = 0.4;
  clip.simulation.duration = 0.4;
  clip.theme = load_theme("light", {}, "theme");
  return clip;
}

std::string setting_of(const Clip& clip) {
  try {
    clip.validate();
  } catch (const Error& e) {
    return e.setting();
  }
  return "(valid)";
}

TEST(Clip, FramesFolderIsMadeWithItsParentsAndFilled) {
  test::TempDir dir;
  Clip clip = small_clip();
  clip.frames = dir / "a" / "b" / "c";
  std::vector<long> drawn;
  const ClipResult result = produce_clip(clip, [&](ClipStage stage, long done, long total) {
    EXPECT_EQ(total, stage == ClipStage::draw ? 4 : 4);
    if (stage == ClipStage::draw) drawn.push_back(done);
  });
  EXPECT_EQ(drawn, (std::vector<long>{1, 2, 3, 4}));
  EXPECT_EQ(result.stats.frames_drawn, 4);
  EXPECT_EQ(result.stats.png_files_written, 4);
  EXPECT_FALSE(result.stats.encoder_opened);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(*clip.frames)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png", "frame_00003.png"}));
}

TEST(Clip, StillDrawsOneFrameAndOpensNoEncoder) {
  test::TempDir dir;
  Clip clip = small_clip();
  clip.out = dir / "still.png";
  clip.settings.at = 0.3;
  const ClipResult result = produce_clip(clip);
  EXPECT_EQ(result.stats.frames_drawn, 1);
  EXPECT_EQ(result.stats.png_files_written, 1);
  EXPECT_FALSE(result.stats.encoder_opened);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"still.png"});
}

TEST(Clip, ErrorsNameTheSettingNotAFlag) {
  test::TempDir dir;
  Clip clip = small_clip();
  EXPECT_EQ(setting_of(clip), "out");  // neither a file nor frames
  clip.out = dir / "clip.mp4";
  EXPECT_EQ(setting_of(clip), "(valid)");
  Clip bad = clip;
  bad.settings.fps = 0;
  EXPECT_EQ(setting_of(bad), "fps");
  bad = clip;
  bad.simulation.dt = 0;
  EXPECT_EQ(setting_of(bad), "dt");
  bad = clip;
  bad.out = "-";  // an MP4 is finished by seeking: never standard output
  EXPECT_THROW((void)produce_clip(bad), Error);
  bad = clip;
  test::write_text(dir / "file", "x");
  bad.frames = dir / "file";
  EXPECT_EQ(setting_of(bad), "frames");
  bad = clip;
  bad.out = dir / "clip.avi";
  EXPECT_EQ(setting_of(bad), "out");
}

TEST(ClipPanel, ValuesAreTheRunsQuantitiesWithWordsAndUnits) {
  const Clip clip = small_clip();
  SimulationOptions options = clip.simulation;
  Simulation sim(clip.inputs.params(), clip.inputs.state(), options);
  const Motion motion = sample_motion(sim, {0.0, 0.1, 0.2}, false);
  const PanelData data = homework_panel({"theta1", "F_x", "energy_error"}, sim, motion, clip.inputs.params(),
                                        body_state(clip.inputs.params(), clip.inputs.state()), 0.4);
  ASSERT_EQ(data.curves.size(), 3u);
  EXPECT_EQ(data.curves[0].label, "θ_{1}");
  EXPECT_EQ(data.curves[0].unit, "rad");
  EXPECT_EQ(data.curves[1].label, "pin force F_{x}");
  EXPECT_EQ(data.curves[1].unit, "N");
  EXPECT_EQ(data.t, (std::vector<double>{0.0, 0.1, 0.2}));
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(data.curves[0].values[k], motion.samples[k].state.theta1);
    EXPECT_NEAR(data.curves[1].values[k], sim.dynamics(motion.samples[k].state).F_x, 1e-9);
    EXPECT_LT(data.curves[2].values[k], 1e-6);  // dop853's relative energy error over 0.2 s
  }
  EXPECT_EQ(data.curves[2].values[0], 0.0);
}

TEST(ClipPanel, UnknownQuantityIsOneLineListingTheValidNames) {
  test::TempDir dir;
  Clip clip = small_clip();
  clip.out = dir / "still.png";
  clip.settings.panel = {"theta1", "thetta2"};
  try {
    clip.validate();
    ADD_FAILURE() << "accepted an unknown quantity";
  } catch (const Error& e) {
    EXPECT_EQ(e.setting(), "panel");
    const std::string detail = e.detail();
    EXPECT_EQ(detail.find('\n'), std::string::npos);
    EXPECT_NE(detail.find("'thetta2' is not a quantity to plot (did you mean 'theta2'?)"), std::string::npos) << detail;
    EXPECT_NE(detail.find("valid: t, x1, y1, theta1"), std::string::npos) << detail;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ClipPanel, StillShowsTheCurveBesideTheMotionAndTheCaptionBelow) {
  test::TempDir dir;
  Clip clip = small_clip();
  clip.settings.width = 640;
  clip.settings.height = 360;
  clip.settings.at = 1.0;
  clip.simulation.duration = 1.0;
  clip.inputs.set(*find_input_key("theta1_dot"), 5.0, "test");
  clip.settings.panel = {"theta1"};
  clip.settings.captions = {{0.0, "Block 1 turns at a steady rate"}};
  clip.out = dir / "still.png";
  (void)produce_clip(clip);
  const Frame frame = test::read_png_file(*clip.out);
  FrameLayout layout(clip.settings, clip.theme, PanelData{{0.0}, {{"θ_{1}", "rad", {0.0}}}, 1.0});
  const Rect panel = layout.panel_rect();
  ASSERT_EQ(panel.x, 384);
  // The curve's colour (palette slot 0) fills a stretch of the panel and nothing of the scene.
  const plot::Rgb blue = plot::palette(plot::Theme::light)[0];
  const test::Rgb8 curve{static_cast<int>(std::lround(255 * blue.r)), static_cast<int>(std::lround(255 * blue.g)),
                         static_cast<int>(std::lround(255 * blue.b))};
  int in_panel = 0;
  for (int y = 0; y < static_cast<int>(panel.height); ++y)
    for (int x = static_cast<int>(panel.x); x < 640; ++x)
      in_panel += test::colour_distance(test::rgb_at(frame, x, y), curve) < 30 ? 1 : 0;
  EXPECT_GT(in_panel, 150);
  // The caption band spans the bottom in the theme's panel colour behind the words.
  const Rect band = layout.caption_rect();
  EXPECT_GT(band.height, 10);
  EXPECT_EQ(test::colour_distance(test::rgb_at(frame, 1, 359), test::rgb8(clip.theme.background)), 0);
  if (const auto folder = test::picture_folder(); !folder.empty())
    std::filesystem::copy_file(*clip.out, folder / "panel-still.png",
                               std::filesystem::copy_options::overwrite_existing);
}

}  // namespace
}  // namespace linkage
