#pragma once
// Two-stage Gauss-Legendre collocation, order 4, implicit, symmetric and symplectic.
//
//   1/2 - sqrt3/6 | 1/4             1/4 - sqrt3/6
//   1/2 + sqrt3/6 | 1/4 + sqrt3/6   1/4
//   --------------+------------------------------
//                 | 1/2             1/2
//
// The stages are found in increment form, Z_i = Y_i - y:
//   Z_i = h sum_j a_ij f(t + c_j h, y + Z_j)       i = 1, 2      (2N equations)
//   y1  = y + sum_i d_i Z_i,  d = b^T A^-1 = (-sqrt3, sqrt3)
// by simplified Newton iteration with J ~ df/dy from forward differences:
//   (I - h A (x) J) dZ = -Z + h (A (x) I) F(Z),    Z <- Z + dZ
// It stops when the update is at the round-off of the residual (eps |Y| propagated
// through h |J|, at least eps max |Y|); it fails (and the step is refused) when the update stops shrinking
// before that, or after `max_iterations`: h is too large for the problem.
//
// Work saved between steps of equal size that continue each other: the iteration starts
// from the previous step's collocation polynomial extrapolated over the new step, and
// the previous J and LU factors are kept while they converge quickly. Should that
// iteration fail, the step is retried once with a fresh J at (t, y) and the start
// Z_i = c_i h f(t, y) before a failure is reported.
//
// Symmetric methods have no systematic energy drift: over long runs the energy error
// oscillates instead of growing.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "integrate/ode.hpp"

namespace linkage::ode {

template <class Scalar, int N>
class GaussLegendre2 {
 public:
  using Vector = State<Scalar, N>;
  static constexpr int max_iterations = 20;
  /// A kept Jacobian is trusted for the next step while Newton needs at most this many.
  static constexpr int fast_convergence = 5;

  /// Advances y from t to t + h in place; on failure y is unchanged.
  template <class F>
  requires Derivative<F, Scalar, N> StepStatus step(F& f, Scalar t, Scalar h, Vector& y) {
    const bool continues = continuation_ && h == h_ && y == y_end_;
    StepStatus status = StepStatus::newton_failed;
    if (continues && keep_jacobian_) {
      extrapolate();
      status = iterate(f, t, h, y);
    }
    if (status == StepStatus::newton_failed) {
      f(t, y, f0_);
      jacobian(f, t, y);
      counters_.rhs_evaluations += 1 + static_cast<std::int64_t>(y.size());
      if (!all_finite(f0_) || !jacobian_.allFinite()) return fail(StepStatus::non_finite);
      factor(h);
      if (continues) {
        extrapolate();
      } else {
        z1_ = c1() * h * f0_;
        z2_ = c2() * h * f0_;
      }
      status = iterate(f, t, h, y);
    }
    if (status != StepStatus::ok) return fail(status);
    z1_end_ = z1_;
    z2_end_ = z2_;
    h_ = h;
    y_end_ = y;
    continuation_ = true;
    ++counters_.steps_accepted;
    return StepStatus::ok;
  }

  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  using Matrix = Eigen::Matrix<Scalar, N, N>;
  using Big = Eigen::Matrix<Scalar, twice(N), 1>;
  using BigMatrix = Eigen::Matrix<Scalar, twice(N), twice(N)>;

  static Scalar r3() { return std::sqrt(Scalar(3)); }
  static Scalar c1() { return Scalar(0.5) - r3() / 6; }
  static Scalar c2() { return Scalar(0.5) + r3() / 6; }
  static Scalar a12() { return Scalar(0.25) - r3() / 6; }
  static Scalar a21() { return Scalar(0.25) + r3() / 6; }
  static constexpr Scalar a11 = Scalar(0.25), a22 = Scalar(0.25);

  StepStatus fail(StepStatus status) {
    continuation_ = false;
    return status;
  }

  /// Newton matrix I - h A (x) J, factored.
  void factor(Scalar h) {
    const Eigen::Index n = jacobian_.rows();
    newton_.setIdentity(2 * n, 2 * n);
    newton_.topLeftCorner(n, n) -= h * a11 * jacobian_;
    newton_.topRightCorner(n, n) -= h * a12() * jacobian_;
    newton_.bottomLeftCorner(n, n) -= h * a21() * jacobian_;
    newton_.bottomRightCorner(n, n) -= h * a22 * jacobian_;
    lu_.compute(newton_);
  }

