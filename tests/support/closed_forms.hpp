#pragma once
// Closed forms the tests check the program against, kept once for every test that needs them.
#include <algorithm>
#include <array>
#include <cmath>

namespace linkage::test {

/// The double pendulum of two uniform rods: its omega^2 from det(K - w M) = 0, M =
/// [[(m1/3 + m2) l1^2, m2 l1 l2 / 2], [m2 l1 l2 / 2, m2 l2^2 / 3]], K = s diag((m1/2 + m2) g
/// l1, m2 g l2 / 2), s = 1 hanging and -1 upright; the smaller first.
inline std::array<double, 2> double_pendulum_w2(double l1, double m1, double l2, double m2, double g, double s) {
  const double M11 = (m1 / 3 + m2) * l1 * l1, M12 = m2 * l1 * l2 / 2, M22 = m2 * l2 * l2 / 3;
  const double K11 = s * (m1 / 2 + m2) * g * l1, K22 = s * m2 * g * l2 / 2;
  const double a = M11 * M22 - M12 * M12, b = -(K11 * M22 + K22 * M11), c = K11 * K22;
  const double root = std::sqrt(b * b - 4 * a * c);
  // The root without cancellation, the other from the product c / a.
  const double big = (-b - std::copysign(root, b)) / (2 * a);
  const double small = c / (a * big);
  return {std::min(big, small), std::max(big, small)};
}

}  // namespace linkage::test
