// Every bad input of `linkage solve` (issue 2, item 7), through the built binary: one
// line on stderr naming the value, where it came from and what is valid; exit code 2;
// nothing on stdout.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/program_path.hpp"
#include "core/run_program.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

struct BadInput {
  std::vector<std::string> args;
  std::vector<std::string> expected;  // substrings of the message
};

void expect_one_line_error(const test::RunResult& r, const BadInput& bad, int code = 2) {
  std::string command = "linkage solve";
  for (const auto& a : bad.args) command += " " + a;
  EXPECT_EQ(r.exit_code, code) << command << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << command << " printed output:\n" << r.out.substr(0, 200);
  ASSERT_FALSE(r.err.empty()) << command;
  EXPECT_EQ(r.err.rfind("linkage: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
  EXPECT_EQ(r.err.back(), '\n');
  for (const auto& text : bad.expected) EXPECT_NE(r.err.find(text), std::string::npos) << command << "\n" << r.err;
}

test::RunResult solve(std::vector<std::string> args) {
  args.insert(args.begin(), "solve");
  return test::run_linkage(args);
}

TEST(SolveBadInput, OutOfRangeParameters) {
  const std::vector<BadInput> cases = {
      {{"--m", "0"}, {"--m", "m = 0 kg", "must be > 0"}},
      {{"--m", "-1"}, {"--m", "m = -1 kg", "must be > 0"}},
      {{"--L", "0"}, {"--L", "L = 0 m", "must be > 0"}},
      {{"--L", "-0.3"}, {"--L", "L = -0.3 m", "must be > 0"}},
      {{"--w", "0"}, {"--w", "w = 0 m", "must be > 0"}},
      {{"--w", "-0.1"}, {"--w", "w = -0.1 m", "must be > 0"}},
      {{"--b", "-0.01"}, {"--b", "b = -0.01 m", "[0, L] = [0, 0.3] m"}},
      {{"--b", "0.31"}, {"--b", "b = 0.31 m", "[0, L] = [0, 0.3] m"}},
      {{"--L", "0.5", "--b", "0.6"}, {"--b", "b = 0.6 m", "[0, L] = [0, 0.5] m"}},
      // b is fine as given, L shrinks below it: the default b is named as such.
      {{"--L", "0.02"}, {"default", "b = 0.04 m", "[0, L] = [0, 0.02] m"}},
      {{"--g", "-9.81"}, {"--g", "g = -9.81 m/s^2", "must be >= 0"}},
  };
  for (const BadInput& bad : cases) expect_one_line_error(solve(bad.args), bad);
}

TEST(SolveBadInput, NonFiniteAndUnparsableNumbers) {
  const std::vector<BadInput> cases = {
      {{"--g", "inf"}, {"--g", "'inf'", "not a finite number"}},
      {{"--g", "-inf"}, {"--g", "'-inf'", "not a finite number"}},
      {{"--g", "nan"}, {"--g", "'nan'", "not a finite number"}},
      {{"--m", "NaN"}, {"--m", "'NaN'", "not a finite number"}},
      {{"--theta1", "abc"}, {"--theta1", "'abc'", "not a number (rad)"}},
      {{"--theta1", "1.5x"}, {"--theta1", "'1.5x'", "not a number"}},
      {{"--x1-dot", "0,15"}, {"--x1-dot", "'0,15'", "not a number (m/s)"}},
      {{"--theta2-dot", ""}, {"--theta2-dot", "the value is empty"}},
      {{"--x1", "1e400"}, {"--x1", "'1e400'"}},
      {{"--m"}, {"--m", "missing"}},
  };
  for (const BadInput& bad : cases) expect_one_line_error(solve(bad.args), bad);
}

TEST(SolveBadInput, UnknownCaseFormatDigitsOrOption) {
  const std::vector<BadInput> cases = {
      {{"--case", "4"}, {"--case", "'4'", "valid: 1, 2, 3, all"}},
      {{"--case", "one"}, {"--case", "'one'", "valid: 1, 2, 3, all"}},
      {{"--case", "0"}, {"--case", "'0'", "valid: 1, 2, 3, all"}},
      {{"--format", "pdf"}, {"--format", "'pdf'", "valid: text, latex, markdown, json"}},
      {{"--format", "JSON"}, {"--format", "'JSON'", "valid: text, latex, markdown, json"}},
      {{"--digits", "0"}, {"--digits", "'0'", "from 1 to 17"}},
      {{"--digits", "18"}, {"--digits", "'18'", "from 1 to 17"}},
      {{"--digits", "2.5"}, {"--digits", "'2.5'", "whole number"}},
      {{"--digits", "six"}, {"--digits", "'six'", "not a number"}},
      {{"--ascii", "--unicode"}, {"--ascii", "--unicode"}},
      {{"--thetta1", "0.3"}, {"--thetta1"}},
  };
  for (const BadInput& bad : cases) expect_one_line_error(solve(bad.args), bad);
}

TEST(SolveBadInput, ConfigFileErrorsNameFileLineColumnAndValidKeys) {
  test::TempDir dir;
  auto file = [&](const std::string& name, const std::string& text) {
    test::write_text(dir / name, text);
    return (dir / name).string();
  };
  const std::string valid_keys =
      "valid keys: L, w, b, m, g, x1, y1, theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot";
  const std::string misspelt = file("misspelt.toml", "L = 0.5\n  thetta1 = 0.3\n");
  const std::string unknown = file("unknown.toml", "m = 0.2\ncolour = 3\n");
  const std::string case_key = file("case.toml", "Theta1 = 0.3\n");
  const std::string nan = file("nan.toml", "g = nan\n");
  const std::string inf = file("inf.toml", "m = -inf\n");
  const std::string text = file("text.toml", "m = \"heavy\"\n");
  const std::string table = file("table.toml", "[inputs]\nm = 1\n");
  const std::string negative = file("negative.toml", "x1 = 3\nm = -1\n");
  const std::string syntax = file("syntax.toml", "m = 0.2\nL = = 3\n");
  const std::string pin = file("pin.toml", "b = 0.5\n");
  std::filesystem::create_directories(dir / "folder.toml");
  const std::vector<BadInput> cases = {
      {{"--config", misspelt},
       {misspelt + ":2:3: config: unknown key 'thetta1'", "did you mean 'theta1'?", valid_keys}},
      {{"--config", unknown}, {unknown + ":2:1: config: unknown key 'colour'", valid_keys}},
      {{"--config", case_key}, {case_key + ":1:1: config: unknown key 'Theta1'", "did you mean 'theta1'?", valid_keys}},
      {{"--config", table}, {table + ":1:2: config: unknown key 'inputs'", valid_keys}},
      {{"--config", nan}, {nan + ":1:5", "config: 'g' = nan is not a finite number"}},
      {{"--config", inf}, {inf + ":1:5", "config: 'm' = -inf is not a finite number"}},
      {{"--config", text}, {text + ":1:5", "config: 'm' must be a number in kg, got a string"}},
      {{"--config", negative}, {negative + ":2:5", "m = -1 kg", "must be > 0"}},
      {{"--config", syntax}, {syntax + ":2:"}},
      {{"--config", pin}, {pin + ":1:5", "b = 0.5 m", "[0, L] = [0, 0.3] m"}},
      {{"--config", (dir / "missing.toml").string()}, {"--config", "missing.toml", "does not exist"}},
      {{"--config", (dir / "folder.toml").string()}, {"--config", "folder.toml", "is a folder"}},
  };
  for (const BadInput& bad : cases) expect_one_line_error(solve(bad.args), bad);

  // Flags override the file: the bad mass in the file is replaced, so this runs.
  const test::RunResult fixed = solve({"--config", negative, "--m", "0.2", "--format", "json"});
  EXPECT_EQ(fixed.exit_code, 0) << fixed.err;
}

TEST(SolveBadInput, UnreadableConfigFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files whatever their permissions";
  test::TempDir dir;
  const auto path = dir / "secret.toml";
  test::write_text(path, "m = 1\n");
  std::filesystem::permissions(path, std::filesystem::perms::none);
  expect_one_line_error(solve({"--config", path.string()}), {{}, {"secret.toml", "cannot read"}});
}

// Permission denied is said as such (a file in a folder one may not enter once "did not
// exist"). Root reads everything, so as root the program runs as nobody (setpriv).
TEST(SolveBadInput, PermissionDeniedIsSaid) {
  std::vector<std::string> as_user;
  if (::geteuid() == 0) {
    if (!on_path("setpriv")) GTEST_SKIP() << "root reads files whatever their permissions, and setpriv is missing";
    as_user = {"setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"};
  }
  test::TempDir dir;
  std::filesystem::permissions(dir.path(), std::filesystem::perms::all);  // others may enter
  test::write_text(dir / "secret.toml", "m = 1\n");
  std::filesystem::permissions(dir / "secret.toml", std::filesystem::perms::none);
  std::filesystem::create_directory(dir / "locked");
  test::write_text(dir / "locked" / "c.toml", "m = 1\n");
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_all);
  for (const auto& [file, why] :
       {std::pair<std::string, std::string>{"secret.toml", "(the file is not readable by you)"},
        {"locked/c.toml", "(a folder on its path may not be entered)"}}) {
    ProgramRun run;
    run.argv = as_user;
    for (const std::string& a :
         {test::linkage_binary(), std::string("solve"), std::string("--config"), (dir / file).string()})
      run.argv.push_back(a);
    run.capture_output = true;
    const ProgramResult r = run_program(run);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output,
              "linkage: error: --config: cannot read '" + (dir / file).string() + "': permission denied " + why + "\n");
  }
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::all);
}

TEST(SolveBadInput, OverflowIsABadInputAndASingularMatrixIsNamed) {
  expect_one_line_error(solve({"--m", "1e300", "--g", "1e10"}),
                        {{}, {"overflows double precision", "m = 1e+300 (--m)"}});
  expect_one_line_error(solve({"--theta1-dot", "1e200"}), {{}, {"overflows", "1.theta_dot = 1e+200 (--theta1-dot)"}});
  // A mass so small the matrices are singular to working precision: bad input (exit 2),
  // one line naming the case, the condition number and the likely cause, no NaN.
  expect_one_line_error(solve({"--m", "1e-300"}),
                        {{}, {"Case 1 matrix is singular", "condition number", "likely causes: m = 1e-300 (--m)"}});
}

}  // namespace
}  // namespace linkage
