#include "integrate/series.hpp"

#include <cmath>
#include <string>

namespace linkage {

std::optional<std::size_t> find_series(std::string_view name) {
  for (std::size_t i = 0; i < kSeries.size(); ++i)
    if (kSeries[i].name == name) return i;
  return std::nullopt;
}

SeriesOrigin SeriesOrigin::at(const Params& p, const BodyState& initial) {
  const Invariants inv = invariants(p, initial);
  SeriesOrigin o;
  o.params = p;
  o.energy0 = inv.energy;
  o.energy_scale = linkage::energy_scale(p, initial);
  o.momentum0 = inv.momentum;
  o.angular_momentum0 = inv.angular_momentum;
  o.com0 = system_com(initial);
  o.com_velocity0 = system_com_velocity(initial);
  return o;
}

double series_value(std::size_t index, const SeriesOrigin& o, double t, const BodyState& s, const Dynamics* d) {
  const Params& p = o.params;
  const std::string_view name = kSeries[index].name;
  // Coordinates and rates: no derived work.
  if (name == "t") return t;
  if (name == "x1") return s.x1;
  if (name == "y1") return s.y1;
  if (name == "theta1") return s.theta1;
  if (name == "theta2") return s.theta2;
  if (name == "x1_dot") return s.x1_dot;
  if (name == "y1_dot") return s.y1_dot;
  if (name == "theta1_dot") return s.theta1_dot;
  if (name == "theta2_dot") return s.theta2_dot;
  if (name == "x2") return s.x2;
  if (name == "y2") return s.y2;
  if (name == "x2_dot") return s.x2_dot;
  if (name == "y2_dot") return s.y2_dot;
  if (name == "x_P" || name == "y_P") {
    const Vec2 pin = pin_position(p, s.x1, s.y1, s.theta1);
    return name == "x_P" ? pin.x() : pin.y();
  }
  const Vec2 com = system_com(s);
  if (name == "x_com") return com.x();
  if (name == "y_com") return com.y();
  if (name == "x_com_dot") return system_com_velocity(s).x();
  if (name == "y_com_dot") return system_com_velocity(s).y();
  if (name == "x1_from_com") return s.x1 - com.x();
  if (name == "y1_from_com") return s.y1 - com.y();
  if (name == "com_parabola_error") {
    const Vec2 parabola = o.com0 + o.com_velocity0 * t + Vec2(0, -0.5 * p.g * t * t);
    return (com - parabola).norm();
  }
  if (name == "constraint_position_error" || name == "constraint_velocity_error") {
    const ConstraintError c = constraint_error(p, s);
    return name == "constraint_position_error" ? c.position.norm() : c.velocity.norm();
  }
  if (kSeries[index].needs_dynamics) {
    if (name == "x1_ddot") return d->x1_ddot;
    if (name == "y1_ddot") return d->y1_ddot;
    if (name == "theta1_ddot") return d->theta1_ddot;
    if (name == "theta2_ddot") return d->theta2_ddot;
    if (name == "x2_ddot") return d->x2_ddot;
    if (name == "y2_ddot") return d->y2_ddot;
    if (name == "F_x") return d->F_x;
    return d->F_y;
  }
  // The invariants.
  const Invariants inv = invariants(p, s);
  if (name == "kinetic_energy") return inv.kinetic_energy;
  if (name == "potential_energy") return inv.potential_energy;
  if (name == "energy") return inv.energy;
  if (name == "energy_error") return std::fabs(inv.energy - o.energy0) / o.energy_scale;
  if (name == "momentum_x") return inv.momentum.x();
  if (name == "momentum_y") return inv.momentum.y();
  if (name == "momentum_x_error") return std::fabs(inv.momentum.x() - o.momentum0.x());
  if (name == "momentum_y_error") return std::fabs(inv.momentum.y() - (o.momentum0.y() - 2 * p.m * p.g * t));
  if (name == "angular_momentum") return inv.angular_momentum;
  return std::fabs(inv.angular_momentum - o.angular_momentum0);  // angular_momentum_error
}

std::string series_axis_label(std::size_t index) {
  const SeriesInfo& info = kSeries[index];
  std::string label(info.label);
  if (!info.unit.empty()) label += " (" + std::string(info.unit) + ")";
  return label;
}

}  // namespace linkage
