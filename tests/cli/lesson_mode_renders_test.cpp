// A lesson's render steps draw modes of small vibration (issue 26): every mode's sheet
// (modes_sheet), one mode's clip (mode) and the full equations started on a mode
// (nonlinear), the files linked from lesson.md; bad mode keys refused at their place.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

const fs::path kLesson =
    fs::path(LINKAGE_SOURCE_DIR) / "tests/data/mechanism-lessons/double-pendulum-mode-renders.toml";

TEST(LessonModeRenders, RendersTheSheetAndAModesClipAndLinksThem) {
  const TempDir dir;
  const fs::path out = dir.path() / "out";
  const RunResult run = run_linkage({"lesson", kLesson.string(), "--quality", "draft", "--out", (out / "").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"modes.png", "mode-2.mp4", "mode-1-nonlinear.png"}) {
    ASSERT_TRUE(fs::exists(out / name)) << name;
    EXPECT_GT(fs::file_size(out / name), 1000U) << name;
  }
  EXPECT_EQ(read_text(out / "modes.png").substr(1, 3), "PNG");
  const std::string document = read_text(out / "lesson.md");
  for (const char* name : {"modes.png", "mode-2.mp4", "mode-1-nonlinear.png"})
    EXPECT_NE(document.find(std::string("(") + name + ")"), std::string::npos) << name << "\n" << document;
  // The sheet is the command's: the same picture as render --modes-sheet at draft size.
  const RunResult cli = run_linkage({"render", "--quiet", "--mechanism", "double-pendulum", "--size", "480x270",
                                     "--amplitude", "0.2", "--modes-sheet", (dir.path() / "cli.png").string()});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(read_text(dir.path() / "cli.png"), read_text(out / "modes.png"));
  // And the mode's still is render --mode's at draft size and rate.
  const RunResult mode = run_linkage({"render", "--quiet", "--mechanism", "double-pendulum", "--mode", "1",
                                      "--nonlinear", "--amplitude", "0.5", "--at", "0.5", "--size", "480x270", "--fps",
                                      "15", "--out", (dir.path() / "mode.png").string()});
  ASSERT_EQ(mode.exit_code, 0) << mode.err;
  EXPECT_EQ(read_text(dir.path() / "mode.png"), read_text(out / "mode-1-nonlinear.png"));
}

struct BadModeKeys {
  const char* keys;
  const char* message;
};

TEST(LessonModeRenders, BadModeKeysAreRefusedAtTheirPlace) {
  const BadModeKeys cases[] = {
      {"out = \"a.png\"\nmodes_sheet = true\nmode = 1\n",
       ":8:8: step 1 (render): 'mode' does not combine with 'modes_sheet'"},
      {"out = \"a.mp4\"\nmodes_sheet = true\n", ":6:7: step 1 (render): 'a.mp4' is a video"},
      {"out = \"a.png\"\nmodes_sheet = true\nensemble = 5\n", ":8:12: step 1 (render): 'ensemble' does not combine"},
      {"out = \"a.png\"\nmodes_sheet = true\npanel = [\"energy\"]\n",
       ":8:9: step 1 (render): 'panel' does not combine with 'modes_sheet'"},
      {"out = \"a.png\"\nmodes_sheet = true\ncaptions = [{at = 0, text = \"x\"}]\n",
       ":8:12: step 1 (render): 'captions' does not combine with 'modes_sheet'"},
      {"out = \"a.png\"\namplitude = 0.2\n", ":7:13: step 1 (render): 'amplitude' applies only with 'mode' or"},
      {"out = \"a.png\"\nmode = 1\namplitude = 0\n", ":8:13: step 1 (render): amplitude: 0; valid:"},
      {"out = \"a.png\"\nmode = 3\n", ": step 1 (render): mode: 3 is out of range; double-pendulum has 2 modes"},
      {"out = \"a.png\"\nmode = 1\ncompare = [\"integrator=rk4\"]\n", "'compare' does not combine with 'mode'"},
      {"out = \"a.png\"\nmode = 1\ncase = 1\n",
       ":8:8: step 1 (render): case = 1 applies to 'mode' only with 'nonlinear'"},
  };
  for (const BadModeKeys& c : cases) {
    SCOPED_TRACE(c.keys);
    const TempDir dir;
    const fs::path lesson = dir.path() / "bad.toml";
    write_text(
        lesson,
        std::string("title = \"bad\"\nmechanism = \"double-pendulum\"\n\n[[step]]\nkind = \"render\"\n") + c.keys);
    const RunResult run = run_linkage({"lesson", lesson.string(), "--out", (dir.path() / "out/").string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out" / "a.png"));
  }
}

}  // namespace
}  // namespace linkage::test
