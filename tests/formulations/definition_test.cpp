// The printed definitions say what docs/errata.md says, not what the spec's typos say.
#include <gtest/gtest.h>

#include "formulations/case1.hpp"
#include "formulations/case2.hpp"
#include "formulations/case3.hpp"
#include "formulations/formulation.hpp"
#include "formulations/linear_solve.hpp"

namespace linkage {
namespace {

using Row = std::vector<std::string>;

TEST(Definition, Case1RowsFiveAndSixAreTheCorrectedOnes) {
  const SymbolicSystem s = symbolic_system(1, expr::Style::ascii);
  ASSERT_EQ(s.A.size(), 8u);
  EXPECT_EQ(s.A[4], (Row{"0", "0", "0", "0", "m", "0", "0", "1"}));
  EXPECT_EQ(s.A[5], (Row{"0", "0", "0", "0", "0", "I", "D sin(th2)", "-D cos(th2)"}));
  EXPECT_EQ(s.A[2], (Row{"0", "0", "I", "0", "0", "0", "D sin(th1)", "-D cos(th1)"}));
  EXPECT_EQ(s.B[6], "D (th1'^2 cos(th1) + th2'^2 cos(th2))");
}

TEST(Definition, Case2RowSixHasNoY2TermAndEndsWithMinusG) {
  const SymbolicSystem s = symbolic_system(2, expr::Style::ascii);
  ASSERT_EQ(s.A.size(), 6u);
  EXPECT_EQ(s.A[5], (Row{"0", "1", "D cos(th1)", "D cos(th2)", "0", "1/m"}));
  EXPECT_EQ(s.B[5], "D (th1'^2 sin(th1) + th2'^2 sin(th2)) - g");
}

TEST(Definition, Case3PrintsInEveryStyle) {
  EXPECT_EQ(symbolic_system(3, expr::Style::unicode).A[0][1], "-m D cos θ₁");
  EXPECT_EQ(symbolic_system(3, expr::Style::latex).A[0][0], "m D \\sin\\theta_1");
  EXPECT_EQ(symbolic_system(3, expr::Style::latex).B[3],
            "D \\left(\\dot{\\theta}_1^2 \\sin\\theta_1 + \\dot{\\theta}_2^2 \\sin\\theta_2\\right) - 2 g");
  EXPECT_EQ(symbolic_system(2, expr::Style::latex).A[4][4], "\\frac{1}{m}");
  EXPECT_EQ(symbolic_system(3, expr::Style::ascii).B[0], "m g D cos(th1)");
}

TEST(Definition, StructuralZerosFollowTheDefinition) {
  using A3 = decltype(Case3::A);
  static_assert(A3::structural_zero(0, 3) && !A3::structural_zero(0, 2));
  static_assert(block_layout_holds<Case1>() && block_layout_holds<Case2>() && block_layout_holds<Case3>());
  // Evaluated structural zeros are exactly zero at any state.
  const expr::Env env = make_env(Params{}, 0.7, -1.3, 2.0, 3.0);
  const auto system = assemble<Case1>(env);
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c)
      if (decltype(Case1::A)::structural_zero(r, c)) {
        EXPECT_EQ(system.A(r, c), 0.0);
      }
}

TEST(Definition, EquationLabelsAndUnknownOrder) {
  EXPECT_EQ(Case1::equations.front(), "1.1");
  EXPECT_EQ(Case1::equations.back(), "8.1");
  EXPECT_EQ(Case2::equations.back(), "6.2");
  EXPECT_EQ(Case3::equations.back(), "4.3");
  // x1'', y1'', th1'', x2'', y2'', th2'', Fx, Fy: the order of the equations (docs/errata.md).
  EXPECT_EQ(Case1::unknowns[1], Unknown::y1_ddot);
  EXPECT_EQ(Case1::unknowns[3], Unknown::x2_ddot);
  EXPECT_EQ(Case2::unknowns[1], Unknown::y1_ddot);
}

}  // namespace
}  // namespace linkage
