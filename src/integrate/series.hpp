#pragma once
// Quantities along a run, sampled over time: the coordinates, the centre of mass, the
// invariants and their errors. A lesson's plot and compare steps and `render --panel`
// draw them, with these words and units on their axes. Names follow
// `linkage simulate --columns` where both have the quantity.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "integrate/simulation.hpp"
#include "model/kinematics.hpp"

namespace linkage {

struct SeriesInfo {
  std::string_view name;   // e.g. "energy_error"
  std::string_view label;  // axis label in plot markup, e.g. "relative energy error |E − E_{0}| / E_{scale}"
  std::string_view unit;   // in plot markup, e.g. "m/s^{2}"; empty for pure numbers
  bool needs_dynamics;     // the accelerations or pin force: one extra solve per sample
};

inline constexpr std::array<SeriesInfo, 42> kSeries{{
    {"t", "time t", "s", false},
    {"x1", "x_{1}", "m", false},
    {"y1", "y_{1}", "m", false},
    {"theta1", "θ_{1}", "rad", false},
    {"theta2", "θ_{2}", "rad", false},
    {"x1_dot", "velocity ẋ_{1}", "m/s", false},
    {"y1_dot", "velocity ẏ_{1}", "m/s", false},
    {"theta1_dot", "angular velocity θ̇_{1}", "rad/s", false},
    {"theta2_dot", "angular velocity θ̇_{2}", "rad/s", false},
    {"x2", "x_{2}", "m", false},
    {"y2", "y_{2}", "m", false},
    {"x2_dot", "velocity ẋ_{2}", "m/s", false},
    {"y2_dot", "velocity ẏ_{2}", "m/s", false},
    {"x_P", "pin x_{P}", "m", false},
    {"y_P", "pin y_{P}", "m", false},
    {"x_com", "centre of mass x_{G}", "m", false},
    {"y_com", "centre of mass y_{G}", "m", false},
    {"x_com_dot", "centre of mass velocity ẋ_{G}", "m/s", false},
    {"y_com_dot", "centre of mass velocity ẏ_{G}", "m/s", false},
    {"x1_from_com", "x_{1} − x_{G}", "m", false},
    {"y1_from_com", "y_{1} − y_{G}", "m", false},
    {"com_parabola_error", "distance of G from the parabola G_{0} + v_{0} t − g t^{2}/2", "m", false},
    {"kinetic_energy", "kinetic energy T", "J", false},
    {"potential_energy", "potential energy V", "J", false},
    {"energy", "energy E = T + V", "J", false},
    {"energy_error", "relative energy error |E − E_{0}| / E_{scale}", "", false},
    {"momentum_x", "momentum p_{x}", "kg m/s", false},
    {"momentum_y", "momentum p_{y}", "kg m/s", false},
    {"momentum_x_error", "momentum error |p_{x} − p_{x0}|", "kg m/s", false},
    {"momentum_y_error", "momentum error |p_{y} − p_{y0} + 2 m g t|", "kg m/s", false},
    {"angular_momentum", "angular momentum H_{G}", "kg m^{2}/s", false},
    {"angular_momentum_error", "angular momentum error |H_{G} − H_{G0}|", "kg m^{2}/s", false},
    {"constraint_position_error", "constraint error |C|", "m", false},
    {"constraint_velocity_error", "constraint rate error |Ċ|", "m/s", false},
    {"x1_ddot", "acceleration ẍ_{1}", "m/s^{2}", true},
    {"y1_ddot", "acceleration ÿ_{1}", "m/s^{2}", true},
    {"theta1_ddot", "angular acceleration θ̈_{1}", "rad/s^{2}", true},
    {"theta2_ddot", "angular acceleration θ̈_{2}", "rad/s^{2}", true},
    {"x2_ddot", "acceleration ẍ_{2}", "m/s^{2}", true},
    {"y2_ddot", "acceleration ÿ_{2}", "m/s^{2}", true},
    {"F_x", "pin force F_{x}", "N", true},
    {"F_y", "pin force F_{y}", "N", true},
}};

[[nodiscard]] std::optional<std::size_t> find_series(std::string_view name);

/// What every sample of one run is measured against: the state at t = 0.
struct SeriesOrigin {
  Params params;
  double energy0 = 0, energy_scale = 1;
  Vec2 momentum0 = Vec2::Zero();
  double angular_momentum0 = 0;
  Vec2 com0 = Vec2::Zero(), com_velocity0 = Vec2::Zero();

  [[nodiscard]] static SeriesOrigin at(const Params& p, const BodyState& initial);
};

/// The value of series `index` at time t and state s; `dynamics` only for the series
/// that need it (nullptr otherwise).
[[nodiscard]] double series_value(std::size_t index, const SeriesOrigin& origin, double t, const BodyState& s,
                                  const Dynamics* dynamics);

/// "label (unit)" in plot markup, e.g. "constraint error |C| (m)".
[[nodiscard]] std::string series_axis_label(std::size_t index);

}  // namespace linkage
