#pragma once
// The homework on the general path: two-blocks.toml's Case 3 through the MechanismDynamics
// that simulate runs, native code attached as simulate's `auto` does (built in, so no
// compiler), as an integrator's f(t, y, dydt) on the mechanism's own state, as simulate
// integrates it: a dynamic-size column of the closed form's eight values (x1, y1, theta1,
// theta2, then their rates; nothing does work, so no W). No adapter copies the state in
// and out: what a run costs here is what simulate pays.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"
#include "evaluate/mechanism_dynamics.hpp"

namespace linkage::bench {

class GeneralCase3Rhs {
 public:
  /// The mechanism at `p`: derived and compiled once per distinct Params in the process,
  /// so a run's time holds its integration alone (after a first, untimed construction).
  explicit GeneralCase3Rhs(const Params& p);
  /// Inline, so an integrator calls MechanismDynamics::derivative as simulate's does.
  void operator()(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
    (void)dynamics_->derivative(t, y, dydt);  // a singular A gives NaN, which the study reports as a failure
  }
  /// The mechanism's state at the closed form's eight values.
  [[nodiscard]] Eigen::VectorXd state(const Vec<8>& y) const;
  /// What computes the equations, as simulate's summary says it: "compiled (built in)",
  /// or "interpreted (why)" when this program has no native code for it.
  [[nodiscard]] const std::string& evaluator() const;

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;
  const eval::MechanismDynamics* dynamics_ = nullptr;  // shared_'s
};

}  // namespace linkage::bench
