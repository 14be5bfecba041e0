#include "pipeline/mode_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

/// "3 modes: 1 unstable, 2 oscillations", in their order (unstable first).
std::string modes_in_words(const ModalAnalysis& modes) {
  const std::size_t n = modes.modes.size();
  std::string words = std::to_string(n) + (n == 1 ? " mode" : " modes");
  const char* separator = ": ";
  for (const Mode::Kind kind : {Mode::Kind::unstable, Mode::Kind::neutral, Mode::Kind::oscillation}) {
    const auto count =
        std::count_if(modes.modes.begin(), modes.modes.end(), [&](const Mode& m) { return m.kind == kind; });
    if (count == 0) continue;
    words += separator + std::to_string(count) + " " + kind_word(kind) +
             (kind == Mode::Kind::oscillation && count > 1 ? "s" : "");
    separator = ", ";
  }
  return words;
}

}  // namespace

void check_amplitude(double amplitude) {
  if (!(amplitude > 0) || !std::isfinite(amplitude))
    throw Error::invalid("amplitude", format_significant(amplitude, 6) +
                                          "; valid: the largest coordinate's displacement, rad or m, > 0");
}

ModeMotion mode_motion(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes, int number,
                       double amplitude, bool nonlinear) {
  const int count = static_cast<int>(modes.modes.size());
  if (number < 1 || number > count)
    throw Error::invalid("mode", std::to_string(number) + " is out of range; " + system.mechanism().name + " has " +
                                     modes_in_words(modes) + "; valid: 1 to " + std::to_string(count));
  const Mode& mode = modes.modes[static_cast<std::size_t>(number - 1)];
  if (mode.kind != Mode::Kind::oscillation)
    throw Error::invalid("mode", std::to_string(number) + " is " + kind_word(mode.kind) + ", not an oscillation: " +
                                     (mode.kind == Mode::Kind::unstable ? "it grows from the equilibrium"
                                                                        : "it drifts without coming back") +
                                     ", so it has no frequency to show; " + modes_in_words(modes));
  check_amplitude(amplitude);
  Eigen::Index largest = 0;
  mode.tree_shape.cwiseAbs().maxCoeff(&largest);
  const double scale = amplitude / std::fabs(mode.tree_shape[largest]);
  ModeMotion out;
  out.equilibrium = linear.equilibrium;
  out.displacement = scale * mode.tree_shape;
  out.omega = mode.omega;
  out.damped_omega = mode.damped_omega;
  out.decay = mode.damping_ratio * mode.omega;
  const auto& coordinates = system.coordinates();
  GiNaC::exmap start;
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    const auto at = static_cast<Eigen::Index>(i);
    start[coordinates[i].symbols.q] = out.equilibrium[at] + out.displacement[at];
    start[coordinates[i].symbols.q_dot] = 0;
  }
  out.initial = sym::close_loops(system, start).state;
  const std::string unit = linear.tree_units[static_cast<std::size_t>(largest)];
  const std::string amount = format_significant(amplitude, 3) + " " + unit;
  const std::string hz = format_significant(mode.damped_omega / (2 * std::numbers::pi), 3) + " Hz";
  const std::string name = "mode " + std::to_string(number);
  out.hud = name + (nonlinear ? " \u00b7 nonlinear, A = " + amount : " \u00b7 linear, " + hz);
  out.caption =
      "Mode " + std::to_string(number) + " of " + std::to_string(count) + ", " + hz + " (" +
      format_significant(mode.damped_omega, 3) + " rad/s), amplitude " + amount + " in " +
      linear.tree_coordinates[static_cast<std::size_t>(largest)] + ": " +
      (nonlinear ? "the full equations started at rest on the mode" : "the linear motion about the equilibrium");
  if (!nonlinear) {
    // q = q0 + d exp(-decay t) cos(w t), q' its derivative.
    out.prescribed = [q0 = out.equilibrium, d = out.displacement, w = out.damped_omega, decay = out.decay](
                         double t, Eigen::VectorXd& y) {
      const auto n = q0.size();
      const double envelope = std::exp(-decay * t), c = std::cos(w * t), s = std::sin(w * t);
      y.head(n) = q0 + envelope * c * d;
      y.segment(n, n) = (envelope * (-decay * c - w * s)) * d;
    };
  }
  return out;
}

}  // namespace linkage
