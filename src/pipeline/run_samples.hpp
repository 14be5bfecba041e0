#pragma once
// Running the simulations of plot and compare steps: sampling series along a run, and
// the reference a compare table measures final errors against.
#include <vector>

#include "integrate/mechanism_simulation.hpp"
#include "integrate/series.hpp"
#include "pipeline/run.hpp"

namespace linkage {

/// One run sampled at t = 0, every, 2 every, ... and exactly at its duration.
struct SampledRun {
  std::vector<std::vector<double>> columns;  // one per requested series, each one value per sample
  SimulationStats stats;
  BodyState final_state;
};

/// Runs `run` by the homework's own simulation, recording the series `series` (indices
/// into kSeries) every `every` s (for fixed-step integrators: the nearest whole number of
/// steps, at least one): a homework plot's centre of mass and invariant errors, which no
/// mechanism column has yet. Throws Error::diverged (exit 3) when the run fails.
[[nodiscard]] SampledRun sample_run(const Run& run, double every, const std::vector<std::size_t>& series);

/// The sample times of a run: 0, every, 2 every, ..., duration.
[[nodiscard]] std::vector<double> sample_times(double duration, double every);
/// The same on a fixed-step integrator's own grid (the nearest whole number of steps).
[[nodiscard]] std::vector<double> run_sample_times(const SimulationOptions& options, double every);
/// A mechanism run sampled at `times`: each column's values (as `linkage simulate
/// --mechanism` computes them), the run's figures and its last state y = (q, q', W).
struct MechanismSampledRun {
  std::vector<std::vector<double>> columns;
  MechanismStats stats;
  Eigen::VectorXd final_state;
};
/// Runs a mechanism run (run.built); Error::diverged when it fails or a value is not finite.
[[nodiscard]] MechanismSampledRun sample_mechanism_run(const Run& run, const std::vector<double>& times,
                                                       const std::vector<MechanismColumn>& columns);

/// The reference for final errors: DOP853 at rtol = atol = kReferenceTolerance on Case 3
/// (which cannot drift).
inline constexpr double kReferenceTolerance = 1e-13;

/// What a mechanism's final error compares: every body's x, y, theta and every slider's
/// travel (the default trajectory columns without t), the same in every case.
[[nodiscard]] std::vector<MechanismColumn> mechanism_final_columns(const sym::System& system);
/// Those columns at the end of the reference run (DOP853 at kReferenceTolerance on Case 3).
[[nodiscard]] std::vector<double> mechanism_reference_final(const Run& run);

}  // namespace linkage
