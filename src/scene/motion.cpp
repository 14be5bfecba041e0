#include "scene/motion.hpp"

#include <algorithm>
#include <cmath>

#include "model/kinematics.hpp"

namespace linkage {

void Motion::set_energy_reference(const Params& p, const BodyState& initial) {
  energy0 = invariants(p, initial).energy;
  energy_scale = linkage::energy_scale(p, initial);
}

std::array<Vec2, 4> block_corners(const Params& p, double x, double y, double theta) {
  const Vec2 c(x, y);
  const Vec2 along = 0.5 * p.L * Vec2(std::cos(theta), std::sin(theta));
  const Vec2 across = 0.5 * p.w * Vec2(-std::sin(theta), std::cos(theta));
  return {c + along - across, c + along + across, c - along + across, c - along - across};
}

Bounds motion_bounds(const Params& p, const Motion& motion) {
  Bounds bounds;
  for (const MotionSample& sample : motion.samples) {
    const BodyState& s = sample.state;
    for (const Vec2& c : block_corners(p, s.x1, s.y1, s.theta1)) bounds.include(c);
    for (const Vec2& c : block_corners(p, s.x2, s.y2, s.theta2)) bounds.include(c);
  }
  return bounds;
}

double max_radius_about_com(const Params& p, const Motion& motion) {
  double radius = 0;
  for (const MotionSample& sample : motion.samples) {
    const BodyState& s = sample.state;
    const Vec2 g = system_com(s);
    for (const Vec2& c : block_corners(p, s.x1, s.y1, s.theta1)) radius = std::max(radius, (c - g).norm());
    for (const Vec2& c : block_corners(p, s.x2, s.y2, s.theta2)) radius = std::max(radius, (c - g).norm());
  }
  return radius;
}

std::array<double, kArrowKinds> arrow_maxima(const Params& p, const Motion& motion, bool relative_to_com) {
  std::array<double, kArrowKinds> maxima{};
  maxima[static_cast<std::size_t>(ArrowKind::gravity)] = motion.samples.empty() ? 0.0 : p.m * p.g;
  for (const MotionSample& sample : motion.samples) {
    const BodyState& s = sample.state;
    const Vec2 frame_velocity = relative_to_com ? system_com_velocity(s) : Vec2::Zero();
    const double v1 = (Vec2(s.x1_dot, s.y1_dot) - frame_velocity).norm();
    const double v2 = (Vec2(s.x2_dot, s.y2_dot) - frame_velocity).norm();
    double& pin = maxima[static_cast<std::size_t>(ArrowKind::pin_force)];
    double& velocity = maxima[static_cast<std::size_t>(ArrowKind::velocity)];
    if (motion.has_pin_force) pin = std::max(pin, sample.pin_force.norm());
    velocity = std::max({velocity, v1, v2});
  }
  return maxima;
}

SampleErrors sample_errors(const Params& p, const Motion& motion, std::size_t index) {
  const BodyState& s = motion.samples[index].state;
  SampleErrors errors;
  errors.energy = (invariants(p, s).energy - motion.energy0) / motion.energy_scale;
  errors.constraint = constraint_error(p, s).position.norm();
  return errors;
}

}  // namespace linkage
