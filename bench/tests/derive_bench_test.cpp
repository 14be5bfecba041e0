// `linkage bench derive --quick`: the report lists every shipped mechanism and both
// targets with a verdict (structure only; timings are the benchmark's to judge).
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(DeriveBench, QuickRunWritesEveryMechanismAndBothTargets) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "linkage-derive-bench-test";
  std::filesystem::remove_all(out);
  const test::RunResult r = test::run_linkage({"bench", "derive", "--quick", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string md = test::read_text(out / "derive.md");
  const std::string csv = test::read_text(out / "derive.csv");
  for (const char* name : {"two-blocks", "unequal-blocks", "double-pendulum", "triple-pendulum", "spring-pendulum",
                           "slider-crank", "four-bar"}) {
    EXPECT_NE(md.find(std::string("| ") + name + " |"), std::string::npos) << name;
    EXPECT_NE(csv.find(std::string("\n") + name + ","), std::string::npos) << name;
  }
  EXPECT_NE(md.find("wall time, general procedure / closed-form path"), std::string::npos) << md;
  EXPECT_NE(md.find("four-bar, all three cases derived"), std::string::npos) << md;
  EXPECT_NE(r.out.find("homework solve wall time"), std::string::npos) << r.out;
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace linkage
