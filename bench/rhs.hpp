#pragma once
// Right-hand sides y' = f(y) of the linkage for the benchmarks.
//
// States: Cases 2 and 3 integrate y = (x1, y1, th1, th2, x1', y1', th1', th2') (8);
// Case 1 integrates y = (x1, y1, th1, x2, y2, th2, and their rates) (12). In both the
// first half of y' is the second half of y, the second half the accelerations.
//
// Two right-hand sides matter for a fair comparison with peer libraries:
//   - formulation_rhs<Case>: ours, from the one definition in src/formulations (the
//     matrices' expressions, then the structured Schur solve of linear_solve.hpp);
//   - user_case3_rhs: what a user of an ODE library would write for Case 3: assemble
//     the 4x4 A and B by hand into fixed-size Eigen types and call partialPivLu().
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/types.hpp"
#include "formulations/linear_solve.hpp"
#include "model/params.hpp"

namespace linkage::bench {

/// Number of coordinates (half the state) a case integrates.
template <class Case>
inline constexpr int coordinates = Case::size == 8 ? 6 : 4;
/// Size of a case's integrated state.
template <class Case>
inline constexpr int state_size = 2 * coordinates<Case>;

/// Our right-hand side for any case; returns false when the matrix is singular.
template <class Case>
bool formulation_rhs(const Params& p, const Vec<state_size<Case>>& y, Vec<state_size<Case>>& dy) {
  constexpr int n = coordinates<Case>;
  // The angles sit at the same place as the unknowns th1'', th2'' in each case.
  constexpr int th1 = 2, th2 = n - 1;
  const expr::Env env = make_env(p, y[th1], y[th2], y[n + th1], y[n + th2]);
  const LinearSystem<Case> system = assemble<Case>(env);
  Vec<Case::size> q;
  const bool ok = solve_blocks<Case>(system.A, system.B, q);
  dy.template head<n>() = y.template tail<n>();
  dy.template tail<n>() = q.template head<n>();
  return ok;
}

/// The parameters a user would precompute once: m, I_zz^C, D, g.
struct UserConstants {
  double m, I, D, g;
  explicit UserConstants(const Params& p) : m(p.m), I(p.inertia_centroidal()), D(p.pin_offset()), g(p.g) {}
};

/// Case 3 as a user of an ODE library writes it (spec sec. 5 typed in by hand):
/// fixed-size 4x4 Eigen matrix, partial-pivot LU. `y` and `dy` hold 8 doubles.
inline void user_case3_rhs(const UserConstants& c, const double* y, double* dy) {
  const double s1 = std::sin(y[2]), c1 = std::cos(y[2]), s2 = std::sin(y[3]), c2 = std::cos(y[3]);
  const double w1 = y[6], w2 = y[7];
  Eigen::Matrix4d A;
  A << c.m * c.D * s1, -c.m * c.D * c1, c.I, 0.0,
       c.m * c.D * s2, -c.m * c.D * c2, 0.0, c.I,
       2.0, 0.0, -c.D * s1, -c.D * s2,
       0.0, 2.0, c.D * c1, c.D * c2;
  Eigen::Vector4d B;
  B << c.m * c.g * c.D * c1, c.m * c.g * c.D * c2, c.D * (w1 * w1 * c1 + w2 * w2 * c2),
       c.D * (w1 * w1 * s1 + w2 * w2 * s2) - 2.0 * c.g;
  const Eigen::Vector4d q = A.partialPivLu().solve(B);
  for (int i = 0; i < 4; ++i) {
    dy[i] = y[i + 4];
    dy[i + 4] = q[i];
  }
}

}  // namespace linkage::bench
