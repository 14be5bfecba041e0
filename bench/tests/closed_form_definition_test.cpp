// The closed-form definitions (the fast path) keep the structure the solvers rely on;
// their values are held to the general procedure in the cases' tests.
#include <gtest/gtest.h>

#include "bench/closed_form/case1.hpp"
#include "bench/closed_form/case2.hpp"
#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/formulation.hpp"
#include "bench/closed_form/linear_solve.hpp"

namespace linkage {
namespace {

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
