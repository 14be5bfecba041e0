#pragma once
// What our integrators cost on their own, per right-hand-side evaluation: each one timed
// on a right-hand side of known, negligible cost (four uncoupled oscillators, the
// homework's 8 values, 4 multiplies), making as many evaluations as it makes on the
// homework at the setting the targets use. Subtracting a separately timed right-hand
// side from the homework run's time per evaluation instead came out negative under load
// (RK4 at -7.26 ns); this figure includes the cheap right-hand side, so it cannot.
#include <cstdint>
#include <optional>
#include <string>

#include "bench/scenarios.hpp"
#include "bench/timing.hpp"
#include "core/types.hpp"

namespace linkage::bench {

/// y = (q, v), q' = v, v' = -w^2 q for four oscillators of angular frequency w = 3, 4,
/// 5, 7 rad/s (periods 0.9 to 2.1 s, like the homework's swings).
struct OscillatorsRhs {
  /// For Vec<8>, or for Eigen::VectorXd as a mechanism read from a file runs.
  template <class V>
  void operator()(double /*t*/, const V& y, V& dydt) const {
    if constexpr (V::SizeAtCompileTime == Eigen::Dynamic) dydt.resize(8);
    dydt[0] = y[4];
    dydt[1] = y[5];
    dydt[2] = y[6];
    dydt[3] = y[7];
    dydt[4] = -9.0 * y[0];
    dydt[5] = -16.0 * y[1];
    dydt[6] = -25.0 * y[2];
    dydt[7] = -49.0 * y[3];
  }
};

/// The starting state of the oscillators' runs.
[[nodiscard]] Vec<8> oscillators_start();

/// One run of `method` (one of our ids: euler, symplectic-euler, rk4, gauss-legendre:
/// `knob` equal steps over `duration` s; dopri5, dop853: rtol = atol = `knob`, stepping
/// until at least `evaluations` evaluations) on OscillatorsRhs. Returns the evaluations
/// made; `sink` receives the final state's sum, so the run cannot be optimized away.
/// `dynamic` (dopri5, dop853 only): on a dynamic-size state, as a mechanism file runs.
std::int64_t run_on_oscillators(const std::string& method, double knob, double duration, std::int64_t evaluations,
                                double& sink, bool dynamic = false);

/// Whether run_on_oscillators has a dynamic-size run of `method`.
[[nodiscard]] bool has_dynamic_run(const std::string& method);

/// One integrator's cost per evaluation on OscillatorsRhs, copying one homework run.
struct OverheadTiming {
  std::string method;  // Method::id
  std::string label;
  bool adaptive = true;
  double knob = 0;                                // the homework run's tolerance (adaptive) or step count
  double homework_error = 0;                      // that run's error, m or rad
  std::int64_t evaluations = 0;                   // per timed run (the homework run's, or just above it)
  PerCall per_evaluation;                         // run time / evaluations, the oscillators' own cost included
  std::optional<PerCall> dynamic_per_evaluation;  // the same on a dynamic-size state (dopri5, dop853, vern7)
  // The homework run itself (Case 3's closed form, real work per evaluation) with a
  // fixed-size state and the right-hand side inline, and with a dynamic-size state and
  // the right-hand side out of line as simulate's: run time per evaluation (adaptive only).
  std::optional<PerCall> closed_form_fixed, closed_form_dynamic;
};

/// Times run_on_oscillators (repeated until `min_time` s, the median run).
[[nodiscard]] PerCall time_on_oscillators(const std::string& method, double knob, double duration,
                                          std::int64_t evaluations, double min_time, std::int64_t& made,
                                          bool dynamic = false);

/// `method` (dopri5, dop853, vern7) on Case 3's closed form over `scenario` at rtol = atol
/// = `tol`: run time per evaluation (the median run, repeated until `min_time` s), with a
/// fixed-size state and the right-hand side inline, or (`dynamic`) a dynamic-size state
/// and the right-hand side called out of line, as simulate runs a mechanism's. `made`:
/// the evaluations of one run.
[[nodiscard]] PerCall time_on_closed_form(const std::string& method, const Scenario& scenario, double tol,
                                          double min_time, bool dynamic, std::int64_t& made);

/// The oscillators' own cost per evaluation, on states along their motion.
[[nodiscard]] PerCall oscillators_rhs_ns(double min_batch);

}  // namespace linkage::bench
