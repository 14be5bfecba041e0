#include "core/angle_unit.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <utility>

#include "core/error.hpp"

namespace linkage {
namespace {

TEST(AngleUnit, DegreesScaleOnlyAngularUnits) {
  const double per_rad = 180 / std::numbers::pi;
  EXPECT_DOUBLE_EQ(angle_factor("rad", AngleUnit::deg), per_rad);
  EXPECT_DOUBLE_EQ(angle_factor("rad/s", AngleUnit::deg), per_rad);
  EXPECT_DOUBLE_EQ(angle_factor("rad/s^2", AngleUnit::deg), per_rad);
  EXPECT_EQ(angle_factor("rad", AngleUnit::rad), 1.0);
  for (const char* other : {"m", "m/s", "J", "N", "radius", "m, rad", ""})
    EXPECT_EQ(angle_factor(other, AngleUnit::deg), 1.0) << other;
  EXPECT_EQ(angle_unit_text("rad/s^2", AngleUnit::deg), "deg/s^2");
  EXPECT_EQ(angle_unit_text("rad", AngleUnit::deg), "deg");
  EXPECT_EQ(angle_unit_text("rad/s", AngleUnit::rad), "rad/s");
  EXPECT_EQ(angle_unit_text("m/s", AngleUnit::deg), "m/s");
  // Half a turn is 180 degrees.
  EXPECT_NEAR(std::numbers::pi * angle_factor("rad", AngleUnit::deg), 180.0, 1e-12);
}

TEST(AngleUnit, ParsesRadAndDegAndNamesTheFlagOtherwise) {
  EXPECT_EQ(parse_angle_unit("rad", "--angles"), AngleUnit::rad);
  EXPECT_EQ(parse_angle_unit("deg", "--angles"), AngleUnit::deg);
  try {
    (void)parse_angle_unit("degrees", "--angles");
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_STREQ(e.what(), "--angles: 'degrees' is not an angle unit; valid: rad, deg");
  }
  // A typo gets the nearer unit (a lesson's `angles = "degs"` reads through here too).
  for (const auto& [typo, message] :
       {std::pair{"degs", "angles: 'degs' is not an angle unit (did you mean 'deg'?); valid: rad, deg"},
        std::pair{"RAD", "angles: 'RAD' is not an angle unit (did you mean 'rad'?); valid: rad, deg"}}) {
    try {
      (void)parse_angle_unit(typo, "angles");
      ADD_FAILURE() << typo << " accepted";
    } catch (const Error& e) {
      EXPECT_STREQ(e.what(), message);
    }
  }
}

}  // namespace
}  // namespace linkage
