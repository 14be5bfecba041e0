#include "bench/closed_form/kinematics.hpp"

#include <cmath>

namespace linkage {

Vec2 pin_position(const Params& p, double x1, double y1, double theta1) {
  const double D = p.pin_offset();
  return {x1 + D * std::cos(theta1), y1 + D * std::sin(theta1)};
}

BodyState body_state(const Params& p, const State& s) {
  const double D = p.pin_offset();
  const double c1 = std::cos(s.theta1), s1 = std::sin(s.theta1);
  const double c2 = std::cos(s.theta2), s2 = std::sin(s.theta2);
  BodyState b;
  b.x1 = s.x1;
  b.y1 = s.y1;
  b.theta1 = s.theta1;
  b.theta2 = s.theta2;
  b.x2 = s.x1 + D * (c1 + c2);
  b.y2 = s.y1 + D * (s1 + s2);
  b.x1_dot = s.x1_dot;
  b.y1_dot = s.y1_dot;
  b.theta1_dot = s.theta1_dot;
  b.theta2_dot = s.theta2_dot;
  b.x2_dot = s.x1_dot - D * (s.theta1_dot * s1 + s.theta2_dot * s2);
  b.y2_dot = s.y1_dot + D * (s.theta1_dot * c1 + s.theta2_dot * c2);
  return b;
}

Invariants invariants(const Params& p, const BodyState& s) {
  const double I = p.inertia_centroidal();
  Invariants r;
  r.kinetic_energy =
      0.5 * p.m * (s.x1_dot * s.x1_dot + s.y1_dot * s.y1_dot + s.x2_dot * s.x2_dot + s.y2_dot * s.y2_dot) +
      0.5 * I * (s.theta1_dot * s.theta1_dot + s.theta2_dot * s.theta2_dot);
  r.potential_energy = p.m * p.g * (s.y1 + s.y2);
  r.energy = r.kinetic_energy + r.potential_energy;
  r.momentum = {p.m * (s.x1_dot + s.x2_dot), p.m * (s.y1_dot + s.y2_dot)};
  const double dx = s.x2 - s.x1, dy = s.y2 - s.y1;
  const double dvx = s.x2_dot - s.x1_dot, dvy = s.y2_dot - s.y1_dot;
  r.angular_momentum = 0.5 * p.m * (dx * dvy - dy * dvx) + I * (s.theta1_dot + s.theta2_dot);
  return r;
}

Vec2 system_com(const BodyState& s) { return {0.5 * (s.x1 + s.x2), 0.5 * (s.y1 + s.y2)}; }
Vec2 system_com_velocity(const BodyState& s) { return {0.5 * (s.x1_dot + s.x2_dot), 0.5 * (s.y1_dot + s.y2_dot)}; }

ConstraintError constraint_error(const Params& p, const BodyState& s) {
  const double D = p.pin_offset();
  const double c1 = std::cos(s.theta1), s1 = std::sin(s.theta1);
  const double c2 = std::cos(s.theta2), s2 = std::sin(s.theta2);
  ConstraintError e;
  e.position = {s.x2 - s.x1 - D * (c1 + c2), s.y2 - s.y1 - D * (s1 + s2)};
  e.velocity = {s.x2_dot - s.x1_dot + D * (s.theta1_dot * s1 + s.theta2_dot * s2),
                s.y2_dot - s.y1_dot - D * (s.theta1_dot * c1 + s.theta2_dot * c2)};
  return e;
}

Derived derive(const Params& p, const State& s) {
  Derived d;
  d.I_zz_C = p.inertia_centroidal();
  d.D = p.pin_offset();
  d.I_zz_P = p.inertia_about_pin();
  d.pin = pin_position(p, s.x1, s.y1, s.theta1);
  const BodyState b = body_state(p, s);
  d.C2 = {b.x2, b.y2};
  d.C2_dot = {b.x2_dot, b.y2_dot};
  d.invariants = invariants(p, b);
  return d;
}

double energy_scale(const Params& p, const BodyState& s) {
  const Invariants inv = invariants(p, s);
  return inv.kinetic_energy + p.m * p.g * (std::fabs(s.y1) + std::fabs(s.y2) + p.L);
}

}  // namespace linkage
