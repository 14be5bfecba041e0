#pragma once
// The linkage as a first-order system y' = f(y) for the integrators, from the one
// definition of each case (case1/2/3.hpp: assemble<Case> + solve_blocks<Case>).
//
// Cases 2 and 3 (generalized coordinates, 8 values):
//   y = (x1, y1, th1, th2, x1', y1', th1', th2'),  y' = (rates, x1'', y1'', th1'', th2'')
// Case 3 steps with its closed-form solution (case3_fast.hpp: the same four equations
// solved by hand, tested against the definition), about twice as fast as the generic
// block solve; output samples still solve the definition itself.
// Case 1 (maximal coordinates, 12 values; x2, y2 are free to drift off the pin):
//   y = (x1, y1, th1, x2, y2, th2, and their rates), y' = (rates, the six accelerations)
//
// Baumgarte stabilization of Case 1. Rows 7 and 8 of its matrix state -C'' = 0 for the
// pin constraint C = C2 - C1 - D (e1 + e2) (kinematics.hpp): the constraint is enforced
// only at acceleration level, so round-off and truncation errors in C and C' grow. Asking
// instead for the damped oscillator C'' + 2 alpha C' + beta^2 C = 0 adds
//   B_7,8 += 2 alpha C' + beta^2 C
// which pulls the error back to zero with rate alpha (critically damped when alpha =
// beta). Large gains make the system stiff, so a step must stay below ~1/alpha.
#include <cmath>
#include <limits>

#include "bench/closed_form/case1.hpp"
#include "bench/closed_form/case2.hpp"
#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "bench/closed_form/params.hpp"
#include "core/types.hpp"

namespace linkage {

/// The number of values a case integrates: 8 for Cases 2 and 3, 12 for Case 1.
template <class Case>
inline constexpr int state_size = Case::size == 8 ? 12 : 8;

/// Accelerations (and, for Cases 1 and 2, the pin force) of a case at angles and rates,
/// the case's unknown vector q. NaN when the matrix is singular to working precision.
template <class Case>
[[nodiscard]] inline Vec<Case::size> case_unknowns(const expr::Env& env) {
  const LinearSystem<Case> system = assemble<Case>(env);
  Vec<Case::size> q;
  if (!solve_blocks<Case>(system.A, system.B, q)) q.setConstant(std::numeric_limits<double>::quiet_NaN());
  return q;
}

/// f(t, y) for Case 2 or Case 3 in generalized coordinates.
template <class Case>
class GeneralizedRhs {
  static_assert(Case::id == 2 || Case::id == 3, "Case 1 integrates maximal coordinates: use MaximalRhs");

 public:
  using Vector = Vec<8>;
  explicit GeneralizedRhs(const Params& p) : env_(make_env(p, 0, 0, 0, 0)), fast_(p) {}

  /// The case's unknowns at state y (for output: accelerations and pin force).
  [[nodiscard]] Vec<Case::size> unknowns(const Vector& y) const { return case_unknowns<Case>(env_at(y)); }

  void operator()(double /*t*/, const Vector& y, Vector& dydt) const {
    if constexpr (Case::id == 3) {
      fast_.rhs(y, dydt);
    } else {
      const Vec<Case::size> q = case_unknowns<Case>(env_at(y));
      dydt.head<4>() = y.tail<4>();
      dydt.tail<4>() = q.template head<4>();  // x1'', y1'', th1'', th2'' lead every case's unknowns
    }
  }

 private:
  [[nodiscard]] expr::Env env_at(const Vector& y) const { return with_angles(env_, y[2], y[3], y[6], y[7]); }

  expr::Env env_;  // m, I, D, g fixed; the angle terms are set per call
  Case3Fast<double> fast_;
};

/// f(t, y) for Case 1 in maximal coordinates, optionally Baumgarte-stabilized.
class MaximalRhs {
 public:
  using Vector = Vec<12>;
  /// alpha, beta in 1/s; both 0 for the plain equations.
  MaximalRhs(const Params& p, double alpha, double beta)
      : env_(make_env(p, 0, 0, 0, 0)), two_alpha_(2 * alpha), beta_squared_(beta * beta) {}

  /// Case 1's unknowns (x1'', y1'', th1'', x2'', y2'', th2'', Fx, Fy) at state y.
  [[nodiscard]] Vec<8> unknowns(const Vector& y) const {
    const expr::Env env = env_at(y);
    LinearSystem<Case1> system = assemble<Case1>(env);
    if (two_alpha_ != 0 || beta_squared_ != 0) {
      const double D = env.D;
      const double cx = y[3] - y[0] - D * (env.c1 + env.c2);  // C
      const double cy = y[4] - y[1] - D * (env.s1 + env.s2);
      const double vx = y[9] - y[6] + D * (env.w1 * env.s1 + env.w2 * env.s2);  // C'
      const double vy = y[10] - y[7] - D * (env.w1 * env.c1 + env.w2 * env.c2);
      system.B[6] += two_alpha_ * vx + beta_squared_ * cx;
      system.B[7] += two_alpha_ * vy + beta_squared_ * cy;
    }
    Vec<8> q;
    if (!solve_blocks<Case1>(system.A, system.B, q)) q.setConstant(std::numeric_limits<double>::quiet_NaN());
    return q;
  }

  void operator()(double /*t*/, const Vector& y, Vector& dydt) const {
    const Vec<8> q = unknowns(y);
    dydt.head<6>() = y.tail<6>();
    dydt.tail<6>() = q.head<6>();
  }

 private:
  [[nodiscard]] expr::Env env_at(const Vector& y) const { return with_angles(env_, y[2], y[5], y[8], y[11]); }

  expr::Env env_;
  double two_alpha_, beta_squared_;
};

}  // namespace linkage
