#pragma once
// Semi-implicit (symplectic) Euler for second-order systems, order 1.
//
// The state is y = (q, v) with q' = v and v' = a(t, q, v); the right-hand side returns
// (v, a). One evaluation per step, velocity first, then position with the new velocity:
//   v1 = v + h a(t, q, v)
//   q1 = q + h v1
// For a separable Hamiltonian (a = a(q)) this map is symplectic: it keeps a modified
// energy H~ = H + O(h) exactly, so the energy error stays bounded instead of drifting.
// (Under constant gravity H~ = H - h g p_y / 2: the energy error follows the vertical
// momentum, which grows in free fall.)
#include "integrate/ode.hpp"

namespace linkage::ode {

template <class Scalar, int N>
class SymplecticEuler {
  static_assert(N == Eigen::Dynamic || N % 2 == 0, "the state must be (positions, velocities) of equal length");

 public:
  using Vector = State<Scalar, N>;

  /// Advances y = (q, v) from t to t + h in place.
  template <class F>
  requires Derivative<F, Scalar, N> StepStatus step(F& f, Scalar t, Scalar h, Vector& y) {
    f(t, y, dydt_);
    ++counters_.rhs_evaluations;
    next_ = y;
    if constexpr (N == Eigen::Dynamic) {
      // (q, v, extra): an odd last entry (a mechanism run's accumulated work) steps
      // with the velocities.
      const Eigen::Index n = y.size() / 2, rest = y.size() - n;
      next_.tail(rest) += h * dydt_.tail(rest);
      next_.head(n) += h * next_.segment(n, n);
    } else {
      next_.template tail<N / 2>() += h * dydt_.template tail<N / 2>();
      next_.template head<N / 2>() += h * next_.template tail<N / 2>();
    }
    if (!all_finite(next_)) return StepStatus::non_finite;
    y = next_;
    ++counters_.steps_accepted;
    return StepStatus::ok;
  }

  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  Vector dydt_, next_;
  Counters counters_;
};

}  // namespace linkage::ode
