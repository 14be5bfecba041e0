#include "report/formula.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report/text_layout.hpp"

namespace linkage {
namespace {

using expr::Style;

std::string print(const Formula& f, Style style, Spelling spelling) { return strip_marks(f.print(style, spelling, 6)); }

TEST(Formula, PrintsEachStyleSymbolicallyAndSubstituted) {
  const Symbol a{"α", "a", "\\alpha", 2.0};
  const Symbol b{"β₁", "b1", "\\beta_1", 0.000123456789};
  const Symbol t{"θ", "th", "\\theta", -0.5, true};
  const Formula f = a * square(b) - cos(t) / Formula::integer(2);
  EXPECT_EQ(print(f, Style::unicode, Spelling::symbolic), "α β₁² - cos θ / 2");
  EXPECT_EQ(print(f, Style::ascii, Spelling::symbolic), "a b1^2 - cos(th) / 2");
  EXPECT_EQ(print(f, Style::latex, Spelling::symbolic), "\\alpha \\beta_1^2 - \\frac{\\cos \\theta}{2}");
  EXPECT_EQ(print(f, Style::unicode, Spelling::substituted), "2 × 0.000123457² - cos (-0.5) / 2");
  EXPECT_EQ(print(f, Style::ascii, Spelling::substituted), "2 * 0.000123457^2 - cos(-0.5) / 2");
  EXPECT_DOUBLE_EQ(f.eval(), 2.0 * 0.000123456789 * 0.000123456789 - std::cos(-0.5) / 2);
}

TEST(Formula, ParenthesesFollowPrecedence) {
  const Symbol x{"x", "x", "x", 1}, y{"y", "y", "y", 2}, z{"z", "z", "z", 3};
  EXPECT_EQ(print(x - (y - z), Style::ascii, Spelling::symbolic), "x - (y - z)");
  EXPECT_EQ(print(x - y * z, Style::ascii, Spelling::symbolic), "x - y z");
  EXPECT_EQ(print((x + y) * z, Style::ascii, Spelling::symbolic), "(x + y) z");
  EXPECT_EQ(print(square(x + y), Style::unicode, Spelling::symbolic), "(x + y)²");
  EXPECT_EQ(print(x / (y * z), Style::ascii, Spelling::symbolic), "x / (y z)");
  EXPECT_EQ(print(x * y / z, Style::ascii, Spelling::substituted), "1 * 2 / 3");
  EXPECT_DOUBLE_EQ((x - (y - z)).eval(), 2.0);
}

TEST(Formula, LatexBracesASquaredSuperscript) {
  const Symbol i{"I_zz^C", "I_zz^C", "I_{zz}^{C}", 1};
  EXPECT_EQ(print(square(i), Style::latex, Spelling::symbolic), "{I_{zz}^{C}}^2");
}

TEST(Formula, NumbersInEachStyle) {
  EXPECT_EQ(format_number(0.000833333333, Style::unicode, 6), "0.000833333");
  EXPECT_EQ(format_number(1.5e-18, Style::ascii, 2), "1.5e-18");
  EXPECT_EQ(format_number(1.5e-18, Style::latex, 2), "1.5 \\times 10^{-18}");
  EXPECT_EQ(format_number(1e-20, Style::latex, 3), "10^{-20}");
  EXPECT_EQ(format_number(-0.0, Style::ascii, 6), "0");
  EXPECT_EQ(format_number(0.30000000000000004, Style::ascii, 0), "0.30000000000000004");
  EXPECT_EQ(format_number(2.0, Style::ascii, 0), "2");
}

TEST(Formula, SumsCarryBreakMarks) {
  const Symbol x{"x", "x", "x", 1}, y{"y", "y", "y", 2};
  const std::string printed = (x + y).print(Style::ascii, Spelling::symbolic, 6);
  EXPECT_EQ(printed, std::string("x") + kBreakMark + " + y");
}

}  // namespace
}  // namespace linkage
