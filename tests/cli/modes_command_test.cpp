// `linkage modes`: the JSON contract of issue 26 (equilibrium, coordinates, M, C, K, modes
// by increasing frequency, stable), the text's sections, an unstable equilibrium's growth
// rates, and bad input in one line (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "support/test_support.hpp"

namespace linkage {
namespace {

void expect_one_line_error(const test::RunResult& r, const std::vector<std::string>& pieces) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const std::string& piece : pieces) EXPECT_NE(r.err.find(piece), std::string::npos) << piece << "\n" << r.err;
}

nlohmann::json modes_json(const std::vector<std::string>& more) {
  std::vector<std::string> args{"modes", "--format", "json"};
  args.insert(args.end(), more.begin(), more.end());
  const test::RunResult r = test::run_linkage(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(ModesCommand, JsonFollowsTheContract) {
  const nlohmann::json j = modes_json({"--mechanism", "double-pendulum"});
  EXPECT_EQ(j["mechanism"], "double-pendulum");
  EXPECT_NEAR(j["equilibrium"]["1.theta"].get<double>(), -std::numbers::pi / 2, 1e-13);
  EXPECT_NEAR(j["equilibrium"]["2.theta"].get<double>(), -std::numbers::pi / 2, 1e-13);
  EXPECT_EQ(j["coordinates"], nlohmann::json({"1.theta", "2.theta"}));
  for (const char* key : {"M", "C", "K"}) {
    ASSERT_EQ(j[key].size(), 2U) << key;
    ASSERT_EQ(j[key][0].size(), 2U) << key;
  }
  EXPECT_TRUE(j["stable"].get<bool>());
  ASSERT_EQ(j["modes"].size(), 2U);
  double last = 0;
  for (const auto& mode : j["modes"]) {
    const double omega = mode["omega"].get<double>();
    EXPECT_GT(omega, last);  // increasing
    last = omega;
    EXPECT_NEAR(mode["frequency_hz"].get<double>() * 2 * std::numbers::pi / omega, 1, 1e-15);
    EXPECT_EQ(mode["damping_ratio"].get<double>(), 0);
    double largest = 0;
    for (const auto& [name, value] : mode["shape"].items()) largest = std::max(largest, std::fabs(value.get<double>()));
    EXPECT_EQ(largest, 1.0);
    // omega^2 M v = K v with the printed matrices, to their round-trip digits.
    for (std::size_t i = 0; i < 2; ++i) {
      double mv = 0, kv = 0;
      const std::array<std::string, 2> names{"1.theta", "2.theta"};
      for (std::size_t c = 0; c < 2; ++c) {
        mv += j["M"][i][c].get<double>() * mode["shape"][names[c]].get<double>();
        kv += j["K"][i][c].get<double>() * mode["shape"][names[c]].get<double>();
      }
      EXPECT_NEAR(omega * omega * mv, kv, 1e-12 * std::fabs(kv) + 1e-15);
    }
  }
}

TEST(ModesCommand, AnUprightPendulumIsUnstableWithGrowthRatesNotFrequencies) {
  const nlohmann::json j =
      modes_json({"--mechanism", "double-pendulum", "--set", "1.theta=1.4", "--set", "2.theta=1.7"});
  EXPECT_FALSE(j["stable"].get<bool>());
  for (const auto& mode : j["modes"]) {
    EXPECT_EQ(mode["kind"], "unstable");
    EXPECT_GT(mode["growth_rate"].get<double>(), 0);
    EXPECT_FALSE(mode.contains("omega"));
    EXPECT_FALSE(mode.contains("frequency_hz"));
  }
}

TEST(ModesCommand, TextShowsTheEquilibriumTheExpansionTheMatricesAndTheModes) {
  const test::RunResult r = test::run_linkage({"modes", "--mechanism", "four-bar", "--set", "2.theta=-1.5", "--ascii"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& piece : {std::string("1. The equilibrium\n"), std::string("2. The expansion\n"),
                                   std::string("3. The linearized equations M z'' + C z' + K z = 0\n"),
                                   std::string("4. The modes"), std::string("independent coordinates z = (2.theta)"),
                                   std::string("The equilibrium is stable"), std::string("oscillation")})
    EXPECT_NE(r.out.find(piece), std::string::npos) << piece << "\n" << r.out;
  for (const std::string& line : test::lines_of(r.out)) EXPECT_LE(line.size(), 80U) << line;
}

TEST(ModesCommand, VerifyComparesEachModeWithTheMotion) {
  const nlohmann::json j = modes_json({"--mechanism", "double-pendulum", "--verify"});
  ASSERT_EQ(j["verify"].size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& check = j["verify"][k];
    EXPECT_EQ(check["mode"], k + 1);
    EXPECT_EQ(check["predicted"], j["modes"][k]["omega"]);
    EXPECT_LE(check["relative_error"].get<double>(), 1e-5);
  }
  const test::RunResult r = test::run_linkage({"modes", "--mechanism", "double-pendulum", "--verify", "--ascii"});
  EXPECT_NE(r.out.find("5. The check: the full equations"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Every mode agrees with the motion to 1e-05."), std::string::npos) << r.out;
}

TEST(ModesCommand, BadInputIsOneLine) {
  expect_one_line_error(test::run_linkage({"modes"}), {"--mechanism", "double-pendulum"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "double-pendulum", "--format", "csv"}),
                        {"--format", "csv", "text, json"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "engine"}), {"engine.toml:", "moves with t"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "two-blocks"}), {"no equilibrium"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "double-pendulum", "--digits", "0"}),
                        {"--digits", "1 to 17"});
}

}  // namespace
}  // namespace linkage
