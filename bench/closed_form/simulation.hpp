#pragma once
// The homework's motion over time by its closed form: one case's equations, one
// integrator, one stabilization, sampled at increasing times (the bench's stress study;
// the program runs every mechanism, the homework too, by integrate/mechanism_simulation).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"
#include "integrate/simulation_options.hpp"

namespace linkage {

struct SimulationStats {
  std::int64_t steps_accepted = 0;
  std::int64_t steps_rejected = 0;
  std::int64_t rhs_evaluations = 0;
  std::int64_t force_evaluations = 0;  // pin-force solves done for output/drawing
  double energy_scale = 0;             // J, kinematics.hpp energy_scale at the start
  double max_energy_error = 0;         // |E - E0| / energy_scale, over samples
  double max_constraint_error = 0;     // m, |C| over samples (Case 1)
  double wall_seconds = 0;             // time spent in state_at() and dynamics()
};

/// Accelerations and pin force at a state, from the selected case's equations.
struct Dynamics {
  double x1_ddot = 0, y1_ddot = 0, theta1_ddot = 0, x2_ddot = 0, y2_ddot = 0, theta2_ddot = 0;
  double F_x = 0, F_y = 0;
};

class Simulation {
 public:
  Simulation(const Params& params, const State& initial, const SimulationOptions& options);
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  /// The state at time t, for t non-decreasing across calls and within [0, duration].
  /// Adaptive methods step past t and interpolate by dense output; they never shorten a
  /// step to hit t. Throws Error::diverged (exit 3) naming the time, the step size and
  /// what to try when the state stops being finite, the step underflows, Newton fails,
  /// or adaptive steps would need more than 1e9 steps to reach the duration. stats()
  /// counts the work done either way.
  [[nodiscard]] BodyState state_at(double t);

  /// Calls `report(t)` with the integrator's time every few thousand steps, so a caller
  /// can show progress within one long state_at().
  void on_progress(std::function<void(double t)> report);

  /// Accelerations and pin force at a state (counts a force evaluation). With
  /// Baumgarte stabilization they include its correction, as integrated.
  [[nodiscard]] Dynamics dynamics(const BodyState& state);

  [[nodiscard]] const SimulationStats& stats() const;
  [[nodiscard]] const Params& params() const;
  [[nodiscard]] const SimulationOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One line for the user when a finished run's figures say its numbers are meaningless
/// (an energy error far beyond the energy scale, a pin drifting by a good part of a
/// block), naming the figure and what to try; empty when they are not. Neutral wording:
/// settings by name ("dt", "rtol"), never a flag.
[[nodiscard]] std::string result_warning(const SimulationOptions& options, const Params& params,
                                         const SimulationStats& stats);

}  // namespace linkage
