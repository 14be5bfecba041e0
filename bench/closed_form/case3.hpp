#pragma once
// Case 3: four equations in the generalized coordinates, pin force eliminated (spec
// sec. 5). Substituting Fx = m x1'' and Fy = m (y1'' + g) from (1.2), (2.2) into the
// rest. Unknowns q = (x1'', y1'', th1'', th2''); an ODE, no algebraic unknowns.
//   (1.3)  m D sin th1 x1'' - m D cos th1 y1'' + I th1''           = m g D cos th1
//   (2.3)  m D sin th2 x1'' - m D cos th2 y1'' + I th2''           = m g D cos th2
//   (3.3)  2 x1'' - D sin th1 th1'' - D sin th2 th2''              = D (th1'^2 cos th1 + th2'^2 cos th2)
//   (4.3)  2 y1'' + D cos th1 th1'' + D cos th2 th2''              = D (th1'^2 sin th1 + th2'^2 sin th2) - 2 g
// Solved by pivoting on the 2s of rows 3.3 and 4.3: the Schur complement for
// (th1'', th2'') is I + (m D^2 / 2) [[1, cos(th1 - th2)], [cos(th1 - th2), 1]],
// symmetric positive definite for every state, so no pivoting is ever needed.
#include <array>
#include <string_view>

#include "bench/closed_form/matrix_def.hpp"
#include "bench/closed_form/unknowns.hpp"

namespace linkage {

struct Case3 {
  static constexpr int id = 3;
  static constexpr int size = 4;
  static constexpr std::string_view title = "Case 3: four equations in generalized coordinates, no pin force";
  static constexpr std::array<Unknown, size> unknowns{Unknown::x1_ddot, Unknown::y1_ddot, Unknown::theta1_ddot,
                                                      Unknown::theta2_ddot};
  static constexpr std::array<std::string_view, size> equations{"1.3", "2.3", "3.3", "4.3"};

  static constexpr auto A = [] {
    using namespace expr;
    return matrix(row(m * D * sin1, -(m * D * cos1), I, zero), row(m * D * sin2, -(m * D * cos2), zero, I),
                  row(two, zero, -(D * sin1), -(D * sin2)), row(zero, two, D * cos1, D * cos2));
  }();
  static constexpr auto B = [] {
    using namespace expr;
    return column(m * g * D * cos1, m * g * D * cos2, D * (w1sq * cos1 + w2sq * cos2),
                  D * (w1sq * sin1 + w2sq * sin2) - two * g);
  }();

  static constexpr std::array<int, 2> pivot_rows{2, 3};
  static constexpr std::array<int, 2> pivot_cols{0, 1};
  static constexpr std::array<int, 2> border_rows{0, 1};
  static constexpr std::array<int, 2> border_cols{2, 3};
};

}  // namespace linkage
