#pragma once
// Right-hand sides y' = f(y) of the linkage for the benchmarks, beside the ones the
// integrators use (closed_form/linkage_rhs.hpp: GeneralizedRhs<Case>, MaximalRhs, from
// the one definition of each case).
//
//   - FastCase3Rhs<T>: the closed-form Case 3 (closed_form/case3_fast.hpp) as an
//     integrator's f(t, y, dydt), for double runs and long double references;
//   - user_case3_rhs: what a user of an ODE library would write for Case 3: the 4x4 A
//     and B of spec sec. 5 typed in by hand into fixed-size Eigen types, then
//     partialPivLu(). The peers run with it, and with FastCase3Rhs.
// State of Cases 2 and 3: y = (x1, y1, th1, th2, x1', y1', th1', th2').
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/closed_form/params.hpp"

namespace linkage::bench {

/// Case3Fast as a right-hand side f(t, y, dydt) for the integrators of src/integrate.
template <class T>
struct FastCase3Rhs {
  using Vector = Eigen::Matrix<T, 8, 1>;
  Case3Fast<T> f;
  explicit FastCase3Rhs(const Params& p) : f(p) {}
  explicit FastCase3Rhs(const Case3Fast<T>& closed_form) : f(closed_form) {}
  void operator()(T /*t*/, const Vector& y, Vector& dydt) const { f.rhs(y, dydt); }
};

/// Case 3 through its definition: the matrices' expressions (case3.hpp) and the block
/// solve, as `linkage solve` does; what the closed form is measured against.
struct DefinitionCase3Rhs {
  Params params;
  void operator()(double /*t*/, const Vec<8>& y, Vec<8>& dydt) const {
    const Vec<4> q = case_unknowns<Case3>(make_env(params, y[2], y[3], y[6], y[7]));
    dydt.head<4>() = y.tail<4>();
    dydt.tail<4>() = q;
  }
};

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
  A << c.m * c.D * s1, -c.m * c.D * c1, c.I, 0.0, c.m * c.D * s2, -c.m * c.D * c2, 0.0, c.I, 2.0, 0.0, -c.D * s1,
      -c.D * s2, 0.0, 2.0, c.D * c1, c.D * c2;
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
