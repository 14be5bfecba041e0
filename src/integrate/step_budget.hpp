#pragma once
// The step budget of an adaptive run: one rule for the homework's runs and a mechanism
// file's, so a run that cannot finish ends with a one-line error instead of grinding on.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "integrate/ode.hpp"
#include "integrate/simulation_options.hpp"

namespace linkage {

/// The most steps a run may take: fixed-step runs are refused at it by validation,
/// adaptive ones are checked against it as they go.
inline constexpr double kMaxSteps = 1e9;
/// Steps between polls for Ctrl-C, progress reports and budget checks: milliseconds of work.
inline constexpr unsigned kCheckInterval = 4096;

/// "try A, B or C".
[[nodiscard]] std::string try_list(const std::vector<std::string>& options);

// Past these a finished run's numbers no longer describe the motion. An energy error of
// 1 is a run that made or lost as much energy as the energy scale holds: every velocity
// is off by a factor, not a digit (the shipped lessons' deliberately poor runs stay below
// 0.3). A joint a quarter of the longest body (the homework's block length L) apart draws
// the bodies visibly apart, its force acting at two points that far apart: it is no
// longer the linkage (the drift lesson shows 0.13 L on purpose).
inline constexpr double kMeaninglessEnergyError = 1.0;
inline constexpr double kMeaninglessDrift = 0.25;  // of the longest body's size

/// The warning for a finished run whose numbers mean nothing: `energy` and `drift` say
/// what went wrong ("the energy ... reached 3 times the energy scale (2 J)", "joint P came
/// 1.2 m apart (...)"), empty when that is within bounds; "" when both are.
[[nodiscard]] std::string meaningless_run_warning(const SimulationOptions& o, const std::string& energy,
                                                  const std::string& drift);

/// What might change the outcome of a step that failed at t with step h, never the case
/// or integrator in use: "try A, B or C". `kept`: the case keeps constraint rows (they can
/// be stabilized).
[[nodiscard]] std::string failed_step_hint(const SimulationOptions& o, bool kept, ode::StepStatus status, double t,
                                           double h);

/// The floor under adaptive steps, relative to t and the duration: at the mean step of the
/// last kBudgetIntervals x kCheckInterval steps, the run must reach its end within
/// kMaxSteps steps in all (from a quarter of an hour of DOP853 steps to hours), else it
/// ends now instead of grinding for hours and then, often, underflowing (1e8 rad/s did,
/// after 6e7 steps). A physical time scale (the spin period, sqrt(L / g)) was measured and
/// rejected as the floor: at angles of 1e7 rad and more, round-off in the angle holds the
/// step near 1e-7 of the spin period for thousands of steps, and such runs still end well.
/// The long window lets such dips pass.
class StepBudget {
 public:
  struct Overrun {
    std::string what;  // "at its recent steps (...) it needs about ... steps ..."
    std::string hint;  // "try A or B"
  };

  /// Call every kCheckInterval accepted steps, at time t after `steps` accepted steps.
  [[nodiscard]] std::optional<Overrun> check(double t, std::int64_t steps, const SimulationOptions& o);

 private:
  static constexpr std::size_t kBudgetIntervals = 16;
  std::array<double, kBudgetIntervals> checked_at_{};  // t at the last checks (and 0 at the start)
  std::size_t next_check_ = 0;
};

}  // namespace linkage
