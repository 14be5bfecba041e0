// --only ranges.
#include "cli/step_range.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace linkage::cli {
namespace {

std::vector<bool> only(const std::string& text, std::size_t count = 6) { return parse_step_range(text, count); }

TEST(StepRange, ParsesSinglesRangesAndOpenEnds) {
  EXPECT_EQ(only("3"), (std::vector<bool>{false, false, true, false, false, false}));
  EXPECT_EQ(only("2-4"), (std::vector<bool>{false, true, true, true, false, false}));
  EXPECT_EQ(only("5-"), (std::vector<bool>{false, false, false, false, true, true}));
  EXPECT_EQ(only("-2"), (std::vector<bool>{true, true, false, false, false, false}));
  EXPECT_EQ(only("1,4-5"), (std::vector<bool>{true, false, false, true, true, false}));
}

TEST(StepRange, RejectsBadRanges) {
  for (const char* bad : {"0", "7", "3-2", "a", "1,,2", "", "2-x", "1-7"}) {
    SCOPED_TRACE(bad);
    try {
      (void)only(bad);
      ADD_FAILURE();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      EXPECT_EQ(e.setting(), "only") << e.what();  // phrased as --only by the CLI
    }
  }
}

}  // namespace
}  // namespace linkage::cli
