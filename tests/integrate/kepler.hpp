#pragma once
// A test problem for the integrators with an exact solution: Kepler's two-body orbit,
// r'' = -r / |r|^3 (GM = 1, semi-major axis 1, period 2 pi), from perihelion. Nonlinear
// and, for eccentricity e > 0, with a step size that must follow the speed along the
// orbit; its energy -1/2 and angular momentum sqrt(1 - e^2) are exact invariants.
#include <cmath>

#include "core/types.hpp"

namespace linkage::test {

struct Kepler {
  double e = 0.5;  // eccentricity, in [0, 1)

  /// y = (x, y, x', y').
  void operator()(double /*t*/, const Vec<4>& y, Vec<4>& dydt) const {
    const double r2 = y[0] * y[0] + y[1] * y[1];
    const double r3 = r2 * std::sqrt(r2);
    dydt << y[2], y[3], -y[0] / r3, -y[1] / r3;
  }

  /// The exact state at time t: Kepler's equation E - e sin E = t solved by Newton (it
  /// converges from E = t for every e < 1), then the ellipse at eccentric anomaly E.
  [[nodiscard]] Vec<4> exact(double t) const {
    double E = t;
    for (int k = 0; k < 50; ++k) {
      const double step = (E - e * std::sin(E) - t) / (1 - e * std::cos(E));
      E -= step;
      if (std::fabs(step) <= 1e-16 * (1 + std::fabs(E))) break;
    }
    const double b = std::sqrt(1 - e * e), d = 1 - e * std::cos(E);
    return {std::cos(E) - e, b * std::sin(E), -std::sin(E) / d, b * std::cos(E) / d};
  }

  [[nodiscard]] Vec<4> initial() const { return exact(0); }

  /// Kinetic plus potential energy, -1/2 on the exact orbit.
  [[nodiscard]] static double energy(const Vec<4>& y) {
    return 0.5 * (y[2] * y[2] + y[3] * y[3]) - 1 / std::hypot(y[0], y[1]);
  }
};

}  // namespace linkage::test
