#include "report/notation.hpp"

#include <gtest/gtest.h>

namespace linkage {
namespace {

TEST(Notation, UnitsNumbersAndLabels) {
  EXPECT_EQ(unit_text("kg m^2", Style::unicode), "kg m²");
  EXPECT_EQ(unit_text("kg m^2", Style::ascii), "kg m^2");
  EXPECT_EQ(unit_text("kg m^2/s", Style::latex), "\\mathrm{kg\\,m^2/s}");
  EXPECT_EQ(format_number(0.000833333333, Style::ascii, 6), "0.000833333");
  EXPECT_EQ(format_number(-2.5e-7, Style::latex, 3), "-2.5 \\times 10^{-7}");
  EXPECT_EQ(format_number(1e-20, Style::latex, 3), "10^{-20}");
  EXPECT_EQ(format_number(-0.0, Style::unicode, 0), "0");
  EXPECT_EQ(format_number(0.1, Style::unicode, 0), "0.1");
  EXPECT_EQ(parenthesized("4.3"), "(4.3)");
}

}  // namespace
}  // namespace linkage
