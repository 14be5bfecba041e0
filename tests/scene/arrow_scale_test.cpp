#include "scene/arrow_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace linkage {
namespace {

TEST(ArrowScale, LongestArrowWithinTwoThirdsAndOneOfTheLimit) {
  // Over many decades the largest arrow is never longer than asked, and rounding to a
  // round scale never shortens it below two thirds.
  for (double magnitude = 1e-7; magnitude < 1e4; magnitude *= 1.37) {
    const ArrowScale scale = choose_arrow_scale(magnitude, 0.08);
    ASSERT_TRUE(scale.drawable());
    const double length = magnitude * scale.metres_per_unit;
    EXPECT_LE(length, 0.08 * (1 + 1e-12)) << magnitude;
    EXPECT_GE(length, 0.08 / 1.5 * (1 - 1e-12)) << magnitude;
    EXPECT_NEAR(scale.metres_per_unit, 0.01 / scale.units_per_cm(), 1e-15 * scale.metres_per_unit);
  }
}

TEST(ArrowScale, ExactRoundValuesAreKept) {
  // 2 mN at most 1 cm long: exactly 1 cm = 2 mN, not the next step up.
  const ArrowScale scale = choose_arrow_scale(2e-3, 0.01);
  EXPECT_EQ(describe_arrow_scale(scale, "N"), "1 cm = 2 mN");
  EXPECT_DOUBLE_EQ(2e-3 * scale.metres_per_unit, 0.01);
}

TEST(ArrowScale, Descriptions) {
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(0.981, 0.0825), "N"), "1 cm = 150 mN");
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(2.0e-3, 0.0825), "N"), "1 cm = 250 µN");
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(0.05, 0.1), "m/s"), "1 cm = 5 mm/s");
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(120.0, 0.1), "m/s"), "1 cm = 15 m/s");
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(1.2, 0.1), "N"), "1 cm = 150 mN");
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(14.0, 0.1), "N"), "1 cm = 1.5 N");
}

TEST(ArrowScale, NothingToDrawForZeroOrNonFinite) {
  EXPECT_FALSE(choose_arrow_scale(0.0, 0.1).drawable());
  EXPECT_FALSE(choose_arrow_scale(std::nan(""), 0.1).drawable());
  EXPECT_EQ(describe_arrow_scale(choose_arrow_scale(0.0, 0.1), "N"), "0 N throughout");
}

TEST(RoundLength, GridSpacingsAreOneTwoFive) {
  EXPECT_EQ(round_length_at_least(0.07).mantissa, 1);
  EXPECT_EQ(round_length_at_least(0.07).exponent, -1);
  EXPECT_EQ(round_length_at_least(0.12).mantissa, 2);
  EXPECT_EQ(round_length_at_least(0.3).mantissa, 5);
  EXPECT_EQ(round_length_at_least(0.1).mantissa, 1);
  EXPECT_DOUBLE_EQ(round_length_at_least(0.1).metres(), 0.1);
  EXPECT_EQ(describe_length(5, -2), "5 cm");
  EXPECT_EQ(describe_length(2, -1), "20 cm");
  EXPECT_EQ(describe_length(1, 0), "1 m");
  EXPECT_EQ(describe_length(5, -3), "5 mm");
  EXPECT_EQ(describe_length(2, 2), "200 m");
  EXPECT_EQ(describe_length(1, 3), "1 km");
}

}  // namespace
}  // namespace linkage
