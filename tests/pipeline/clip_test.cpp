// The one render pipeline: a clip is a value, producing it is one call.
#include "pipeline/clip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
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

}  // namespace
}  // namespace linkage
