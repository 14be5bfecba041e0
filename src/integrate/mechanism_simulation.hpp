#pragma once
// The motion of any mechanism over time: one case's compiled equations
// (evaluate/mechanism_dynamics.hpp), one integrator, one stabilization, sampled at
// increasing times. The integrators are the homework's, on a state sized at run time.
// When the drivers take every degree of freedom nothing is integrated: the kinematic
// analysis of integrate/kinematic_path.hpp gives the states instead.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "columns/mechanism_columns.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "integrate/simulation_options.hpp"
#include "symbolic/system.hpp"

namespace linkage {

struct MechanismStats {
  std::int64_t steps_accepted = 0;
  std::int64_t steps_rejected = 0;
  std::int64_t rhs_evaluations = 0;
  double energy_scale = 0;          // J: T + |V - V_gravity| + sum m_i g (|y_i| + half-length_i), at t = 0
  double max_energy_error = 0;      // |E - E0 - W| / energy_scale over samples (W: work of dampers and loads)
  double max_constraint_error = 0;  // m (rad for a slider's angle), over samples and joints
  std::string drifted_joint;        // the joint of max_constraint_error ("" while it is 0)
  // A tree's kept constraints (Case 1) may drift, reported at the end; a loop that opens stops the run.
  bool drift_allowed = false;
  double size = 0;          // m: the longest body's length or radius (0 when no body has a size)
  std::string size_name;    // "body 1's length L", for the warning
  double wall_seconds = 0;  // in state_at()
  // What computed the equations, once for the summary: "compiled (built in)", "interpreted (...)".
  std::string evaluator;
  // The drivers take every degree of freedom: kinematic analysis, no integrator (the steps
  // count its continuation steps, the right-hand sides its position solves).
  bool kinematic = false;
};

class MechanismSimulation {
 public:
  /// `initial`: the generalized coordinates and rates with every loop closed
  /// (sym::close_loops). Validates the options; throws Error::input when the case's matrix
  /// is singular at the start, naming the case and its condition estimate. `derived`: the
  /// case already derived (eval::MechanismDynamics).
  MechanismSimulation(const sym::System& system, const GiNaC::exmap& initial, const SimulationOptions& options,
                      std::optional<CaseSystem> derived = {});
  ~MechanismSimulation();
  MechanismSimulation(MechanismSimulation&&) noexcept;
  MechanismSimulation& operator=(MechanismSimulation&&) noexcept;

  /// The state y = (q, q'[, W]) at t, for t non-decreasing and within [0, duration]. Throws
  /// Error::diverged naming the time, the case and what to try when the run cannot go on:
  /// a state that stops being finite, a matrix that turns singular (a dead point, a
  /// change point), a loop that opens.
  [[nodiscard]] const Eigen::VectorXd& state_at(double t);
  /// Everything a sample reports at (t, y) (with `kinematics`, the accelerations and the
  /// named points' motion too); updates the energy and constraint figures.
  void sample(double t, const Eigen::VectorXd& y, eval::MechanismSample& out, bool kinematics = false);

  void on_progress(std::function<void(double t)> report);
  [[nodiscard]] const eval::MechanismDynamics& dynamics() const;
  [[nodiscard]] const MechanismStats& stats() const;
  /// Kinetic plus potential energy at t = 0, J.
  [[nodiscard]] double energy0() const;
  /// What the error columns measure against: E, the scale, the momenta and G at t = 0.
  [[nodiscard]] const ColumnOrigin& origin() const;
  [[nodiscard]] const SimulationOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Right-hand sides from which `auto` compiles a mechanism that is not built in: the
/// compile (0.3 s for a four-bar, seconds for long chains, docs/performance.md) against
/// the saving of native code (0 to 60 ns per right-hand side measured): about 2 s / 50 ns.
inline constexpr double kCompileWorthEvaluations = 4e7;
/// Attaches native code to `dynamics` as `o.evaluator` asks (built in; else for compiled,
/// or auto on a run of kCompileWorthEvaluations or more, compiled at run time, a cached
/// entry used by auto too); what runs and why, one line. Throws Error::invalid about
/// "evaluator" when compiled cannot be.
[[nodiscard]] std::string choose_evaluator(eval::MechanismDynamics& dynamics, const SimulationOptions& o);

/// One line for the user when a finished run's figures say its numbers are meaningless
/// (the energy balance off by more than the energy scale, or a tree's joint drifted a
/// quarter of the longest body's size apart), empty when they are not.
[[nodiscard]] std::string mechanism_result_warning(const SimulationOptions& options, const MechanismStats& stats);

}  // namespace linkage
