#pragma once
// A mode of small vibration drawn (`linkage render --mode`, issue 26): the linear motion
// about the equilibrium, prescribed rather than integrated, or the full equations started
// at rest on the equilibrium displaced along the mode (`nonlinear`).
#include <ginac/ginac.h>

#include <Eigen/Core>
#include <functional>
#include <string>

#include "formulations/linearization.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// The state a clip draws at t instead of its simulation's: the tree coordinates q (the
/// first entries of y) and their rates q' (the next ones); the rest of y is left as is.
using PrescribedState = std::function<void(double t, Eigen::VectorXd& y)>;

struct ModeMotion {
  GiNaC::exmap initial;          // the displaced equilibrium, at rest, loops closed again
  PrescribedState prescribed;    // the linear motion; empty for the nonlinear one
  Eigen::VectorXd equilibrium;   // q0, every tree coordinate
  Eigen::VectorXd displacement;  // A' tree_shape: the largest entry's size is the amplitude
  double omega = 0;              // rad/s of the undamped mode
  double damped_omega = 0;       // rad/s: the motion's
  double decay = 0;              // 1/s: zeta omega, the linear motion's envelope exp(-decay t)
  std::string hud;               // "mode 1 · linear, 0.819 Hz"
  std::string caption;           // the default caption: the mode, its frequency and amplitude
};

/// Error::invalid("amplitude", ...) unless `amplitude` (a mode's largest tree coordinate's
/// displacement, rad or m) is finite and > 0.
void check_amplitude(double amplitude);

/// Mode `number` (from 1, as `linkage modes` numbers them) of `modes` at `amplitude` (the
/// largest tree coordinate's displacement, rad or m). Error::invalid("mode", ...) for a
/// number out of range or a mode that does not oscillate, ("amplitude", ...) for an
/// amplitude not finite and > 0.
[[nodiscard]] ModeMotion mode_motion(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     int number, double amplitude, bool nonlinear);

}  // namespace linkage
