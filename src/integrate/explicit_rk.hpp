#pragma once
// Fixed-step explicit Runge-Kutta methods, each a Butcher tableau (see tableau.hpp).
//
// Explicit Euler, order 1:        Classical Runge-Kutta (RK4), order 4:
//   0 |                             0   |
//   --+--                           1/2 | 1/2
//     | 1                           1/2 | 0    1/2
//                                   1   | 0    0    1
//   y1 = y + h f(t, y)              ----+-------------------
//                                       | 1/6  1/3  1/3  1/6
//
// Global error O(h^p) with p the order; neither conserves energy: RK4 loses it slowly
// (its error in energy grows linearly with time), Euler gains it quickly.
#include <array>

#include "integrate/ode.hpp"
#include "integrate/tableau.hpp"

namespace linkage::ode {

inline constexpr Tableau<1> kEulerTableau{{0.0L}, {{{0.0L}}}, {1.0L}};

inline constexpr Tableau<4> kRk4Tableau{
    {0.0L, 0.5L, 0.5L, 1.0L},
    {{{0.0L, 0.0L, 0.0L, 0.0L}, {0.5L, 0.0L, 0.0L, 0.0L}, {0.0L, 0.5L, 0.0L, 0.0L}, {0.0L, 0.0L, 1.0L, 0.0L}}},
    {1.0L / 6, 1.0L / 3, 1.0L / 3, 1.0L / 6}};

/// A fixed-step explicit Runge-Kutta method given by tableau T.
template <auto T, class Scalar, int N>
class ExplicitRk {
 public:
  using Vector = State<Scalar, N>;
  static constexpr std::size_t stages = decltype(T)::stages;

  /// Advances y from t to t + h in place.
  template <class F>
  requires Derivative<F, Scalar, N> StepStatus step(F& f, Scalar t, Scalar h, Vector& y) {
    f(t, y, k_[0]);
    evaluate_stages<T, 1, stages>(f, t, y, h, k_, stage_);
    add_weighted<T.b>(y, h, k_, stage_);
    counters_.rhs_evaluations += static_cast<std::int64_t>(stages);
    if (!all_finite(stage_)) return StepStatus::non_finite;
    y = stage_;
    ++counters_.steps_accepted;
    return StepStatus::ok;
  }

  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  std::array<Vector, stages> k_;
  Vector stage_;
  Counters counters_;
};

template <class Scalar, int N>
using ExplicitEuler = ExplicitRk<kEulerTableau, Scalar, N>;
template <class Scalar, int N>
using Rk4 = ExplicitRk<kRk4Tableau, Scalar, N>;

}  // namespace linkage::ode
