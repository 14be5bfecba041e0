#include "integrate/step_budget.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_format.hpp"

namespace linkage {

std::string try_list(const std::vector<std::string>& options) {
  std::string text = "try ";
  for (std::size_t i = 0; i < options.size(); ++i)
    text += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + options[i];
  return text;
}

std::string meaningless_run_warning(const SimulationOptions& o, const std::string& energy, const std::string& drift) {
  if (energy.empty() && drift.empty()) return "";
  std::vector<std::string> remedies;
  if (!drift.empty()) {
    if (o.stabilization != Stabilization::projection) remedies.emplace_back("stabilization by projection");
    remedies.emplace_back("Case 3 (it cannot drift)");
  }
  if (!info(o.integrator).adaptive) {
    remedies.emplace_back("a smaller step dt");
    remedies.emplace_back("an adaptive integrator (dop853)");
  } else if (o.rtol > 1e-12 || o.atol > 1e-12) {
    remedies.emplace_back("a tighter rtol/atol");
  } else {
    remedies.emplace_back("a shorter duration");
  }
  return "the run's numbers do not describe the motion: " + (energy.empty() ? drift : energy) +
         (!energy.empty() && !drift.empty() ? " and " + drift : "") + "; " + try_list(remedies);
}

std::string failed_step_hint(const SimulationOptions& o, bool kept, ode::StepStatus status, double t, double h) {
  std::vector<std::string> options;
  if (status == ode::StepStatus::newton_failed) {
    options = {"a smaller step dt", "an explicit integrator (dop853)"};
  } else if (!info(o.integrator).adaptive) {
    options = {"a smaller step dt", "an adaptive integrator (dop853)"};
    // gains well beyond 1/dt make the stabilization itself the unstable part
    if (kept && o.stabilization == Stabilization::baumgarte && std::max(o.baumgarte_alpha, o.baumgarte_beta) * h > 1)
      options.emplace_back("smaller Baumgarte gains");
  } else {
    // the controller wants ever smaller steps: tolerances at round-off of the state, or
    // equations that need something other than an explicit method's steps
    if (o.rtol < 1e-6 || o.atol < 1e-6) options.emplace_back("a looser rtol/atol");
    if (o.case_id != 3) options.emplace_back("Case 3");
  }
  if (kept && o.stabilization != Stabilization::projection) options.emplace_back("stabilization by projection");
  if (options.empty())
    options.push_back(t > 0 ? "a duration under " + format_significant(t, 3) + " s" : "gentler initial conditions");
  return try_list(options);
}

std::optional<StepBudget::Overrun> StepBudget::check(double t, std::int64_t steps, const SimulationOptions& o) {
  const double then = checked_at_[next_check_ % kBudgetIntervals];  // kBudgetIntervals checks ago
  checked_at_[next_check_++ % kBudgetIntervals] = t;
  if (next_check_ < kBudgetIntervals) return std::nullopt;
  const auto taken = static_cast<double>(steps);
  const double mean_step = (t - then) / (kBudgetIntervals * kCheckInterval);
  const double needed = taken + std::max(0.0, o.duration - t) / mean_step;
  if (!(needed > kMaxSteps)) return std::nullopt;
  Overrun out;
  std::vector<std::string> remedies;
  // Smooth steps grow about as tol^(1 / order); steps held down by round-off (far below
  // the run's mean so far) grow much faster with a looser tolerance.
  const double rtol = o.rtol * std::pow(needed / kMaxSteps, info(o.integrator).order);
  if (mean_step < 1e-3 * t / taken && (o.rtol < 1e-6 || o.atol < 1e-6))
    remedies.emplace_back("a looser rtol/atol");
  else if (rtol <= 1e-6)
    remedies.push_back("an rtol/atol of " + format_significant(rtol, 1) + " or looser");
  remedies.push_back("a duration under " + format_significant(t + (kMaxSteps - taken) * mean_step, 2) + " s");
  out.hint = try_list(remedies);
  out.what = "at its recent steps (" + format_significant(mean_step, 2) + " s on average) it needs about " +
             format_significant(needed, 2) + " steps to reach " + format_significant(o.duration, 6) +
             " s, more than the limit of " + format_significant(kMaxSteps, 1);
  return out;
}

}  // namespace linkage
