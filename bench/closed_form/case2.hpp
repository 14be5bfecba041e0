#pragma once
// Case 2: six equations in the generalized coordinates (x1, y1, th1, th2), pin force
// kept (spec sec. 4, corrected per docs/errata.md: coordinates {x1, y1, th1, th2}, eqs. 3.2
// and 4.2 once each, no y2'' in 6.2). Block 2's Newton equations (4.1), (5.1) give
// x2'' = -Fx/m and y2'' = -g - Fy/m, which are substituted into the constraints.
// Unknowns q = (x1'', y1'', th1'', th2'', Fx, Fy).
//   (1.2)  m x1''                                 - Fx         = 0
//   (2.2)  m y1''                                 - Fy         = -m g
//   (3.2)  I th1''          + D sin th1 Fx - D cos th1 Fy      = 0
//   (4.2)  I th2''          + D sin th2 Fx - D cos th2 Fy      = 0
//   (5.2)  x1'' - D sin th1 th1'' - D sin th2 th2'' + Fx/m     = D (th1'^2 cos th1 + th2'^2 cos th2)
//   (6.2)  y1'' + D cos th1 th1'' + D cos th2 th2'' + Fy/m     = D (th1'^2 sin th1 + th2'^2 sin th2) - g
// The 1/m in rows 5-6 makes the matrix's scaling depend on m (see `bench stress`).
#include <array>
#include <string_view>

#include "bench/closed_form/matrix_def.hpp"
#include "bench/closed_form/unknowns.hpp"

namespace linkage {

struct Case2 {
  static constexpr int id = 2;
  static constexpr int size = 6;
  static constexpr std::string_view title = "Case 2: six equations in generalized coordinates with the pin force";
  static constexpr std::array<Unknown, size> unknowns{Unknown::x1_ddot,     Unknown::y1_ddot, Unknown::theta1_ddot,
                                                      Unknown::theta2_ddot, Unknown::F_x,     Unknown::F_y};
  static constexpr std::array<std::string_view, size> equations{"1.2", "2.2", "3.2", "4.2", "5.2", "6.2"};

  static constexpr auto A = [] {
    using namespace expr;
    return matrix(row(m, zero, zero, zero, -one, zero), row(zero, m, zero, zero, zero, -one),
                  row(zero, zero, I, zero, D * sin1, -(D * cos1)), row(zero, zero, zero, I, D * sin2, -(D * cos2)),
                  row(one, zero, -(D * sin1), -(D * sin2), inv(m), zero),
                  row(zero, one, D * cos1, D * cos2, zero, inv(m)));
  }();
  static constexpr auto B = [] {
    using namespace expr;
    return column(zero, -(m * g), zero, zero, D * (w1sq * cos1 + w2sq * cos2), D * (w1sq * sin1 + w2sq * sin2) - g);
  }();

  static constexpr std::array<int, 4> pivot_rows{0, 1, 2, 3};
  static constexpr std::array<int, 4> pivot_cols{0, 1, 2, 3};
  static constexpr std::array<int, 2> border_rows{4, 5};
  static constexpr std::array<int, 2> border_cols{4, 5};
};

}  // namespace linkage
