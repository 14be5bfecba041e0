// `linkage bench derive --quick`: the report lists every shipped mechanism and both
// targets with a verdict (structure only; timings are the benchmark's to judge); the
// solve ratio is measured against --baseline, here this very binary.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(DeriveBench, QuickRunWritesEveryMechanismAndBothTargets) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "linkage-derive-bench-test";
  std::filesystem::remove_all(out);
  const test::RunResult r =
      test::run_linkage({"bench", "derive", "--quick", "--out", out.string(), "--baseline", LINKAGE_BINARY});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string md = test::read_text(out / "derive.md");
  const std::string csv = test::read_text(out / "derive.csv");
  for (const char* name : {"two-blocks", "unequal-blocks", "double-pendulum", "triple-pendulum", "spring-pendulum",
                           "slider-crank", "four-bar"}) {
    EXPECT_NE(md.find(std::string("| ") + name + " |"), std::string::npos) << name;
    EXPECT_NE(csv.find(std::string("\n") + name + ","), std::string::npos) << name;
  }
  EXPECT_NE(md.find("wall time, this build / baseline | "), std::string::npos) << md;
  EXPECT_EQ(md.find("not measured"), std::string::npos) << md;
  EXPECT_NE(md.find("four-bar, all three cases derived"), std::string::npos) << md;
  EXPECT_NE(r.out.find("homework solve wall time"), std::string::npos) << r.out;
  std::filesystem::remove_all(out);
}

TEST(DeriveBench, WithoutABaselineTheRatioIsNotMeasured) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "linkage-derive-bench-test-nobase";
  std::filesystem::remove_all(out);
  const test::RunResult r = test::run_linkage({"bench", "derive", "--quick", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("not measured (no --baseline)"), std::string::npos) << r.out;
  const test::RunResult bad = test::run_linkage({"bench", "derive", "--quick", "--baseline", "/no/such/linkage"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--baseline"), std::string::npos) << bad.err;
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace linkage
