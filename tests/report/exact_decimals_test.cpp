// Decimals of a mechanism's expressions as exact fractions (report/exact_decimals.hpp).
#include "report/exact_decimals.hpp"

#include <gtest/gtest.h>

#include "support/mechanisms_in_code.hpp"

namespace linkage {
namespace {

TEST(ExactDecimals, DecimalsBecomeFractions) {
  EXPECT_EQ(exact_decimal_text("L/2 - 0.04"), "L/2 - (4/100)");
  EXPECT_EQ(exact_decimal_text("1.5e3*k"), "1500*k");
  EXPECT_EQ(exact_decimal_text("3E+2"), "300");
  EXPECT_EQ(exact_decimal_text("1e-3 + .5"), "(1/1000) + (5/10)");
  EXPECT_EQ(exact_decimal_text("2.50"), "(250/100)");
  EXPECT_EQ(exact_decimal_text("0.0"), "(0/10)");
}

TEST(ExactDecimals, NamesIntegersAndOddTextStay) {
  EXPECT_EQ(exact_decimal_text("tau0*exp(-t/T) + L1^2 - 12"), "tau0*exp(-t/T) + L1^2 - 12");
  EXPECT_EQ(exact_decimal_text("x_2e3 + 2e1"), "x_2e3 + 20");
  EXPECT_EQ(exact_decimal_text("1e"), "1e");                // not a number GiNaC reads either
  EXPECT_EQ(exact_decimal_text("1e1234567"), "1e1234567");  // an exponent no double has
  EXPECT_EQ(exact_decimal_text("2.5e-40*k"), "2.5e-40*k");  // more zeros than a file needs
}

TEST(ExactDecimals, EveryQuantityOfTheMechanism) {
  const Mechanism m = with_exact_decimals(built::cart_pendulum());
  EXPECT_EQ(m.bodies[0].length->text, "(3/10)");
  EXPECT_EQ(m.bodies[0].points[1].at.x.text, "(5/100)");
  EXPECT_EQ(m.ground_points[1].at.y.text, "-(25/100)");
  EXPECT_EQ(m.springs[0].rest_length.text, "(2/10)");
  EXPECT_EQ(m.forces[0].value.x.text, "3*cos(t)");
  EXPECT_EQ(m.bodies[1].mass.text, "m");
}

}  // namespace
}  // namespace linkage
