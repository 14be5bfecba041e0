#pragma once
// Running the simulations of plot and compare steps: sampling series along a run, and
// the reference a compare table measures final errors against.
#include <cstdint>
#include <vector>

#include "integrate/series.hpp"
#include "lesson/lesson.hpp"

namespace linkage::lesson {

/// One run sampled at t = 0, every, 2 every, ... and exactly at its duration.
struct SampledRun {
  std::vector<std::vector<double>> columns;  // one per requested series, each one value per sample
  SimulationStats stats;
  BodyState final_state;
};

/// Runs `run`, recording the series `series` (indices into kSeries) every `every` s
/// (for fixed-step integrators: the nearest whole number of steps, at least one).
/// Throws Error::diverged (exit 3) when the run fails.
[[nodiscard]] SampledRun sample_run(const Run& run, double every, const std::vector<std::size_t>& series);

/// The sample times of a run: 0, every, 2 every, ..., duration.
[[nodiscard]] std::vector<double> sample_times(double duration, double every);

/// The figures of one run in a compare table.
struct RunFigures {
  double final_error = 0;       // largest |error| of x1, y1, theta1, theta2 at the end (m or rad)
  double energy_error = 0;      // largest relative energy error over the samples
  double constraint_error = 0;  // largest |C| over the samples, m
  std::int64_t steps = 0, rejected = 0, rhs_evaluations = 0;
  double run_time = 0;  // s
};

/// The reference for final errors: DOP853 at rtol = atol = kReferenceTolerance on Case 3
/// (which cannot drift), for the run's inputs and duration.
[[nodiscard]] State reference_final_state(const Run& run);
inline constexpr double kReferenceTolerance = 1e-13;

/// Largest |a - b| over x1, y1, theta1, theta2.
[[nodiscard]] double final_error(const BodyState& a, const State& reference);

}  // namespace linkage::lesson
