#pragma once
// Case 1: eight DAEs in maximal coordinates, pin force kept (spec sec. 3, corrected
// per docs/errata.md: inertia in both moment balances, rows 5 and 6 of the matrix, and the
// unknown order). Unknowns q = (x1'', y1'', th1'', x2'', y2'', th2'', Fx, Fy).
//   (1.1)  m x1''                              - Fx          = 0
//   (2.1)  m y1''                              - Fy          = -m g
//   (3.1)  I th1''       + D sin th1 Fx - D cos th1 Fy       = 0
//   (4.1)  m x2''                              + Fx          = 0
//   (5.1)  m y2''                              + Fy          = -m g
//   (6.1)  I th2''       + D sin th2 Fx - D cos th2 Fy       = 0
//   (7.1)  x1'' - D sin th1 th1'' - x2'' - D sin th2 th2''    = D (th1'^2 cos th1 + th2'^2 cos th2)
//   (8.1)  y1'' + D cos th1 th1'' - y2'' + D cos th2 th2''    = D (th1'^2 sin th1 + th2'^2 sin th2)
// with I = I_zz^C and D = L/2 - b. Rows 1-6 are Newton-Euler for each block, rows 7-8
// the pin constraint differentiated twice. The mass block is diagonal, so the solve is
// a 2x2 Schur complement for (Fx, Fy).
#include <array>
#include <string_view>

#include "bench/closed_form/matrix_def.hpp"
#include "bench/closed_form/unknowns.hpp"

namespace linkage {

struct Case1 {
  static constexpr int id = 1;
  static constexpr int size = 8;
  static constexpr std::string_view title = "Case 1: eight DAEs in maximal coordinates with the pin force";
  static constexpr std::array<Unknown, size> unknowns{Unknown::x1_ddot, Unknown::y1_ddot, Unknown::theta1_ddot,
                                                      Unknown::x2_ddot, Unknown::y2_ddot, Unknown::theta2_ddot,
                                                      Unknown::F_x,     Unknown::F_y};
  static constexpr std::array<std::string_view, size> equations{"1.1", "2.1", "3.1", "4.1", "5.1", "6.1", "7.1", "8.1"};

  static constexpr auto A = [] {
    using namespace expr;
    return matrix(row(m, zero, zero, zero, zero, zero, -one, zero), row(zero, m, zero, zero, zero, zero, zero, -one),
                  row(zero, zero, I, zero, zero, zero, D * sin1, -(D * cos1)),
                  row(zero, zero, zero, m, zero, zero, one, zero), row(zero, zero, zero, zero, m, zero, zero, one),
                  row(zero, zero, zero, zero, zero, I, D * sin2, -(D * cos2)),
                  row(one, zero, -(D * sin1), -one, zero, -(D * sin2), zero, zero),
                  row(zero, one, D * cos1, zero, -one, D * cos2, zero, zero));
  }();
  static constexpr auto B = [] {
    using namespace expr;
    return column(zero, -(m * g), zero, zero, -(m * g), zero, D * (w1sq * cos1 + w2sq * cos2),
                  D * (w1sq * sin1 + w2sq * sin2));
  }();

  // Block layout for the Schur-complement solve: unknown pivot_cols[i] is found from row
  // pivot_rows[i] alone once the border unknowns are known.
  static constexpr std::array<int, 6> pivot_rows{0, 1, 2, 3, 4, 5};
  static constexpr std::array<int, 6> pivot_cols{0, 1, 2, 3, 4, 5};
  static constexpr std::array<int, 2> border_rows{6, 7};
  static constexpr std::array<int, 2> border_cols{6, 7};
};

}  // namespace linkage
