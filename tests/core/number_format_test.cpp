#include "core/number_format.hpp"

#include <gtest/gtest.h>

#include <string>

namespace linkage {
namespace {

TEST(NumberFormat, RoundTripIsShortestAndExact) {
  EXPECT_EQ(format_roundtrip(0.1), "0.1");
  EXPECT_EQ(format_roundtrip(-9.807252963427482), "-9.807252963427482");
  for (double v : {1.0 / 3.0, 2.0433333333333e-3, 1e-300, -7.25e21}) EXPECT_EQ(std::stod(format_roundtrip(v)), v);
}

TEST(NumberFormat, SignificantDigits) {
  EXPECT_EQ(format_significant(0.012919401675492492, 6), "0.0129194");
  EXPECT_EQ(format_significant(-9.807252963427482, 6), "-9.80725");
  EXPECT_EQ(format_significant(0.1, 6), "0.1");
  EXPECT_EQ(format_significant(0.0, 6), "0");
  EXPECT_EQ(format_significant(2.5e-7, 3), "2.5e-07");
  EXPECT_EQ(format_significant(123456789.0, 3), "1.23e+08");
}

}  // namespace
}  // namespace linkage
