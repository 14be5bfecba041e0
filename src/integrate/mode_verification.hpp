#pragma once
// `linkage modes --verify`: the modes checked against the full equations. Each oscillating
// mode's shape, at a small amplitude, starts a run of the nonlinear mechanism from the
// equilibrium at rest (loops closed again); the modal coordinate's zero crossings over
// several periods give the frequency the motion has, to compare with the computed one.
#include <vector>

#include "formulations/linearization.hpp"
#include "symbolic/system.hpp"

namespace linkage {

struct ModeCheck {
  std::size_t mode = 0;  // into ModalAnalysis::modes
  double predicted = 0;  // rad/s: the crossings' frequency the modes give (damped_omega)
  double measured = 0;   // rad/s: 2 pi (crossings - 1) / (last - first upward crossing's time)
  int crossings = 0;     // upward
  double amplitude = 0;  // the largest coordinate's displacement at the start, rad or m
  [[nodiscard]] double relative_error() const { return std::fabs(measured / predicted - 1); }
};

/// One check per oscillating mode (neutral and unstable modes have no frequency to
/// check): DOP853 at rtol = atol = 1e-13 over `periods` periods, sampled 400 times a
/// period, the upward crossings interpolated linearly (third order at a crossing of a sine).
[[nodiscard]] std::vector<ModeCheck> verify_modes(const sym::System& system, const Linearization& linear,
                                                  const ModalAnalysis& modes, double amplitude = 1e-4,
                                                  int periods = 10);

}  // namespace linkage
