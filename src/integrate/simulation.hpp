#pragma once
// The motion over time: one case's equations, one integrator, one stabilization,
// sampled at increasing times. This is the seam every consumer uses (simulate, render,
// lesson, bench); integrators themselves know nothing about the linkage.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "model/kinematics.hpp"
#include "model/params.hpp"
#include "model/state.hpp"

namespace linkage {

enum class IntegratorKind { euler, symplectic_euler, rk4, dopri5, dop853, gauss2 };
enum class Stabilization { none, baumgarte, projection };

struct IntegratorInfo {
  IntegratorKind kind;
  std::string_view name;  // CLI spelling, e.g. "dop853"
  std::string_view description;
  bool adaptive;
  int order;
};
/// Every integrator, in the order the help lists them.
[[nodiscard]] const std::array<IntegratorInfo, 6>& integrators();
[[nodiscard]] const IntegratorInfo& info(IntegratorKind kind);
/// Parses a CLI spelling; throws Error::input naming `origin` and the valid names.
[[nodiscard]] IntegratorKind parse_integrator(std::string_view name, const std::string& origin);
[[nodiscard]] Stabilization parse_stabilization(std::string_view name, const std::string& origin);
[[nodiscard]] std::string_view name(Stabilization s);

struct SimulationOptions {
  int case_id = 3;  // 1, 2 or 3
  IntegratorKind integrator = IntegratorKind::dop853;
  double dt = 1e-3;                   // s: fixed step, or first step of adaptive methods
  double rtol = 1e-10, atol = 1e-10;  // adaptive error control
  double duration = 10.0;             // s
  Stabilization stabilization = Stabilization::none;
  // Baumgarte asks C'' + 2 alpha C' + beta^2 C = 0 of the pin constraint C (Case 1).
  // alpha = beta is critical damping: a violation decays like (1 + 10 t) e^(-10 t), in
  // about half a second, while the gains stay small enough (10/s) that explicit steps
  // up to ~0.1 s remain stable.
  double baumgarte_alpha = 10.0;  // 1/s, damping of the constraint error rate
  double baumgarte_beta = 10.0;   // 1/s, stiffness of the constraint error
  /// Validates ranges; throws Error::invalid about the setting (e.g. "dt") with its range.
  void validate() const;
};

/// The options that are numbers, by the name a lesson's run key and (with '-' for '_')
/// a flag give them, with their unit: one table for both.
struct NumberOption {
  std::string_view name;
  double SimulationOptions::*field;
  std::string_view unit;
};
inline constexpr std::array<NumberOption, 6> kNumberOptions{{
    {"dt", &SimulationOptions::dt, "s"},
    {"rtol", &SimulationOptions::rtol, ""},
    {"atol", &SimulationOptions::atol, ""},
    {"duration", &SimulationOptions::duration, "s"},
    {"baumgarte_alpha", &SimulationOptions::baumgarte_alpha, "1/s"},
    {"baumgarte_beta", &SimulationOptions::baumgarte_beta, "1/s"},
}};

struct SimulationStats {
  std::int64_t steps_accepted = 0;
  std::int64_t steps_rejected = 0;
  std::int64_t rhs_evaluations = 0;
  std::int64_t force_evaluations = 0;  // pin-force solves done for output/drawing
  double energy_scale = 0;             // J, model/kinematics energy_scale at the start
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
