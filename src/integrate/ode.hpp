#pragma once
// What every integrator shares: the state type, the derivative callable, the outcome of
// a step, and the counters a run reports.
//
// An initial value problem y' = f(t, y), y(t0) = y0, with y a fixed-size column of N
// values of type Scalar (double, or long double for references). Integrators call
//   f(t, y, dydt)        // void(Scalar, const State<Scalar, N>&, State<Scalar, N>&)
// and know nothing else about the problem: no formulation, no allocation in a step.
#include <Eigen/Core>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <string_view>

namespace linkage::ode {

/// A state column: fixed-size, or Eigen::Dynamic for a mechanism read from a file
/// (sized once by the first right-hand side; no allocation in later steps).
template <class Scalar, int N>
using State = Eigen::Matrix<Scalar, N, 1>;

/// 2 N, or Dynamic for Dynamic: the size of a pair of stages.
[[nodiscard]] constexpr int twice(int n) { return n == Eigen::Dynamic ? Eigen::Dynamic : 2 * n; }

/// A right-hand side f(t, y, dydt) that writes y' into dydt.
template <class F, class Scalar, int N>
concept Derivative = requires(F& f, Scalar t, const State<Scalar, N>& y, State<Scalar, N>& dydt) {
  {f(t, y, dydt)};
};

/// Why a step did not produce a usable state.
enum class StepStatus {
  ok,
  non_finite,      // the new state (or a stage) is not finite
  step_underflow,  // the adaptive step fell below round-off of t
  newton_failed,   // an implicit method's Newton iteration did not converge
};

[[nodiscard]] constexpr std::string_view describe(StepStatus s) {
  switch (s) {
    case StepStatus::ok:
      return "ok";
    case StepStatus::non_finite:
      return "the state stopped being finite";
    case StepStatus::step_underflow:
      return "the step size underflowed";
    case StepStatus::newton_failed:
      return "the Newton iteration of the implicit method did not converge";
  }
  return "unknown";
}

/// Work done by an integrator so far.
struct Counters {
  std::int64_t steps_accepted = 0;
  std::int64_t steps_rejected = 0;
  std::int64_t rhs_evaluations = 0;
  std::int64_t newton_iterations = 0;  // implicit methods only
};

/// dst = src. For a fixed size a plain loop: Eigen's assignment stayed an out-of-line
/// call inside an adaptive step (too large a function for GCC's inliner).
template <class Scalar, int N>
inline void copy_state(const State<Scalar, N>& src, State<Scalar, N>& dst) {
  if constexpr (N == Eigen::Dynamic)
    dst = src;
  else
    for (int i = 0; i < N; ++i) dst[i] = src[i];
}

/// True when every entry is finite.
template <class Scalar, int N>
[[nodiscard]] bool all_finite(const State<Scalar, N>& y) {
  for (Eigen::Index i = 0; i < y.size(); ++i)
    if (!std::isfinite(y[i])) return false;
  return true;
}

}  // namespace linkage::ode
