#pragma once
// Case 3 in closed form: the same four equations as case3.hpp, solved by hand once and
// for all, for the integrators' inner loop. Verified against the definition by
// bench/tests/closed_form_case3_fast_test.cpp; case3.hpp stays the one definition.
//
// Rows (3.3) and (4.3) give the linear accelerations from the angular ones:
//   x1'' = D/2 (sin th1 th1'' + sin th2 th2'' + th1'^2 cos th1 + th2'^2 cos th2)
//   y1'' = D/2 (-cos th1 th1'' - cos th2 th2'' + th1'^2 sin th1 + th2'^2 sin th2) - g
// Substituted into (1.3) and (2.3), gravity cancels (the system falls freely) and,
// with k = m D^2 / 2, c = cos(th1 - th2), s = sin(th1 - th2):
//   [ I + k    k c  ] [th1'']       [ -th2'^2 ]
//   [  k c    I + k ] [th2''] = k s [  th1'^2 ]
// whose determinant (I + k (1 - c)) (I + k (1 + c)) >= I^2 > 0: never singular, and
// written as that product it has no cancellation. Cost: two sincos and ~35 flops.
#include <cmath>

#include "bench/closed_form/params.hpp"

namespace linkage {

/// The closed-form Case 3 accelerations for scalar T (double, or long double for
/// reference runs). Construct once per parameter set.
template <class T = double>
class Case3Fast {
 public:
  explicit Case3Fast(const Params& p)
      : Case3Fast(static_cast<T>(p.L), static_cast<T>(p.w), static_cast<T>(p.b), static_cast<T>(p.m),
                  static_cast<T>(p.g)) {}
  /// From parameters given in T itself (e.g. long double values of decimal inputs).
  Case3Fast(T L, T w, T b, T m, T g)
      : I_(m * (w * w + L * L) / T(12)), D_(L / T(2) - b), k_(m * D_ * D_ / T(2)), g_(g) {}

  /// (x1'', y1'', th1'', th2'') into q[0..3].
  void accelerations(T theta1, T theta2, T theta1_dot, T theta2_dot, T* q) const {
    using std::cos;
    using std::sin;
    const T s1 = sin(theta1), c1 = cos(theta1), s2 = sin(theta2), c2 = cos(theta2);
    const T w1sq = theta1_dot * theta1_dot, w2sq = theta2_dot * theta2_dot;
    const T c = c1 * c2 + s1 * s2;  // cos(th1 - th2)
    const T s = s1 * c2 - c1 * s2;  // sin(th1 - th2)
    const T diag = I_ + k_, off = k_ * c;
    const T det = (I_ + k_ * (T(1) - c)) * (I_ + k_ * (T(1) + c));
    const T ks_det = k_ * s / det;
    const T a1 = -ks_det * (diag * w2sq + off * w1sq);
    const T a2 = ks_det * (diag * w1sq + off * w2sq);
    const T half_D = D_ / T(2);
    q[0] = half_D * (s1 * a1 + s2 * a2 + w1sq * c1 + w2sq * c2);
    q[1] = half_D * (w1sq * s1 + w2sq * s2 - c1 * a1 - c2 * a2) - g_;
    q[2] = a1;
    q[3] = a2;
  }

  /// y' = f(y) for y = (x1, y1, th1, th2, x1', y1', th1', th2'); `y` and `dy` are
  /// anything indexable with 8 entries (Eigen vectors, std::array, raw pointers).
  template <class In, class Out>
  void rhs(const In& y, Out& dy) const {
    T q[4];
    accelerations(y[2], y[3], y[6], y[7], q);
    for (int i = 0; i < 4; ++i) {
      dy[i] = y[i + 4];
      dy[i + 4] = q[i];
    }
  }

 private:
  T I_, D_, k_, g_;
};

}  // namespace linkage
