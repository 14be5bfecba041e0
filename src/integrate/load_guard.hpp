#pragma once
// The loads and spring/damper values that change during a run (they read the state or t):
// sym::validate_quantities checks them at the start only, so a value that turns
// non-finite, or a stiffness or damping that turns negative, later in the run is caught
// here, at the states the integrator reaches, and stops the run with one line.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "model/mechanism.hpp"
#include "symbolic/system.hpp"

namespace linkage {

class LoadGuard {
 public:
  LoadGuard(const sym::System& system, const eval::MechanismDynamics& dynamics);

  /// The one line for the first guarded value out of its range at (t, y) ("FILE:LINE:COLUMN:
  /// stiffness of spring k1 \"...\" is -2 at t = 0.4 s; valid: >= 0 ..."), empty when none is.
  [[nodiscard]] std::string check(double t, const Eigen::VectorXd& y);
  /// Throws Error::input with check()'s line when there is one.
  void require(double t, const Eigen::VectorXd& y);
  /// Nothing changes during a run: nothing to check.
  [[nodiscard]] bool empty() const { return values_.empty(); }

 private:
  struct Value {
    std::string what;  // "stiffness of spring k1", as the start's checks name it
    const Quantity* quantity;
    bool non_negative;
  };
  const eval::MechanismDynamics* dynamics_;
  std::vector<Value> values_;
  eval::Program program_;
  std::vector<double> out_, scratch_;
};

}  // namespace linkage
