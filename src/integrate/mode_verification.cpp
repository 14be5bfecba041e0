#include "integrate/mode_verification.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {

std::vector<ModeCheck> verify_modes(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                    double amplitude, int periods) {
  constexpr int kSamplesPerPeriod = 400;
  std::vector<ModeCheck> checks;
  const auto& coordinates = system.coordinates();
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const Mode& mode = modes.modes[k];
    if (mode.kind != Mode::Kind::oscillation) continue;
    ModeCheck check;
    check.mode = k;
    check.predicted = mode.damped_omega;
    check.amplitude = amplitude;
    // The equilibrium moved along the shape, the largest tree coordinate by `amplitude`.
    const double scale = amplitude / mode.tree_shape.cwiseAbs().maxCoeff();
    GiNaC::exmap start;
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
      const auto at = static_cast<Eigen::Index>(i);
      start[coordinates[i].symbols.q] = linear.equilibrium[at] + scale * mode.tree_shape[at];
      start[coordinates[i].symbols.q_dot] = 0;
    }
    const GiNaC::exmap closed = sym::close_loops(system, start).state;
    const double period = 2 * std::numbers::pi / check.predicted;
    SimulationOptions options;
    options.integrator = IntegratorKind::dop853;
    options.rtol = options.atol = 1e-13;
    options.duration = periods * period;
    MechanismSimulation simulation(system, closed, options);
    // The modal coordinate: the shape's M-weighted share of the independent coordinates' motion.
    const Eigen::RowVectorXd weight = mode.shape.transpose() * linear.M;
    const auto modal = [&](const Eigen::VectorXd& y) {
      double sum = 0;
      for (std::size_t c = 0; c < linear.independent.size(); ++c) {
        const auto i = static_cast<Eigen::Index>(linear.independent[c]);
        sum += weight[static_cast<Eigen::Index>(c)] * (y[i] - linear.equilibrium[i]);
      }
      return sum;
    };
    // Crossings one way only (upward), a period apart: a cubic term in the potential moves
    // the motion's centre by O(amplitude^2), which shifts the upward and downward crossings
    // opposite ways; over whole periods it cancels.
    const int samples = periods * kSamplesPerPeriod;
    double t_prev = 0, eta_prev = modal(simulation.state_at(0));
    double first = 0, last = 0;
    for (int s = 1; s <= samples; ++s) {
      const double t = options.duration * s / samples;
      const double eta = modal(simulation.state_at(t));
      if (eta_prev < 0 && eta >= 0) {
        const double crossing = t_prev + (t - t_prev) * eta_prev / (eta_prev - eta);
        if (check.crossings == 0) first = crossing;
        last = crossing;
        ++check.crossings;
      }
      t_prev = t;
      eta_prev = eta;
    }
    if (check.crossings < 2)
      throw Error::diverged("modes --verify: mode " + std::to_string(k + 1) + " crossed its equilibrium upwards " +
                            std::to_string(check.crossings) + " times in " + std::to_string(periods) +
                            " of its periods; the motion is not the mode's");
    check.measured = 2 * std::numbers::pi * (check.crossings - 1) / (last - first);
    checks.push_back(check);
  }
  return checks;
}

}  // namespace linkage