  /// Z from the last step's collocation polynomial u(tau) (u(0) = 0, u(c_i) = Z_i, tau
  /// in units of h), continued over the next step: Z_i = u(1 + c_i) - u(1).
  void extrapolate() {
    const Scalar p = c1(), q = c2();
    auto u = [&](Scalar tau, Vector& out) {
      out = (tau * (tau - q) / (p * (p - q))) * z1_end_ + (tau * (tau - p) / (q * (q - p))) * z2_end_;
    };
    u(1, stage_);
    u(1 + p, z1_);
    u(1 + q, z2_);
    z1_ -= stage_;
    z2_ -= stage_;
  }

  /// The simplified Newton iteration from the current Z; on success writes y1 into y.
  template <class F>
  StepStatus iterate(F& f, Scalar t, Scalar h, Vector& y) {
    const Scalar eps = std::numeric_limits<Scalar>::epsilon();
    Scalar previous = std::numeric_limits<Scalar>::infinity();
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
      stage_ = y + z1_;
      f(t + c1() * h, stage_, f1_);
      stage_ = y + z2_;
      f(t + c2() * h, stage_, f2_);
      counters_.rhs_evaluations += 2;
      ++counters_.newton_iterations;
      const Eigen::Index n = y.size();
      residual_.resize(2 * n);
      residual_.head(n) = -z1_ + h * (a11 * f1_ + a12() * f2_);
      residual_.tail(n) = -z2_ + h * (a21() * f1_ + a22 * f2_);
      delta_ = lu_.solve(residual_);
      if (!delta_.allFinite()) return StepStatus::non_finite;
      z1_ += delta_.head(n);
      z2_ += delta_.tail(n);

      // The update in units of the residual's round-off: each stage input Y_j carries
      // eps |Y_j| of rounding, which reaches component i through h |J_ij|.
      magnitude_ = y.cwiseAbs() + z1_.cwiseAbs() + z2_.cwiseAbs();
      noise_ = eps * (magnitude_ + h * (jacobian_.cwiseAbs() * magnitude_));
      // A component that is zero by symmetry (a cart's y, a hanging rod's vertical rate)
      // has no round-off of its own, yet the right-hand side's linear solve leaves eps of
      // the other components in it: judge it against eps times the state's largest, as a
      // scalar atol does.
      noise_ = noise_.cwiseMax(eps * magnitude_.maxCoeff());
      Scalar change = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const Scalar d = std::max(std::fabs(delta_[i]), std::fabs(delta_[n + i]));
        if (d > 0) change = std::max(change, d / std::max(noise_[i], std::numeric_limits<Scalar>::min()));
      }
      const bool at_round_off = change <= 10;
      const bool stalled = change >= Scalar(0.9) * previous;
      if (at_round_off || (stalled && change <= 1000)) {
        next_ = y + r3() * (z2_ - z1_);
        if (!all_finite(next_)) return StepStatus::non_finite;
        y = next_;
        keep_jacobian_ = iteration <= fast_convergence;
        return StepStatus::ok;
      }
      if (stalled && iteration > 1) return StepStatus::newton_failed;
      previous = change;
    }
    return StepStatus::newton_failed;
  }

  /// Forward differences, one column per state component.
  template <class F>
  void jacobian(F& f, Scalar t, const Vector& y) {
    const Scalar delta0 = std::sqrt(std::numeric_limits<Scalar>::epsilon());
    jacobian_.resize(y.size(), y.size());
    for (Eigen::Index j = 0; j < y.size(); ++j) {
      stage_ = y;
      const Scalar delta = delta0 * std::max(Scalar(1), std::fabs(y[j]));
      stage_[j] += delta;
      f(t, stage_, f1_);
      jacobian_.col(j) = (f1_ - f0_) / (stage_[j] - y[j]);
    }
  }

  Vector f0_, f1_, f2_, z1_, z2_, stage_, next_, magnitude_, noise_;
  Matrix jacobian_;
  BigMatrix newton_;
  Eigen::PartialPivLU<BigMatrix> lu_;
  Big residual_, delta_;
  // The last step, for continuing from it.
  bool continuation_ = false, keep_jacobian_ = false;
  Scalar h_ = 0;
  Vector y_end_, z1_end_, z2_end_;
  Counters counters_;
};

}  // namespace linkage::ode
