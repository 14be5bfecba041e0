#include "pipeline/run_samples.hpp"

#include <algorithm>
#include <cmath>

#include "core/interrupt.hpp"
#include "pipeline/simulate_rows.hpp"

namespace linkage {

std::vector<double> sample_times(double duration, double every) {
  std::vector<double> times;
  const auto n = static_cast<long>(std::floor(duration / every * (1 + 1e-12)));
  times.reserve(static_cast<std::size_t>(n) + 2);
  for (long k = 0; k <= n; ++k) times.push_back(std::min(static_cast<double>(k) * every, duration));
  if (times.back() < duration) times.push_back(duration);
  return times;
}

std::vector<double> run_sample_times(const SimulationOptions& o, double every) {
  // A fixed-step run samples on its own step grid: a sample between grid points would
  // cost an extra short step and inflate the counts a compare table reports.
  if (!info(o.integrator).adaptive) every = o.dt * std::max(1.0, std::round(every / o.dt));
  return sample_times(o.duration, every);
}

MechanismSampledRun sample_mechanism_run(const Run& run, const std::vector<double>& times,
                                         const std::vector<MechanismColumn>& columns) {
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  MechanismSampledRun out;
  out.columns.assign(columns.size(), {});
  for (auto& column : out.columns) column.reserve(times.size());
  eval::MechanismSample sample;
  std::vector<double> values;
  for (const double t : times) {
    throw_if_interrupted();
    const Eigen::VectorXd& y = sim.state_at(t);
    mechanism_row(sim, run.options.case_id, t, y, columns, sample, values);
    for (std::size_t j = 0; j < columns.size(); ++j) out.columns[j].push_back(values[j]);
    out.final_state = y;
  }
  out.stats = sim.stats();
  return out;
}

std::vector<MechanismColumn> mechanism_final_columns(const sym::System& system) {
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  std::vector<MechanismColumn> out;
  for (const sym::GeneralizedCoordinate& g : system.coordinates())
    out.push_back(find_mechanism_column(all, g.coordinate.key, "generalized coordinate"));
  return out;
}

std::vector<double> mechanism_reference_final(const Run& run) {
  Run reference = run;
  SimulationOptions& o = reference.options;
  o = SimulationOptions{};
  o.case_id = 3;
  o.integrator = IntegratorKind::dop853;
  o.rtol = o.atol = kReferenceTolerance;
  o.duration = run.options.duration;
  const MechanismSampledRun data =
      sample_mechanism_run(reference, {o.duration}, mechanism_final_columns(*run.built->system));
  std::vector<double> out;
  for (const auto& column : data.columns) out.push_back(column.back());
  return out;
}

}  // namespace linkage
