// `linkage solve --form lagrange`: Case 3 in the board's form for every shipped mechanism
// in every format, its solution Case 3's (from the JSON), the same bits in every run, the
// double pendulum's coupling printed as a cos(θ₁ - θ₂) term; the default form unchanged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

nlohmann::json case3(const std::string& mechanism, const std::string& form) {
  const test::RunResult r =
      test::run_linkage({"solve", "--mechanism", mechanism, "--case", "3", "--form", form, "--format", "json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out)["cases"][0];
}

class SolveLagrange : public testing::TestWithParam<std::string> {};

TEST_P(SolveLagrange, EveryFormatRunsAndSolvesAsCase3) {
  for (const char* format : {"text", "latex", "markdown", "matlab", "python"}) {
    const test::RunResult r =
        test::run_linkage({"solve", "--mechanism", GetParam(), "--form", "lagrange", "--format", format});
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    EXPECT_NE(r.out.find("Lagrange's form"), std::string::npos) << format;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << format;
    EXPECT_TRUE(r.err.empty()) << r.err;
  }
  const nlohmann::json lagrange = case3(GetParam(), "lagrange");
  const nlohmann::json reduced = case3(GetParam(), "newton-euler");
  EXPECT_NE(lagrange["title"].get<std::string>().find("M(q) q'' = Q"), std::string::npos) << lagrange["title"];
  EXPECT_EQ(lagrange["unknowns"], reduced["unknowns"]);
  double scale = 1;
  for (const auto& [name, value] : reduced["solution"].items()) scale = std::max(scale, std::abs(value.get<double>()));
  // Round-off of two solves with condition numbers below 1e5.
  for (const char* part : {"solution", "recovered"})
    for (const auto& [name, value] : reduced[part].items())
      EXPECT_NEAR(lagrange[part][name].get<double>(), value.get<double>(), 1e-10 * scale) << part << " " << name;
  // The same bits in another run (GiNaC's term order changes from run to run).
  EXPECT_EQ(case3(GetParam(), "lagrange"), lagrange);
}

INSTANTIATE_TEST_SUITE_P(Shipped, SolveLagrange, testing::ValuesIn(shipped_mechanism_names()),
                         [](const testing::TestParamInfo<std::string>& p) { return test::test_name(p.param); });

TEST(SolveLagrangeForm, TheDoublePendulumReadsAsOnTheBoard) {
  const test::RunResult r =
      test::run_linkage({"solve", "--mechanism", "double-pendulum", "--case", "3", "--form", "lagrange", "--unicode"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("cos(θ₁ - θ₂)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sin(θ₁ - θ₂)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("sin θ₁ sin θ₂"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("cos θ₁ cos θ₂"), std::string::npos) << r.out;
}

TEST(SolveLagrangeForm, TheDefaultFormIsNewtonEuler) {
  const test::RunResult plain = test::run_linkage({"solve", "--mechanism", "four-bar", "--case", "3"});
  const test::RunResult named =
      test::run_linkage({"solve", "--mechanism", "four-bar", "--case", "3", "--form", "newton-euler"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out, named.out);
  EXPECT_EQ(plain.out.find("Lagrange"), std::string::npos);
}

}  // namespace
}  // namespace linkage
