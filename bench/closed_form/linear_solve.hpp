#pragma once
// Assembling and solving a case's A q = B. Every case has the same block shape: a set
// of "pivot" rows that each involve one pivot unknown plus the two "border" unknowns,
// and two border rows. Eliminating the pivots leaves a 2x2 Schur complement:
//   x_i = (b_i - sum_j C_ij y_j) / a_ii                          for each pivot i
//   (E - G diag(a)^-1 C) y = b_border - G diag(a)^-1 b_pivot     for the border y
// which costs a few dozen flops, needs no pivoting for any valid input, and is checked
// against the definition's structural zeros at compile time.
#include <cmath>
#include <limits>

#include "bench/closed_form/expr.hpp"
#include "bench/closed_form/params.hpp"
#include "core/types.hpp"

namespace linkage {

/// `base` (its m, I, D, g kept) at the given angles and rates.
[[nodiscard]] inline expr::Env with_angles(expr::Env base, double theta1, double theta2, double theta1_dot,
                                           double theta2_dot) {
  base.s1 = std::sin(theta1);
  base.c1 = std::cos(theta1);
  base.s2 = std::sin(theta2);
  base.c2 = std::cos(theta2);
  base.w1 = theta1_dot;
  base.w2 = theta2_dot;
  return base;
}

/// The Env of a case's expressions at the given angles and rates.
[[nodiscard]] inline expr::Env make_env(const Params& p, double theta1, double theta2, double theta1_dot,
                                        double theta2_dot) {
  expr::Env env;
  env.m = p.m;
  env.I = p.inertia_centroidal();
  env.D = p.pin_offset();
  env.g = p.g;
  return with_angles(env, theta1, theta2, theta1_dot, theta2_dot);
}

template <class Case>
struct LinearSystem {
  Mat<Case::size> A;
  Vec<Case::size> B;
};

template <class Case>
[[nodiscard]] LinearSystem<Case> assemble(const expr::Env& env) {
  LinearSystem<Case> s;
  decltype(Case::A)::eval(s.A, env);
  decltype(Case::B)::eval(s.B, env);
  return s;
}

/// True when the case's declared block layout matches its definition's zeros.
template <class Case>
constexpr bool block_layout_holds() {
  using A = decltype(Case::A);
  for (std::size_t i = 0; i < Case::pivot_rows.size(); ++i) {
    const int r = Case::pivot_rows[i];
    if (A::structural_zero(r, Case::pivot_cols[i])) return false;
    for (std::size_t j = 0; j < Case::pivot_cols.size(); ++j)
      if (j != i && !A::structural_zero(r, Case::pivot_cols[j])) return false;
  }
  return true;
}

/// Solves A q = B by the Schur complement on the case's block layout. Returns false
/// (leaving q unspecified) when a pivot or the 2x2 complement is singular to working
/// precision.
template <class Case>
[[nodiscard]] bool solve_blocks(const Mat<Case::size>& A, const Vec<Case::size>& B, Vec<Case::size>& q) {
  static_assert(block_layout_holds<Case>(), "the case's pivot rows must each hold one pivot unknown");
  constexpr auto& pr = Case::pivot_rows;
  constexpr auto& pc = Case::pivot_cols;
  constexpr auto& br = Case::border_rows;
  constexpr auto& bc = Case::border_cols;
  constexpr std::size_t np = pr.size();

  // S = E - G diag(a)^-1 C, rhs = b_border - G diag(a)^-1 b_pivot
  double s00 = A(br[0], bc[0]), s01 = A(br[0], bc[1]), s10 = A(br[1], bc[0]), s11 = A(br[1], bc[1]);
  double r0 = B[br[0]], r1 = B[br[1]];
  for (std::size_t i = 0; i < np; ++i) {
    const double a = A(pr[i], pc[i]);
    if (a == 0.0) return false;
    const double g0 = A(br[0], pc[i]) / a, g1 = A(br[1], pc[i]) / a;
    const double c0 = A(pr[i], bc[0]), c1 = A(pr[i], bc[1]), b = B[pr[i]];
    s00 -= g0 * c0;
    s01 -= g0 * c1;
    s10 -= g1 * c0;
    s11 -= g1 * c1;
    r0 -= g0 * b;
    r1 -= g1 * b;
  }
  const double det = s00 * s11 - s01 * s10;
  const double size = std::fabs(s00 * s11) + std::fabs(s01 * s10);
  if (!(std::fabs(det) > 8 * std::numeric_limits<double>::epsilon() * size)) return false;
  const double y0 = (r0 * s11 - s01 * r1) / det;
  const double y1 = (s00 * r1 - s10 * r0) / det;
  q[bc[0]] = y0;
  q[bc[1]] = y1;
  for (std::size_t i = 0; i < np; ++i)
    q[pc[i]] = (B[pr[i]] - A(pr[i], bc[0]) * y0 - A(pr[i], bc[1]) * y1) / A(pr[i], pc[i]);
  return true;
}

}  // namespace linkage
