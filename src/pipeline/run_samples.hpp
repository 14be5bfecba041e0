#pragma once
// Running the simulations of plot and compare steps: sampling columns along a run, and
// the reference a compare table measures final errors against.
#include <vector>

#include "integrate/mechanism_simulation.hpp"
#include "pipeline/run.hpp"

namespace linkage {

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

/// What a mechanism's final error compares: its generalized coordinates (System::coordinates:
/// two-blocks' x1, y1, theta1, theta2; a slider's travel s), the same in every case.
[[nodiscard]] std::vector<MechanismColumn> mechanism_final_columns(const sym::System& system);
/// Those columns at the end of the reference run (DOP853 at kReferenceTolerance on Case 3).
[[nodiscard]] std::vector<double> mechanism_reference_final(const Run& run);

}  // namespace linkage
