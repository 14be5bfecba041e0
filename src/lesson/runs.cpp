#include "lesson/runs.hpp"

#include <algorithm>
#include <cmath>

#include "core/interrupt.hpp"

namespace linkage::lesson {

std::vector<double> sample_times(double duration, double every) {
  std::vector<double> times;
  const auto n = static_cast<long>(std::floor(duration / every * (1 + 1e-12)));
  times.reserve(static_cast<std::size_t>(n) + 2);
  for (long k = 0; k <= n; ++k) times.push_back(std::min(static_cast<double>(k) * every, duration));
  if (times.back() < duration) times.push_back(duration);
  return times;
}

SampledRun sample_run(const Run& run, double every, const std::vector<std::size_t>& series) {
  // A fixed-step run samples on its own step grid: a sample between grid points would
  // cost an extra short step and inflate the counts a compare table reports.
  const SimulationOptions& o = run.options;
  if (!info(o.integrator).adaptive) every = o.dt * std::max(1.0, std::round(every / o.dt));
  const std::vector<double> times = sample_times(o.duration, every);
  Simulation sim(run.inputs.params(), run.inputs.state(), o);
  const bool dynamics =
      std::any_of(series.begin(), series.end(), [](std::size_t i) { return kSeries[i].needs_dynamics; });
  SampledRun out;
  out.columns.assign(series.size(), {});
  for (auto& column : out.columns) column.reserve(times.size());
  SeriesOrigin origin;
  for (std::size_t k = 0; k < times.size(); ++k) {
    throw_if_interrupted();
    const BodyState s = sim.state_at(times[k]);
    if (k == 0) origin = SeriesOrigin::at(run.inputs.params(), s);
    Dynamics d;
    if (dynamics) d = sim.dynamics(s);
    for (std::size_t c = 0; c < series.size(); ++c)
      out.columns[c].push_back(series_value(series[c], origin, times[k], s, dynamics ? &d : nullptr));
    if (k + 1 == times.size()) out.final_state = s;
  }
  out.stats = sim.stats();
  return out;
}

State reference_final_state(const Run& run) {
  SimulationOptions o;
  o.case_id = 3;
  o.integrator = IntegratorKind::dop853;
  o.rtol = o.atol = kReferenceTolerance;
  o.duration = run.options.duration;
  Simulation sim(run.inputs.params(), run.inputs.state(), o);
  return sim.state_at(o.duration).generalized();
}

double final_error(const BodyState& a, const State& r) {
  return std::max(
      {std::fabs(a.x1 - r.x1), std::fabs(a.y1 - r.y1), std::fabs(a.theta1 - r.theta1), std::fabs(a.theta2 - r.theta2)});
}

}  // namespace linkage::lesson
