#include "report/notation.hpp"

#include <gtest/gtest.h>

#include "formulations/formulation.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

using expr::Style;

std::string equation(int id, std::size_t row, Style style) {
  const SymbolicSystem s = symbolic_system(id, style);
  const CaseSolution c = solve_case(id, Params{}, State{});
  const EquationSides eq = equation_sides(s.A[row], s.B[row], c.unknowns, style);
  return strip_marks(eq.lhs) + " = " + eq.rhs;
}

TEST(Notation, EquationsSkipZerosAndKeepSigns) {
  EXPECT_EQ(equation(1, 0, Style::unicode), "m ẍ₁ - Fx = 0");
  EXPECT_EQ(equation(1, 2, Style::unicode), "I θ̈₁ + D sin θ₁ Fx - D cos θ₁ Fy = 0");
  EXPECT_EQ(equation(1, 6, Style::ascii),
            "x1'' - D sin(th1) th1'' - x2'' - D sin(th2) th2'' = D (th1'^2 cos(th1) + th2'^2 cos(th2))");
  EXPECT_EQ(equation(3, 0, Style::ascii), "m D sin(th1) x1'' - m D cos(th1) y1'' + I th1'' = m g D cos(th1)");
  EXPECT_EQ(equation(3, 3, Style::ascii),
            "2 y1'' + D cos(th1) th1'' + D cos(th2) th2'' = D (th1'^2 sin(th1) + th2'^2 sin(th2)) - 2 g");
}

TEST(Notation, ReciprocalCoefficientsReadAsDivision) {
  // docs/errata.md: (6.2) has no y2'' term and ends with - g; Fy enters as Fy/m.
  EXPECT_EQ(equation(2, 5, Style::ascii),
            "y1'' + D cos(th1) th1'' + D cos(th2) th2'' + Fy/m = D (th1'^2 sin(th1) + th2'^2 sin(th2)) - g");
  EXPECT_NE(equation(2, 4, Style::latex).find("\\frac{F_x}{m}"), std::string::npos);
}

TEST(Notation, SumCoefficientsGetParentheses) {
  const EquationSides eq =
      equation_sides({"a + b", "-(c - d)", "0"}, "0", {Unknown::x1_ddot, Unknown::F_x, Unknown::F_y}, Style::ascii);
  EXPECT_EQ(strip_marks(eq.lhs), "(a + b) x1'' - (c - d) Fx");
  EXPECT_EQ(strip_marks(equation_sides({"0", "0"}, "g", {Unknown::F_x, Unknown::F_y}, Style::ascii).lhs), "0");
}

TEST(Notation, UnitsAndInputSymbols) {
  EXPECT_EQ(unit_text("kg m^2", Style::unicode), "kg m²");
  EXPECT_EQ(unit_text("kg m^2", Style::ascii), "kg m^2");
  EXPECT_EQ(unit_text("kg m^2/s", Style::latex), "\\mathrm{kg\\,m^2/s}");
  const Inputs inputs;
  const Symbol theta1_dot = input_symbol(*find_input_key("theta1_dot"), inputs);
  EXPECT_EQ(theta1_dot.unicode, "θ̇₁");
  EXPECT_EQ(theta1_dot.ascii, "th1'");
  EXPECT_EQ(theta1_dot.latex, "\\dot{\\theta}_1");
  EXPECT_DOUBLE_EQ(theta1_dot.value, 0.35);
  EXPECT_TRUE(theta1_dot.exact);
  EXPECT_EQ(unknown_name(Unknown::theta2_ddot, Style::ascii), "th2''");
  EXPECT_EQ(parenthesized("4.3"), "(4.3)");
}

}  // namespace
}  // namespace linkage
