// `linkage solve` as a new user meets it: readable at 80 columns in every case and
// style, LaTeX that compiles (when pdflatex is installed), help that explains every
// option with its unit and default.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/program_path.hpp"
#include "report/text_layout.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(SolveOutput, TextFitsEightyColumnsForEveryCaseAndStyle) {
  const std::vector<std::vector<std::string>> inputs = {
      {},
      {"--m", "250", "--L", "1.5", "--w", "0.02", "--b", "1.5", "--theta1", "-2.5", "--theta2-dot", "-120.75"},
      {"--m", "0.001", "--g", "0", "--x1", "-12345.678", "--y1", "1e-9", "--x1-dot", "-0.000123"},
  };
  for (const auto& extra : inputs) {
    for (const char* which : {"1", "2", "3", "all"}) {
      for (const char* style : {"--ascii", "--unicode"}) {
        std::vector<std::string> args = {"solve", "--case", which, style};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::RunResult r = test::run_linkage(args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        std::size_t count = 0;
        std::istringstream out(r.out);
        for (std::string line; std::getline(out, line);) {
          EXPECT_LE(display_width(line), 80u) << "--case " << which << " " << style << ": " << line;
          ++count;
        }
        EXPECT_GT(count, 60u);
      }
    }
  }
}

TEST(SolveOutput, DigitsSetThePrecisionOfPrintedNumbers) {
  const test::RunResult three = test::run_linkage({"solve", "--case", "3", "--ascii", "--digits", "3"});
  ASSERT_EQ(three.exit_code, 0) << three.err;
  EXPECT_NE(three.out.find("y1''   -9.81 "), std::string::npos) << three.out;
  const test::RunResult twelve = test::run_linkage({"solve", "--case", "3", "--ascii", "--digits", "12"});
  EXPECT_NE(twelve.out.find("-9.80725296343 "), std::string::npos) << twelve.out;
}

// A table row "label value unit ...": the value after `label`.
double table_value(const std::string& text, const std::string& label, const std::string& unit) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first, value, u;
    if (words >> first >> value >> u && first == label && u == unit) return std::stod(value);
  }
  ADD_FAILURE() << "no row '" << label << " ... " << unit << "' in\n" << text;
  return 0;
}

TEST(SolveOutput, AnglesInDegreesInTheStateAndSolutionTables) {
  const test::RunResult rad = test::run_linkage({"solve", "--case", "3", "--ascii", "--digits", "9"});
  const test::RunResult deg =
      test::run_linkage({"solve", "--case", "3", "--ascii", "--digits", "9", "--angles", "deg"});
  ASSERT_EQ(rad.exit_code, 0) << rad.err;
  ASSERT_EQ(deg.exit_code, 0) << deg.err;
  const double per_rad = 180 / 3.14159265358979323846;
  // The state (theta1 = 0.1 rad, theta1_dot = 0.35 rad/s) and the solved accelerations.
  EXPECT_NEAR(table_value(deg.out, "th1", "deg"), 0.1 * per_rad, 1e-7);
  EXPECT_NEAR(table_value(deg.out, "th1'", "deg/s"), 0.35 * per_rad, 1e-7);
  const double a_rad = table_value(rad.out, "th2''", "rad/s^2");
  EXPECT_NE(a_rad, 0.0);
  EXPECT_NEAR(table_value(deg.out, "th2''", "deg/s^2"), a_rad * per_rad, 1e-7 * std::fabs(a_rad * per_rad));
  // Metres are untouched.
  EXPECT_EQ(table_value(deg.out, "x1", "m"), table_value(rad.out, "x1", "m"));
  const test::RunResult json = test::run_linkage({"solve", "--format", "json", "--angles", "deg"});
  EXPECT_EQ(json.exit_code, 2);
  EXPECT_NE(json.err.find("--angles: deg applies to the text format; json keeps radians"), std::string::npos)
      << json.err;
}

TEST(SolveOutput, HelpExplainsEveryOptionWithUnitAndDefault) {
  const test::RunResult r = test::run_linkage({"solve", "--help"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* text : {"--case", "(default all)", "--format", "text", "latex", "markdown", "json", "(default text)",
                           "--digits", "(default 6)", "--ascii", "--unicode", "--config", "flags override it"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
  const std::vector<std::pair<const char*, const char*>> flags = {{"--L", "m (default 0.3)"},
                                                                  {"--w", "m (default 0.1)"},
                                                                  {"--b", "m (default 0.04)"},
                                                                  {"--m", "kg (default 0.1)"},
                                                                  {"--g", "m/s^2 (default 9.81)"},
                                                                  {"--x1", "m (default 1)"},
                                                                  {"--y1", "m (default 2)"},
                                                                  {"--theta1", "rad (default 0.1)"},
                                                                  {"--theta2", "rad (default 0.2)"},
                                                                  {"--x1-dot", "m/s (default 0.15)"},
                                                                  {"--y1-dot", "m/s (default 0.25)"},
                                                                  {"--theta1-dot", "rad/s (default 0.35)"},
                                                                  {"--theta2-dot", "rad/s (default 0.45)"}};
  for (const auto& [flag, unit_and_default] : flags) {
    const auto at = r.out.find(std::string("  ") + flag + " ");
    ASSERT_NE(at, std::string::npos) << flag;
    const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
    EXPECT_NE(line.find(unit_and_default), std::string::npos) << line;
  }
}

// Finds `program` on PATH.

// `args`' LaTeX \input into a standard document compiles, with no line wider than the page.
void expect_latex_compiles(const std::vector<std::string>& args) {
  SCOPED_TRACE(args[0]);
  test::TempDir dir;
  const test::RunResult r = test::run_linkage(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  test::write_text(dir / "solution.tex", r.out);
  test::write_text(dir / "doc.tex",
                   "\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n\\input{solution}\n"
                   "\\end{document}\n");
  const std::string command =
      "cd '" + dir.path().string() + "' && pdflatex -interaction=nonstopmode -halt-on-error doc.tex >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << test::read_text(dir / "doc.log");
  EXPECT_TRUE(std::filesystem::exists(dir / "doc.pdf"));
  const std::string log = test::read_text(dir / "doc.log");
  EXPECT_EQ(log.find("Overfull \\hbox"), std::string::npos) << "a line is wider than the page";
}

TEST(SolveOutput, LatexCompilesInAStandardDocument) {
  if (!on_path("pdflatex")) GTEST_SKIP() << "pdflatex is not installed";
  expect_latex_compiles({"solve", "--format", "latex"});
  // `linkage modes` too: a loop's reduction and each body's motion, an unstable
  // equilibrium's growth rates, and the check of --verify.
  expect_latex_compiles({"modes", "--mechanism", "four-bar-spring", "--format", "latex"});
  expect_latex_compiles(
      {"modes", "--mechanism", "double-pendulum", "--set", "1.theta=1.4", "--set", "2.theta=1.7", "--format", "latex"});
  expect_latex_compiles({"modes", "--mechanism", "spring-pendulum", "--verify", "--format", "latex"});
}

}  // namespace
}  // namespace linkage
