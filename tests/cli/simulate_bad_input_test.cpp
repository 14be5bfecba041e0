// Every bad input of `linkage simulate`: exit 2, one line naming the flag, the value
// and the valid range, nothing on stdout and no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

struct BadInput {
  std::vector<std::string> args;
  std::string expected;  // a part of the one-line message
};

class SimulateBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SimulateBadInput, IsExit2WithOneLineAndNoOutput) {
  TempDir dir;
  std::vector<std::string> args{"simulate"};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  args.insert(args.end(), {"--out", (dir / "run.csv").string()});
  const RunResult r = run_linkage(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(dir.entries().empty());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, SimulateBadInput,
    ::testing::Values(BadInput{{"--dt", "0"}, "--dt: 0 s is out of range; valid: 0 < dt <= duration (10 s)"},
                      BadInput{{"--dt", "-0.01"}, "--dt: -0.01 s is out of range"},
                      BadInput{{"--dt", "abc"}, "--dt: 'abc' is not a number"},
                      BadInput{{"--duration", "0"}, "--duration: 0 s is out of range; valid: 0 < duration <= 1e+06 s"},
                      BadInput{{"--duration", "-5"}, "--duration: -5 s is out of range"},
                      BadInput{{"--duration", "1e7"}, "--duration: 1e+07 s is out of range"},
                      BadInput{{"--duration", "inf"}, "--duration: 'inf' is not a finite number"},
                      BadInput{{"--every", "0"}, "--every: 0 s is out of range; valid: 0 < every <= duration (10 s)"},
                      BadInput{{"--every", "-1"}, "--every: -1 s is out of range"},
                      BadInput{{"--every", "11"}, "--every: 11 s is out of range"},
                      BadInput{{"--every", "1e-9"}, "the limit is 1e7 rows"},
                      BadInput{{"--rtol", "0"}, "--rtol: 0 is out of range; valid: 1e-14 <= rtol <= 1"},
                      BadInput{{"--rtol", "1e-16"}, "--rtol: 1e-16 is out of range"},
                      BadInput{{"--atol", "-1e-10"}, "--atol: -1e-10 is out of range; valid: 1e-20 <= atol <= 1"},
                      BadInput{{"--integrator", "rk45"},
                               "--integrator: 'rk45' is not an integrator (did you mean 'rk4'?); valid: euler, "
                               "symplectic-euler, rk4, dopri5, dop853, vern7, "
                               "gauss-legendre"},
                      BadInput{{"--stabilize", "yes"},
                               "--stabilize: 'yes' is not a stabilization; valid: none, baumgarte, projection"},
                      BadInput{{"--case", "4"}, "--case: '4' is not a case; valid: 1, 2, 3"},
                      BadInput{{"--columns", "t,x3"},
                               "--columns: 'x3' is not a column (did you mean 'x1'?); valid: all, t, x1"},
                      BadInput{{"--columns", "t,t"}, "--columns: column 't' is listed twice"},
                      BadInput{{"--columns", ""}, "--columns: the value is empty"},
                      BadInput{{"--format", "xml"}, "--format: 'xml' is not a format; valid: csv, json"},
                      BadInput{{"--baumgarte-alpha", "-1"}, "--baumgarte-alpha: -1 1/s is out of range"},
                      BadInput{{"--integrator", "rk4", "--dt", "1e-9"},
                               "--dt: 1e-09 s needs 1e+10 steps of rk4 for a duration of 10 s; the limit is 1e9 steps"},
                      BadInput{{"--m", "-1"}, "--m"}));

TEST(SimulateBadOutput, MissingFolderIsExit2) {
  TempDir dir;
  const RunResult r = run_linkage({"simulate", "--out", (dir / "missing" / "run.csv").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkage::test
