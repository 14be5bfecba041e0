#include "scene/arrow_scale.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "core/error.hpp"

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

// Beyond the prefixes (pico .. tera) the number is scientific, never a row of zeros
// (--arrow-scale joint=1e-300 once printed 300 of them in the legend).
TEST(ArrowScale, ExtremeScalesAndLengthsStayShort) {
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(1e-300), "N"), "1 cm = 1e-300 N");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(2.5e200), "N"), "1 cm = 2.5e200 N");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(2.5e-12), "N"), "1 cm = 2.5 pN");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(999e12), "N"), "1 cm = 999 TN");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(1e15), "N"), "1 cm = 1e15 N");
  EXPECT_EQ(describe_length(2, 307), "2e307 m");
  EXPECT_EQ(describe_length(5, -16), "5e-16 m");
}

TEST(ArrowScale, AGivenScaleIsKeptToThreeDigits) {
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(2.0), "N"), "1 cm = 2 N");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(0.0025), "N"), "1 cm = 2.5 mN");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(123.456), "N"), "1 cm = 123 N");
  EXPECT_EQ(describe_arrow_scale(arrow_scale_of(9.9996), "N"), "1 cm = 10 N");
  EXPECT_NEAR(arrow_scale_of(0.5).metres_per_unit, 0.02, 1e-15);  // 1 cm per 0.5 N: 2 cm per N
  EXPECT_FALSE(arrow_scale_of(0.0).drawable());
  EXPECT_FALSE(arrow_scale_of(-1.0).drawable());
}

TEST(ArrowScale, RequestsParseCommonAndKinds) {
  static constexpr std::array<std::string_view, 3> kinds{"pin", "gravity", "velocity"};
  const ArrowScaleRequest common = parse_arrow_scale_request("common", "--arrow-scale", kinds);
  EXPECT_TRUE(common.common);
  EXPECT_EQ(common.common_units_per_cm, 0);
  EXPECT_FALSE(common.is_default());
  const ArrowScaleRequest set = parse_arrow_scale_request("pin=0.002,gravity=5", "--arrow-scale", kinds);
  EXPECT_FALSE(set.common);
  EXPECT_DOUBLE_EQ(set.fixed_for("pin"), 0.002);
  EXPECT_DOUBLE_EQ(set.fixed_for("gravity"), 5);
  EXPECT_EQ(set.fixed_for("velocity"), 0);
  EXPECT_DOUBLE_EQ(parse_arrow_scale_request("common=2", "--arrow-scale", kinds).common_units_per_cm, 2);
  EXPECT_TRUE(ArrowScaleRequest{}.is_default());
  for (const char* bad : {"", "pin", "pin=", "pin=0", "pin=-1", "pin=2x", "joint=1", "common=nan", "pin=1,,"}) {
    SCOPED_TRACE(bad);
    try {
      (void)parse_arrow_scale_request(bad, "--arrow-scale", kinds);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      const std::string message = e.what();
      EXPECT_NE(message.find("--arrow-scale"), std::string::npos) << message;
      EXPECT_NE(message.find("pin, gravity, velocity"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace linkage
