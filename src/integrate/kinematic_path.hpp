#pragma once
// Kinematic analysis: when the drivers take every degree of freedom, nothing is
// integrated. At each time the positions solve C(q, t) = 0 (joints and drivers) by
// Newton's method from the last solution, continued over shorter steps where needed so
// the branch stays the one the start is on; the rates solve J q' = -C_t, and the case's
// own A u = B at (q, q') gives q'' (its constraint rows are the acceleration equations)
// and the multipliers: the drivers' torques and the joint forces. W, the work of drivers,
// dampers and loads, is the integral of their power along this exact path by Gauss-Legendre
// quadrature, halved until it agrees to round-off.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "symbolic/system.hpp"

namespace linkage {

class KinematicPath {
 public:
  /// `y`: the closed initial state (q, q', W = 0), refined here on C(q, 0) = 0. Throws
  /// Error::input when the start is a dead point.
  KinematicPath(const sym::System& system, const eval::MechanismDynamics& dynamics, Eigen::VectorXd& y);
  /// J, what the quadrature's round-off is relative to (default 1).
  void set_energy_scale(double scale) { energy_scale_ = scale > 0 ? scale : 1; }

  /// Moves y from the last time to t (not before it). Throws Error::input with one line when
  /// the mechanism cannot go on: a time at which the loops cannot close near the branch it
  /// is on, or a toggle where J turns singular.
  void advance(double t, Eigen::VectorXd& y);

  /// Continuation steps accepted and rejected, position solves.
  [[nodiscard]] std::int64_t accepted() const { return accepted_; }
  [[nodiscard]] std::int64_t rejected() const { return rejected_; }
  [[nodiscard]] std::int64_t solves() const { return solves_; }

 private:
  /// q at time t from (t0, y0) by the second-order predictor and Newton; false when Newton
  /// fails or its correction is not small against the predicted motion (another branch).
  bool solve_at(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& a0, double t, Eigen::VectorXd& y);
  /// y' at (t, y): the accelerations and the power.
  Eigen::VectorXd derivative(double t, const Eigen::VectorXd& y) const;
  /// q at t within a step accepted from (a, ya) to (b, yb), predicted by the cubic through
  /// their q and q'; false as solve_at().
  bool solve_between(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb, double t,
                     Eigen::VectorXd& y);
  /// The work done over the step from (a, ya) to (b, yb), halved until the quadrature agrees
  /// to round-off; nullopt when a point within cannot be solved (the step is then not taken).
  /// `whole`: the quadrature over the step at one level, when known already.
  std::optional<double> work(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb,
                             std::optional<double> whole, int depth);
  std::optional<double> gauss(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb);
  /// Stops the run where det J changes sign between (a, ya) and (b, yb): a change point
  /// (or any singular point) stepped over, found by bisection along the step.
  [[noreturn]] void crossed(double a, Eigen::VectorXd ya, double b, Eigen::VectorXd yb);
  /// links_in_line() at (t, y).
  [[nodiscard]] std::string in_line(double t, const Eigen::VectorXd& y) const;
  [[noreturn]] void stop(double t, const std::string& what) const;

  const sym::System* system_;
  const eval::MechanismDynamics* dynamics_;
  double energy_scale_ = 1;
  double t_ = 0, h_ = 0;
  Eigen::VectorXd dy_;  // y' at (t_, y)
  int sign_ = 0;        // the sign of det J at (t_, y)
  std::vector<double> nodes_, weights_;
  std::int64_t accepted_ = 0, rejected_ = 0, solves_ = 0;
};

/// "3 and 4 in line": the bodies joined by pins whose joint-to-joint lines (for a body on a
/// slider, its axis) are parallel at `pose` (per body x, y, theta), grouped; the nearest pair
/// when none is; "its links in line" when no body has a line. For a stop message.
[[nodiscard]] std::string links_in_line(const sym::System& system, const std::vector<double>& pose);

/// "cannot close beyond here (a limit position, 3 and 4 in line: J's smallest over largest
/// singular value S there", at (t, y): what driven_stop_message() says at a limit position
/// (the caller closes the parenthesis).
[[nodiscard]] std::string past_the_limit(const sym::System& system, const eval::MechanismDynamics& dynamics, double t,
                                         const Eigen::VectorXd& y);

/// "at t = T s driver 'M' at V rad: the loop through B WHAT; valid: ...": where a driven
/// mechanism cannot go on, for the one line that ends its run.
[[nodiscard]] std::string driven_stop_message(const sym::System& system, double t, const std::string& what);

}  // namespace linkage
