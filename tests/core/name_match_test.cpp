#include "core/name_match.hpp"

#include <gtest/gtest.h>

namespace linkage {
namespace {

TEST(NameMatch, TypoDistanceCountsEditsIgnoringCaseAndSwapsAsOne) {
  EXPECT_EQ(typo_distance("follow", "follow"), 0U);
  EXPECT_EQ(typo_distance("RAD", "rad"), 0U);
  EXPECT_EQ(typo_distance("folow", "follow"), 1U);   // a letter left out
  EXPECT_EQ(typo_distance("lenght", "length"), 1U);  // neighbours swapped
  EXPECT_EQ(typo_distance("hgh", "high"), 1U);
  EXPECT_EQ(typo_distance("", "fit"), 3U);
}

TEST(NameMatch, SuggestsOnlyWhatIsCloseEnoughToBeATypo) {
  const std::vector<std::string> cameras{"follow", "fixed", "fit"};
  EXPECT_EQ(did_you_mean("folow", cameras), " (did you mean 'follow'?)");
  EXPECT_EQ(did_you_mean("fixd", cameras), " (did you mean 'fixed'?)");
  EXPECT_EQ(did_you_mean("orbit", cameras), "");  // 4 edits from "fit": no typo
  EXPECT_EQ(did_you_mean("2", {"1"}), "");        // every letter differs
  EXPECT_EQ(did_you_mean("degs", {"rad", "deg"}), " (did you mean 'deg'?)");
  EXPECT_EQ(closest_name("x", {}), std::nullopt);
  EXPECT_EQ(join_names({"a", "b"}), "a, b");
  EXPECT_EQ(join_names({}, "(none)"), "(none)");
}

}  // namespace
}  // namespace linkage
