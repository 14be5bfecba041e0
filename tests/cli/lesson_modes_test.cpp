// A lesson's modes step and the modes' quantities (issue 26): the report in every format
// of the lesson, and an exercise on the double pendulum's second frequency against the
// closed form of two uniform rods.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>

#include "support/closed_forms.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

const fs::path kLesson = fs::path(LINKAGE_SOURCE_DIR) / "tests/data/mechanism-lessons/double-pendulum-modes.toml";

TEST(LessonModes, TheSecondFrequencyMatchesTheClosedForm) {
  TempDir dir;
  const RunResult r = run_linkage({"lesson", kLesson.string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The answer to 17 digits, its unit the quantity's.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(Answer: ([0-9.e+-]+) Hz)"))) << r.out;
  const auto w2 = double_pendulum_w2(0.7, 1.3, 0.4, 0.55, 9.81, 1);
  EXPECT_NEAR(std::stod(m[1]) / (std::sqrt(w2[1]) / (2 * std::numbers::pi)), 1, 1e-10) << m[1];
  // The step prints `linkage modes` at the lesson's settings, to its digits.
  const RunResult modes = run_linkage({"modes", "--mechanism", "double-pendulum", "--set", "l1=0.7", "--set", "m1=1.3",
                                       "--set", "l2=0.4", "--set", "m2=0.55", "--digits", "8"});
  ASSERT_EQ(modes.exit_code, 0) << modes.err;
  const std::size_t table = modes.out.find("4. The modes");
  ASSERT_NE(table, std::string::npos);
  EXPECT_NE(r.out.find(modes.out.substr(table)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Two rods, 2 modes."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("The slow mode swings at "), std::string::npos) << r.out;
}

TEST(LessonModes, TheDocumentAndTheHandoutHoldTheModesInTheirFormats) {
  TempDir dir;
  const RunResult r = run_linkage({"lesson", kLesson.string(), "--out", (dir / "out").string(), "--format", "latex"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\\textbf{4. The modes: $K v = \\omega^2 M v$.}"), std::string::npos) << r.out;
  const std::string md = read_text(dir / "out" / "lesson.md");
  EXPECT_NE(md.find("\n### Small vibrations of double-pendulum"), std::string::npos) << md;
  EXPECT_NE(md.find("\n#### 4. The modes: $K v = \\omega^2 M v$\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\\begin{bmatrix}"), std::string::npos) << md;
  const std::string tex = read_text(dir / "out" / "lesson.tex");
  EXPECT_NE(tex.find("M_0[\\theta_1, \\theta_1] &= "), std::string::npos) << tex;
}

}  // namespace
}  // namespace linkage::test
