#include "bench/closed_form/projection.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace linkage {
namespace {

constexpr int kMaxIterations = 8;

/// J (2 x 6) of the pin constraint at angles th1 = y[2], th2 = y[5].
Mat<2, 6> constraint_jacobian(double D, const Vec<12>& y) {
  const double s1 = std::sin(y[2]), c1 = std::cos(y[2]), s2 = std::sin(y[5]), c2 = std::cos(y[5]);
  Mat<2, 6> J;
  J << -1, 0, D * s1, 1, 0, D * s2,  //
      0, -1, -D * c1, 0, 1, -D * c2;
  return J;
}

/// The mass-weighted correction -M^-1 J^T (J M^-1 J^T)^-1 r for a constraint residual r.
Vec<6> correction(const Mat<2, 6>& J, const Vec<6>& inverse_mass, const Vec2& r) {
  const Mat<6, 2> MinvJt = inverse_mass.asDiagonal() * J.transpose();
  const Eigen::Matrix2d W = J * MinvJt;  // symmetric positive definite: 2/m on the diagonal at least
  return -(MinvJt * W.inverse() * r);
}

}  // namespace

ProjectionResult project_onto_constraint(const Params& p, Vec<12>& y) {
  const double D = p.pin_offset();
  const double inv_m = 1.0 / p.m, inv_I = 1.0 / p.inertia_centroidal();
  Vec<6> inverse_mass;
  inverse_mass << inv_m, inv_m, inv_I, inv_m, inv_m, inv_I;
  const double eps = std::numeric_limits<double>::epsilon();

  ProjectionResult result;
  double previous = std::numeric_limits<double>::infinity();
  for (;;) {
    const Vec2 C{y[3] - y[0] - D * (std::cos(y[2]) + std::cos(y[5])),
                 y[4] - y[1] - D * (std::sin(y[2]) + std::sin(y[5]))};
    result.residual = C.cwiseAbs().maxCoeff();
    // Round-off of C's evaluation, from the size of the terms it subtracts.
    const double round_off =
        8 * eps * (std::max({std::fabs(y[0]), std::fabs(y[1]), std::fabs(y[3]), std::fabs(y[4])}) + D);
    if (result.residual <= round_off || (result.residual >= previous && result.residual <= 100 * round_off)) {
      result.converged = true;
      break;
    }
    if (result.iterations == kMaxIterations || !std::isfinite(result.residual)) return result;
    y.head<6>() += correction(constraint_jacobian(D, y), inverse_mass, C);
    previous = result.residual;
    ++result.iterations;
  }
  const Mat<2, 6> J = constraint_jacobian(D, y);
  const Vec2 velocity_error = J * y.tail<6>();
  y.tail<6>() += correction(J, inverse_mass, velocity_error);
  return result;
}

}  // namespace linkage
