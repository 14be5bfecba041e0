#pragma once
// The double pendulum's right-hand side as a user would write it by hand for a library
// integrator (Boost.Odeint): two uniform rods, rod 1 pinned at its end to the ground at
// the origin, rod 2 pinned to rod 1's far end; absolute angles from +x, counter-clockwise,
// gravity along -y. From Lagrange's equations with k = m2 l1 l2 / 2, s = sin(th1 - th2):
//   (m1/3 + m2) l1^2 a1 + k cos(th1 - th2) a2 = -(m1/2 + m2) g l1 cos th1 - k s w2^2
//   k cos(th1 - th2) a1 + m2 l2^2 / 3 a2       = -m2 g l2 / 2 cos th2 + k s w1^2
// Written once here, independently of the tool's derivation; a test holds it to ours.
#include <cmath>

namespace linkage::bench {

struct DoublePendulumUser {
  double l1 = 0.3, m1 = 0.2, l2 = 0.25, m2 = 0.15, g = 9.81;

  /// x = (th1, th2, w1, w2) -> dxdt.
  template <class State>
  void operator()(const State& x, State& dxdt, double /*t*/) const {
    const double k = m2 * l1 * l2 / 2, c = std::cos(x[0] - x[1]), s = std::sin(x[0] - x[1]);
    const double M11 = (m1 / 3 + m2) * l1 * l1, M12 = k * c, M22 = m2 * l2 * l2 / 3;
    const double b1 = -(m1 / 2 + m2) * g * l1 * std::cos(x[0]) - k * s * x[3] * x[3];
    const double b2 = -m2 * g * l2 / 2 * std::cos(x[1]) + k * s * x[2] * x[2];
    const double det = M11 * M22 - M12 * M12;
    dxdt[0] = x[2];
    dxdt[1] = x[3];
    dxdt[2] = (b1 * M22 - M12 * b2) / det;
    dxdt[3] = (M11 * b2 - M12 * b1) / det;
  }
};

}  // namespace linkage::bench
