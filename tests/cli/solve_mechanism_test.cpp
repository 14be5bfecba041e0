// `linkage solve --mechanism` for every shipped mechanism: every format runs, the cases
// agree to 1e-12 relative (from the JSON), the text fits 80 columns where it can, and
// --set changes what it names.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "report/text_layout.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

const std::vector<std::string> kShipped = {"two-blocks",      "unequal-blocks", "double-pendulum", "triple-pendulum",
                                           "spring-pendulum", "slider-crank",   "four-bar"};

class SolveMechanism : public testing::TestWithParam<std::string> {};

TEST_P(SolveMechanism, EveryFormatRunsAndTheCasesAgree) {
  for (const char* format : {"text", "latex", "markdown", "matlab", "python"}) {
    const test::RunResult r = test::run_linkage({"solve", "--mechanism", GetParam(), "--format", format});
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    EXPECT_GT(r.out.size(), 1000u) << format;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << format;
    EXPECT_TRUE(r.err.empty()) << r.err;
  }
  const test::RunResult r = test::run_linkage({"solve", "--mechanism", GetParam(), "--format", "json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["cases"].size(), 3u);
  double scale = 0;
  for (const auto& [name, value] : doc["cases"][0]["solution"].items())
    scale = std::max(scale, std::abs(value.get<double>()));
  for (const auto& [name, difference] : doc["agreement"].items())
    EXPECT_LE(difference.get<double>(), 1e-12 * scale) << GetParam() << " " << name;
  // Every body and joint is reported in every case.
  for (const auto& c : doc["cases"]) {
    EXPECT_FALSE(c["bodies"].empty());
    for (const auto& [name, body] : c["bodies"].items()) EXPECT_EQ(body["acceleration"].size(), 2u) << name;
  }
}

// The same inputs give the same bits in every process, although GiNaC orders terms by
// hash values that change with the addresses of each run (the evaluator and the numbers
// walk them in an order of their own).
TEST_P(SolveMechanism, EveryRunPrintsTheSameBits) {
  const test::RunResult first = test::run_linkage({"solve", "--mechanism", GetParam(), "--format", "json"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  for (int run = 0; run < 4; ++run)
    EXPECT_TRUE(test::run_linkage({"solve", "--mechanism", GetParam(), "--format", "json"}).out == first.out)
        << GetParam() << " run " << run + 2;
}

INSTANTIATE_TEST_SUITE_P(Shipped, SolveMechanism, testing::ValuesIn(kShipped),
                         [](const testing::TestParamInfo<std::string>& p) { return test::test_name(p.param); });

TEST(SolveMechanismSet, ChangesAParameterAndACoordinate) {
  const auto base = nlohmann::json::parse(
      test::run_linkage({"solve", "--mechanism", "double-pendulum", "--format", "json", "--case", "3"}).out);
  const test::RunResult r = test::run_linkage({"solve", "--mechanism", "double-pendulum", "--format", "json", "--case",
                                               "3", "--set", "g=0", "--set", "1.theta=0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto changed = nlohmann::json::parse(r.out);
  EXPECT_EQ(changed["parameters"]["g"].get<double>(), 0.0);
  EXPECT_EQ(changed["state"]["1.theta"].get<double>(), 0.0);
  EXPECT_NE(changed["cases"][0]["solution"].dump(), base["cases"][0]["solution"].dump());
}

TEST(SolveMechanismSet, BadSettingsAreOneLineErrors) {
  const test::RunResult unknown = test::run_linkage({"solve", "--mechanism", "four-bar", "--set", "nope=1"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("nope"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
  const test::RunResult malformed = test::run_linkage({"solve", "--set", "L"});
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_NE(malformed.err.find("NAME=VALUE"), std::string::npos) << malformed.err;
  const test::RunResult mixed = test::run_linkage({"solve", "--mechanism", "four-bar", "--L", "0.3"});
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("--set L=VALUE"), std::string::npos) << mixed.err;
  const test::RunResult missing = test::run_linkage({"solve", "--mechanism", "no-such-thing"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("four-bar"), std::string::npos) << missing.err;
}

TEST(SolveMechanismSet, AChangePointIsRefusedWithoutNumbers) {
  // A parallelogram four-bar with every link in line: the loop's rates are not determined.
  const test::RunResult r =
      test::run_linkage({"solve", "--mechanism", "four-bar", "--set", "a=0.2", "--set", "b=0.3", "--set", "c=0.2",
                         "--set", "d=0.3", "--set", "2.theta=0", "--set", "3.theta=0", "--set", "4.theta=0"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("change point"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("four-bar.toml:"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace
}  // namespace linkage
