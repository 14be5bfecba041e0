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
  static_assert(N % 2 == 0, "the state must be (positions, velocities) of equal length");
  static constexpr int n = N / 2;

 public:
  using Vector = State<Scalar, N>;

  /// Advances y = (q, v) from t to t + h in place.
  template <class F>
  requires Derivative<F, Scalar, N> StepStatus step(F& f, Scalar t, Scalar h, Vector& y) {
    f(t, y, dydt_);
    ++counters_.rhs_evaluations;
    next_ = y;
    next_.template tail<n>() += h * dydt_.template tail<n>();
    next_.template head<n>() += h * next_.template tail<n>();
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
