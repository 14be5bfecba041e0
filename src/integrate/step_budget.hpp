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
#include "integrate/simulation.hpp"

namespace linkage {

/// The most steps a run may take: fixed-step runs are refused at it by validation,
/// adaptive ones are checked against it as they go.
inline constexpr double kMaxSteps = 1e9;
/// Steps between polls for Ctrl-C, progress reports and budget checks: milliseconds of work.
inline constexpr unsigned kCheckInterval = 4096;

/// "try A, B or C".
[[nodiscard]] std::string try_list(const std::vector<std::string>& options);

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
