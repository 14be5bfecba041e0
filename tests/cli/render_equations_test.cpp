// render --show equations draws the lines `linkage solve --case N` prints (the report's
// printer is their one source), for the homework and any mechanism, from the command
// line and a lesson's render step; --angles deg is taken by both.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "model/inputs.hpp"
#include "model/mechanism_toml.hpp"
#include "report/mechanism_text.hpp"
#include "support/test_support.hpp"
#include "symbolic/system.hpp"

namespace linkage::test {
namespace {
namespace fs = std::filesystem;

// The heading line and the lines under "Equations, one per row of A q = B:" up to the blank line.
struct Printed {
  bool has_heading = false;
  std::vector<std::string> lines;
};
Printed printed(const std::vector<std::string>& solve_args, const std::string& heading) {
  const RunResult r = run_linkage(solve_args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  Printed p;
  std::istringstream in(r.out);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line == heading) p.has_heading = true;
    if (inside && line.empty()) break;
    if (inside) p.lines.push_back(line);
    if (line == "  Equations, one per row of A q = B:") inside = true;
  }
  return p;
}

TEST(RenderEquations, AreTheLinesSolvePrintsForTheCase) {
  const sym::System homework(default_mechanism(Inputs{}));
  const std::vector<std::size_t> rows{8, 6, 4};
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE("Case " + std::to_string(n));
    const CaseEquations shown = case_equations(homework, static_cast<CaseId>(n));
    const Printed solve = printed({"solve", "--case", std::to_string(n), "--unicode"}, shown.heading);
    EXPECT_TRUE(solve.has_heading) << shown.heading;
    EXPECT_EQ(shown.lines, solve.lines);
    std::size_t labelled = 0;
    for (const std::string& line : shown.lines) labelled += line.find("(") == 4 ? 1 : 0;
    EXPECT_EQ(labelled, rows[static_cast<std::size_t>(n - 1)]);
  }
  const sym::System slider(load_mechanism("slider-crank"));
  const CaseEquations shown = case_equations(slider, CaseId::reduced);
  const Printed solve = printed({"solve", "--mechanism", "slider-crank", "--case", "3", "--unicode"}, shown.heading);
  EXPECT_TRUE(solve.has_heading) << shown.heading;
  EXPECT_EQ(shown.lines, solve.lines);
  EXPECT_GT(shown.lines.size(), 5U);  // five rows, some wrapped
}

TEST(RenderEquations, StillsOfTheHomeworkAndAMechanismWithAPanelInDegrees) {
  TempDir dir;
  const RunResult homework =
      run_linkage({"render", "--show", "equations", "--case", "1", "--quality", "low", "--panel", "theta1", "--angles",
                   "deg", "--caption", "Case 1", "--at", "1", "--out", (dir / "case1.png").string(), "--quiet"});
  EXPECT_EQ(homework.exit_code, 0) << homework.err;
  EXPECT_TRUE(fs::exists(dir / "case1.png"));
  const RunResult mechanism =
      run_linkage({"render", "--mechanism", "slider-crank", "--show", "equations", "--panel", "2.theta", "--angles",
                   "deg", "--out", (dir / "slider.png").string(), "--quiet"});
  EXPECT_EQ(mechanism.exit_code, 0) << mechanism.err;
  EXPECT_TRUE(fs::exists(dir / "slider.png"));
}

TEST(RenderEquations, BadUseIsOneLineAndNoFile) {
  TempDir dir;
  const std::string out = (dir / "x.png").string();
  struct Bad {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Bad> cases{
      {{"render", "--show", "equations", "--case", "1", "--size", "480x270", "--out", out},
       "linkage: error: --show: Case 1's equations (8 lines) do not fit a 480x270 frame at a legible size (9 px or "
       "more); use quality low (854x480) or a larger size\n"},
      {{"render", "--mechanism", "slider-crank", "--show", "equations,trails", "--out", out},
       "linkage: error: --show: 'trails' is not an element (did you mean 'trail'?)"},
      {{"render", "--angles", "grad", "--out", out},
       "linkage: error: --angles: 'grad' is not an angle unit (did you mean 'rad'?); valid: rad, deg\n"},
  };
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.args[2]);
    const RunResult r = run_linkage(bad.args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind(bad.message, 0), 0U) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line";
    EXPECT_FALSE(fs::exists(out));
  }
}

std::string render_lesson(const std::string& keys) {
  return "title = \"Equations\"\n[[step]]\nkind = \"render\"\nout = \"still.png\"\nat = 0.5\n" + keys + "\n";
}

TEST(RenderEquations, LessonStepsShowThemHomeworkAndMechanism) {
  TempDir dir;
  const std::vector<std::string> good{
      "show = [\"equations\"]\ncase = 2\nangles = \"deg\"\npanel = [\"theta1\"]",
      "mechanism = \"slider-crank\"\nshow = [\"equations\"]\nangles = \"deg\"",
  };
  for (std::size_t i = 0; i < good.size(); ++i) {
    const fs::path file = dir / ("good" + std::to_string(i) + ".toml");
    write_text(file, render_lesson(good[i]));
    const RunResult r = run_linkage({"lesson", file.string(), "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 0) << good[i] << "\n" << r.err;
    EXPECT_TRUE(fs::exists(dir / "out" / "still.png"));
    fs::remove_all(dir / "out");
  }
  const fs::path file = dir / "bad.toml";
  write_text(file, render_lesson("mechanism = \"slider-crank\"\nshow = [\"equations\", \"trails\"]"));
  const RunResult r = run_linkage({"lesson", file.string(), "--check"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":7:8: step 1 (render): show: 'trails' is not an element"), std::string::npos) << r.err;
  write_text(file, render_lesson("angles = \"grad\""));
  const RunResult angles = run_linkage({"lesson", file.string(), "--check"});
  EXPECT_EQ(angles.exit_code, 2);
  EXPECT_NE(angles.err.find("angles"), std::string::npos) << angles.err;
}

}  // namespace
}  // namespace linkage::test
