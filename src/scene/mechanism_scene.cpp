#include "scene/mechanism_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"
#include "symbolic/joints.hpp"
#include "symbolic/spelling.hpp"

namespace linkage {
namespace {

constexpr int kDiscSides = 48;
constexpr int kCapSides = 8;               // per round end of a rod
constexpr int kSpringTurns = 8;            // fixed, so the coil visibly stretches and compresses
constexpr double kApart = 0.5;             // the free-body view's spread, of each centre's distance from the centroid
constexpr double kTypicalShare = 1.0 / 6;  // a typical frame's largest force arrow, of the extent
constexpr double kCapFactor = 1.5;         // arrows longer than this times the typical are cut
// "Typical": the upper quartile. The 90th percentile is still a peak for a four-bar
// (9 N against a median of 2.3 N), which would leave most frames' arrows stubs.
constexpr double kTypicalQuantile = 0.75;
constexpr double kTypicalSweep = 1.25 * std::numbers::pi;  // a typical torque's arc
constexpr double kLongestSweep = 1.75 * std::numbers::pi;

double number(const sym::System& system, const GiNaC::ex& e) {
  return sym::to_double(e.subs(system.constants()).subs(system.constants()).subs(system.parameter_values()));
}

double number(const sym::System& system, const std::optional<Quantity>& q) {
  return q ? number(system, system.quantity(*q, false)) : 0.0;
}

// A spring's damping for the drawing (damped or not): 1 when it depends on the state.
double damping_of(const sym::System& system, const Quantity& q) {
  const GiNaC::ex c = system.quantity(q, false, true);
  return system.depends_on_state(c) ? (c.is_zero() ? 0.0 : 1.0) : number(system, c);
}

Vec2 vector_of(const sym::System& system, const sym::Vec2& v) { return {number(system, v.x), number(system, v.y)}; }

Vec2 rotated(double theta, const Vec2& v) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

BodyPoint point_of(const sym::System& system, const std::string& body, const std::string& point) {
  const int index = system.mechanism().body_index(body);
  if (index < 0) return {-1, vector_of(system, system.point_position(-1, point))};
  return {index, vector_of(system, system.bodies()[static_cast<std::size_t>(index)].points.at(point))};
}

// The value below which `quantile` of `values` lie (by rank); 0 for none.
double quantile_of(std::vector<double> values, double quantile) {
  if (values.empty()) return 0;
  const auto rank = static_cast<std::ptrdiff_t>(std::floor(quantile * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + rank, values.end());
  return values[static_cast<std::size_t>(rank)];
}

// A typical positive magnitude: the quantile, or the largest when most are zero.
double typical_of(const std::vector<double>& values) {
  const double typical = quantile_of(values, kTypicalQuantile);
  return typical > 0 ? typical : (values.empty() ? 0 : *std::max_element(values.begin(), values.end()));
}

// The 1, 2 or 5 x 10^k nearest to `value` (> 0) on a log scale.
double round_near(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  double best = decade;
  for (const double m : {2.0, 5.0, 10.0})
    if (std::fabs(std::log(m * decade / value)) < std::fabs(std::log(best / value))) best = m * decade;
  return best;
}

bool plain_name(const std::string& s) {
  if (s.empty() || std::isalpha(static_cast<unsigned char>(s[0])) == 0) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
}

// A weight as a lecturer writes it: the mass's and gravity's names side by side, "mg",
// "m₁g" (digits lowered), "mc g" (a space after a longer name, so it does not read as
// m c g); "weight of 1" when either is a number or an expression.
std::string weight_name(const std::string& mass, const std::string& gravity, const std::string& body) {
  if (!plain_name(mass) || !plain_name(gravity)) return "weight of " + body;
  const bool one_letter = mass.size() == 1 || std::isalpha(static_cast<unsigned char>(mass[1])) == 0;
  return sym::spell_name(mass).unicode + (one_letter ? "" : " ") + sym::spell_name(gravity).unicode;
}

std::string names_of(const std::vector<std::pair<std::string, Vec2>>& points) {
  std::string names;
  for (const auto& [name, at] : points) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "(none)" : names;
}

}  // namespace

bool MechanismGeometry::grounded() const {
  for (const JointShape& j : joints)
    if (j.points[0].body < 0 || j.points[1].body < 0) return true;
  for (const SpringShape& s : springs)
    if (s.ends[0].body < 0 || s.ends[1].body < 0) return true;
  return false;
}

BodyPoint MechanismGeometry::resolve(const std::string& reference, const std::string& setting) const {
  const auto dot = reference.find('.');
  std::string body_names = kGround;
  for (const BodyShape& b : bodies) body_names += ", " + b.name;
  if (dot == std::string::npos)
    throw Error::invalid(setting, "'" + reference + "' is not BODY.POINT; bodies: " + body_names);
  const std::string body = reference.substr(0, dot), point = reference.substr(dot + 1);
  const std::vector<std::pair<std::string, Vec2>>* points = nullptr;
  int index = -1;
  if (body == kGround) {
    points = &ground;
  } else {
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i].name == body) {
        points = &bodies[i].points;
        index = static_cast<int>(i);
      }
  }
  if (points == nullptr)
    throw Error::invalid(setting, "'" + body + "' is not a body of the mechanism; valid: " + body_names);
  for (const auto& [name, at] : *points)
    if (name == point) return {index, at};
  throw Error::invalid(setting, "'" + point + "' is not a point of " + body + "; valid: " + names_of(*points));
}

MechanismGeometry mechanism_geometry(const sym::System& system) {
  const Mechanism& m = system.mechanism();
  MechanismGeometry g;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& body = m.bodies[i];
    MechanismGeometry::BodyShape shape;
    shape.name = body.name;
    shape.shape = body.shape;
    shape.length = number(system, body.length);
    shape.width = number(system, body.width);
    shape.radius = number(system, body.radius);
    shape.mass = number(system, system.bodies()[i].mass);
    for (const NamedPoint& p : body.points)
      shape.points.emplace_back(p.name, vector_of(system, system.bodies()[i].points.at(p.name)));
    g.bodies.push_back(std::move(shape));
  }
  for (const NamedPoint& p : m.ground_points)
    g.ground.emplace_back(p.name, vector_of(system, system.point_position(-1, p.name)));
  for (const Joint& j : m.joints) {
    MechanismGeometry::JointShape shape;
    shape.name = j.name;
    shape.type = j.type;
    // P.force_x aliased as F_x names the force F (the homework's "F on 1", "−F on 2").
    // A copy: aliased() returns its argument, here a temporary, when there is no alias.
    const std::string alias = m.aliased(j.name + ".force_x");
    if (alias != j.name + ".force_x" && alias.size() > 2 && alias.ends_with("_x"))
      shape.force_name = alias.substr(0, alias.size() - 2);
    for (std::size_t k = 0; k < 2; ++k) shape.points[k] = point_of(system, j.bodies[k], j.points[k]);
    shape.torsion = j.stiffness.has_value() || j.damping.has_value();
    if (j.rest_angle) shape.rest = number(system, system.quantity(*j.rest_angle, false));
    if (j.axis) {
      const Vec2 axis{number(system, system.quantity(j.axis->x, false)),
                      number(system, system.quantity(j.axis->y, false))};
      if (axis.norm() > 0) shape.axis = axis.normalized();
    }
    if (j.radius) shape.radius = number(system, system.quantity(*j.radius, false));
    if (j.radii) {
      const std::array<GiNaC::ex, 2> radii = sym::joint_radii(system, j);
      shape.radii = {number(system, radii[0]), number(system, radii[1])};
      shape.mesh = j.internal ? -1 : 1;
      shape.constant = number(system, system.joint_constant(static_cast<int>(g.joints.size())));
      shape.carrier = m.body_index(j.carrier);
    }
    g.joints.push_back(std::move(shape));
  }
  for (const Driver& d : m.drivers)
    for (std::size_t j = 0; j < m.joints.size(); ++j)
      if (m.joints[j].name == d.joint) g.drivers.push_back({d.name, j});
  for (const Spring& s : m.springs)
    g.springs.push_back({s.name,
                         {point_of(system, s.between[0].body, s.between[0].point),
                          point_of(system, s.between[1].body, s.between[1].point)},
                         damping_of(system, s.damping)});
  // The loads' values keep t: constants and parameters substituted once, t per frame.
  const auto in_time = [&](const Quantity& q) {
    return system.quantity(q, true, true)
        .subs(system.constants())
        .subs(system.constants())
        .subs(system.parameter_values());
  };
  for (const AppliedForce& f : m.forces)
    g.forces.push_back({point_of(system, f.body, f.point), in_time(f.value.x), in_time(f.value.y)});
  for (const AppliedTorque& t : m.torques) g.torques.push_back({m.body_index(t.body), in_time(t.value)});
  g.time = system.time();
  for (const sym::BodySystem& b : system.bodies())
    for (const sym::CoordinateSymbols* c : {&b.x, &b.y, &b.theta}) g.state.push_back(c->q);
  for (const sym::BodySystem& b : system.bodies())
    for (const sym::CoordinateSymbols* c : {&b.x, &b.y, &b.theta}) g.state.push_back(c->q_dot);
  if (m.gravity) g.gravity = number(system, system.quantity(*m.gravity, false));
  // Gravity and springs as the System states them (one source of truth), compiled once.
  std::vector<GiNaC::ex> outputs;
  const auto numeric = [&](const GiNaC::ex& e) {
    return e.subs(system.lengths())
        .subs(system.lengths())
        .subs(system.constants())
        .subs(system.constants())
        .subs(system.parameter_values());
  };
  for (const sym::Load& load : system.loads()) {
    const bool gravity = load.source == "gravity";
    const bool spring =
        std::any_of(m.springs.begin(), m.springs.end(), [&](const Spring& s) { return s.name == load.source; });
    if (load.body < 0 || !(gravity || spring)) continue;
    const Body& body = m.bodies[static_cast<std::size_t>(load.body)];
    g.loads.push_back(
        {load.body, gravity, gravity ? weight_name(body.mass.text, m.gravity->text, body.name) : load.source});
    for (const GiNaC::ex& e : {load.force.x, load.force.y, load.point.x, load.point.y}) outputs.push_back(numeric(e));
  }
  std::vector<GiNaC::symbol>& inputs = g.inputs;
  for (const sym::BodySystem& b : system.bodies())
    for (const sym::CoordinateSymbols* c : {&b.x, &b.y, &b.theta}) inputs.push_back(c->q);
  for (const sym::BodySystem& b : system.bodies())
    for (const sym::CoordinateSymbols* c : {&b.x, &b.y, &b.theta}) inputs.push_back(c->q_dot);
  inputs.push_back(system.time());
  if (!outputs.empty()) g.load_values = eval::compile(outputs, inputs);
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    g.point_velocities.emplace_back();
    for (const NamedPoint& p : m.bodies[i].points) {
      const sym::Vec2 r = system.point_position(static_cast<int>(i), p.name);
      g.point_velocities.back().push_back({numeric(system.time_derivative(r.x)), numeric(system.time_derivative(r.y))});
    }
  }
  return g;
}

void load_inputs(const eval::MechanismSample& sample, double t, std::vector<double>& inputs) {
  inputs.assign(sample.pose.begin(), sample.pose.end());
  inputs.insert(inputs.end(), sample.rates.begin(), sample.rates.end());
  inputs.push_back(t);
}

Vec2 world_point(const std::vector<double>& pose, const BodyPoint& p) {
  if (p.body < 0) return p.local;
  const auto b = 3 * static_cast<std::size_t>(p.body);
  return Vec2(pose[b], pose[b + 1]) + rotated(pose[b + 2], p.local);
}

/// Whether `p` lies inside the closed polygon `outline` (even-odd rule); a point mass's
/// single-point outline holds nothing.
bool inside(const std::vector<Vec2>& outline, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Vec2 &a = outline[i], &c = outline[j];
    if ((a.y() > p.y()) != (c.y() > p.y()) && p.x() < (c.x() - a.x()) * (p.y() - a.y()) / (c.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

std::vector<Vec2> body_outline(const MechanismGeometry::BodyShape& body, const std::vector<double>& pose,
                               std::size_t index) {
  const Vec2 centre(pose[3 * index], pose[3 * index + 1]);
  const double theta = pose[3 * index + 2];
  std::vector<Vec2> local;
  constexpr double pi = std::numbers::pi;
  switch (body.shape) {
    case Shape::rectangle: {
      const double a = 0.5 * body.length, b = 0.5 * body.width;
      local = {{-a, -b}, {a, -b}, {a, b}, {-a, b}};
      break;
    }
    case Shape::rod: {
      // Round ends inside the length, so the outline spans exactly the rod's length.
      const double r = std::min(body.length / 24, 0.5 * body.length), a = 0.5 * body.length - r;
      for (int k = 0; k <= kCapSides; ++k) {
        const double angle = -0.5 * pi + pi * k / kCapSides;
        local.emplace_back(a + r * std::cos(angle), r * std::sin(angle));
      }
      for (int k = 0; k <= kCapSides; ++k) {
        const double angle = 0.5 * pi + pi * k / kCapSides;
        local.emplace_back(-a + r * std::cos(angle), r * std::sin(angle));
      }
      break;
    }
    case Shape::disc:
    case Shape::ring:  // the painter cuts the hole
      for (int k = 0; k < kDiscSides; ++k) {
        const double angle = 2 * pi * k / kDiscSides;
        local.emplace_back(body.radius * std::cos(angle), body.radius * std::sin(angle));
      }
      break;
    case Shape::point:
      local = {Vec2::Zero()};
      break;
  }
  for (Vec2& p : local) p = centre + rotated(theta, p);
  return local;
}

std::string format_quantity(double value, const char* unit) {
  char buffer[48];
  const double size = std::fabs(value);
  if (size != 0 && (size < 1e-3 || size >= 1e5))
    std::snprintf(buffer, sizeof buffer, "%.2e %s", value, unit);
  else if (size >= 999.5)  // "1000 N", not "%g"'s "1e+03 N"
    std::snprintf(buffer, sizeof buffer, "%.0f %s", value, unit);
  else
    std::snprintf(buffer, sizeof buffer, "%.3g %s", value, unit);
  return buffer;
}

void MechanismDrawList::clear() {
  outlines.clear();
  lines.clear();
  markers.clear();
  arrows.clear();
  torques.clear();
  motors.clear();
  labels.clear();
  joint_labels.clear();
  ghosts.clear();
}

MechanismScene::MechanismScene(MechanismGeometry geometry, const MechanismMotion& motion, std::vector<BodyPoint> trails,
                               double trail_seconds, const ArrowScaleRequest& arrows, ElementSet shown, bool free_body,
                               bool relative_velocities, const std::vector<BodyPoint>& arrow_points)
    : geometry_(std::move(geometry)),
      motion_(motion),
      trails_(std::move(trails)),
      trail_seconds_(trail_seconds),
      shown_(shown),
      free_body_(free_body),
      relative_velocities_(relative_velocities) {
  if (!shown_.has(Element::trail)) trails_.clear();
  // The points whose velocity and acceleration are drawn: the trails', then those named
  // (--points), these labelled with their magnitude.
  for (const BodyPoint& trail : trails_) marked_.push_back({trail, false});
  for (const BodyPoint& point : arrow_points) {
    const auto same = std::find_if(marked_.begin(), marked_.end(), [&](const Marked& m) {
      return m.point.body == point.body && m.point.local == point.local;
    });
    if (same != marked_.end())
      same->valued = true;
    else
      marked_.push_back({point, true});
  }
  const std::size_t joints = geometry_.joints.size(), samples = motion_.samples.size();
  rail_span_.assign(joints, {1e300, -1e300});
  spring_span_.assign(geometry_.springs.size(), {1e300, 0});
  applied_.assign(samples, {});
  torque_.assign(samples, {});
  load_.assign(samples, {});
  const bool joints_shown = shown_.has(Element::pin_force), loads_shown = shown_.has(Element::loads);
  // Each sample's largest force (joint or applied) and torque: the scales' statistics;
  // and per other kind its own largest.
  std::vector<double> largest_force(samples, 0), largest_torque(samples, 0), largest_gravity(samples, 0),
      largest_spring(samples, 0), largest_velocity(samples, 0), largest_acceleration(samples, 0),
      largest_driver_force(samples, 0), largest_driver_torque(samples, 0);
  std::vector<double> inputs, scratch(geometry_.load_values.scratch_size());
  // The traced points' velocities, shown with the centres of mass's.
  trail_velocity_.assign(samples, {});
  eval::Program traced;
  if (shown_.has(Element::velocity)) {
    std::vector<GiNaC::ex> velocities;
    for (const Marked& marked : marked_) {
      const BodyPoint& trail = marked.point;
      if (trail.body < 0) continue;
      const auto b = static_cast<std::size_t>(trail.body);
      for (std::size_t p = 0; p < geometry_.bodies[b].points.size() && b < geometry_.point_velocities.size(); ++p)
        if (geometry_.bodies[b].points[p].second == trail.local) {
          velocities.push_back(geometry_.point_velocities[b][p][0]);
          velocities.push_back(geometry_.point_velocities[b][p][1]);
          traced_.push_back(marked);
          break;
        }
    }
    if (!velocities.empty()) traced = eval::compile(velocities, geometry_.inputs);
  }
  // The traced points' places in a sample's named points (bodies in order, each body's
  // points by name), whose accelerations are drawn with the centres of mass's.
  for (std::size_t m = 0; m < marked_.size(); ++m) {
    const BodyPoint& trail = marked_[m].point;
    if (trail.body < 0 || !shown_.has(Element::acceleration)) continue;
    std::size_t index = 0;
    for (std::size_t b = 0; b < static_cast<std::size_t>(trail.body); ++b) index += geometry_.bodies[b].points.size();
    const auto& points = geometry_.bodies[static_cast<std::size_t>(trail.body)].points;
    const auto own = std::find_if(points.begin(), points.end(), [&](const auto& p) { return p.second == trail.local; });
    if (own == points.end()) continue;
    for (const auto& p : points) index += p.first < own->first ? 1 : 0;
    traced_points_.emplace_back(m, index);
  }
  std::vector<double> scratch_traced(traced.scratch_size());
  for (std::size_t k = 0; k < samples; ++k) {
    const eval::MechanismSample& s = motion_.samples[k];
    const Vec2 c = centroid(k);
    for (std::size_t i = 0; i < geometry_.bodies.size(); ++i)
      for (const Vec2& p : body_outline(geometry_.bodies[i], s.pose, i)) {
        bounds_.include(p);
        reach_ = std::max(reach_, (p - c).norm());
      }
    for (std::size_t d = 0; d < geometry_.drivers.size() && d < s.drivers.size(); ++d) {
      const bool slider =
          joint_type_info(geometry_.joints[geometry_.drivers[d].joint].type).motion == JointMotion::prismatic;
      double& largest = slider ? largest_driver_force[k] : largest_driver_torque[k];
      largest = std::max(largest, std::fabs(s.drivers[d]));
    }
    for (std::size_t j = 0; j < joints; ++j) {
      const MechanismGeometry::JointShape& joint = geometry_.joints[j];
      if (joints_shown && (joint.points[0].body >= 0 || joint.points[1].body >= 0))
        largest_force[k] = std::max(largest_force[k], std::hypot(s.force[3 * j], s.force[3 * j + 1]));
      switch (sym::joint_stages(joint.type).drawing) {  // the drawing's extent: a rail spans the travel
        case sym::JointDrawing::marker:
        case sym::JointDrawing::bracket:
        case sym::JointDrawing::gear:
          continue;
        case sym::JointDrawing::rail:
        case sym::JointDrawing::rolling:
        case sym::JointDrawing::slot:
          break;
      }
      const Vec2 p0 = world_point(s.pose, joint.points[0]), p1 = world_point(s.pose, joint.points[1]);
      const double theta0 =
          joint.points[0].body < 0 ? 0 : s.pose[3 * static_cast<std::size_t>(joint.points[0].body) + 2];
      const double along = (p1 - p0).dot(rotated(theta0, joint.axis));
      rail_span_[j] = {std::min(rail_span_[j][0], along), std::max(rail_span_[j][1], along)};
    }
    for (std::size_t i = 0; i < geometry_.springs.size(); ++i) {
      const auto& ends = geometry_.springs[i].ends;
      const double length = (world_point(s.pose, ends[1]) - world_point(s.pose, ends[0])).norm();
      spring_span_[i] = {std::min(spring_span_[i][0], length), std::max(spring_span_[i][1], length)};
    }
    // The time, and the sample's state for a load that depends on it.
    GiNaC::exmap at{{geometry_.time, motion_.times[k]}};
    for (std::size_t i = 0; i < geometry_.state.size() && i < s.pose.size() + s.rates.size(); ++i)
      at[geometry_.state[i]] = i < s.pose.size() ? s.pose[i] : s.rates[i - s.pose.size()];
    for (const MechanismGeometry::ForceShape& f : geometry_.forces) {
      applied_[k].emplace_back(sym::evaluate(f.x, at), sym::evaluate(f.y, at));
      if (loads_shown) largest_force[k] = std::max(largest_force[k], applied_[k].back().norm());
    }
    for (const MechanismGeometry::TorqueShape& t : geometry_.torques) {
      torque_[k].push_back(sym::evaluate(t.value, at));
      if (loads_shown) largest_torque[k] = std::max(largest_torque[k], std::fabs(torque_[k].back()));
    }
    if (!geometry_.loads.empty() && !s.rates.empty()) {
      load_inputs(s, motion_.times[k], inputs);
      load_[k].resize(geometry_.load_values.output_count());
      geometry_.load_values.run(inputs.data(), load_[k].data(), scratch.data());
      for (std::size_t i = 0; i < geometry_.loads.size(); ++i) {
        const double size = std::hypot(load_[k][4 * i], load_[k][4 * i + 1]);
        double& largest = geometry_.loads[i].gravity ? largest_gravity[k] : largest_spring[k];
        largest = std::max(largest, size);
      }
    }
    const Vec2 frame_velocity = relative_velocities_ && !s.rates.empty() ? centroid_velocity(k) : Vec2::Zero();
    for (std::size_t i = 0; i < geometry_.bodies.size() && !s.rates.empty(); ++i)
      largest_velocity[k] =
          std::max(largest_velocity[k], (Vec2(s.rates[3 * i], s.rates[3 * i + 1]) - frame_velocity).norm());
    for (std::size_t i = 0; 3 * i + 1 < s.accelerations.size(); ++i)
      largest_acceleration[k] =
          std::max(largest_acceleration[k], std::hypot(s.accelerations[3 * i], s.accelerations[3 * i + 1]));
    for (const auto& [m, p] : traced_points_)
      if (6 * p + 5 < s.points.size())
        largest_acceleration[k] =
            std::max(largest_acceleration[k], std::hypot(s.points[6 * p + 4], s.points[6 * p + 5]));
    if (traced.output_count() > 0 && !s.rates.empty()) {
      load_inputs(s, motion_.times[k], inputs);
      trail_velocity_[k].resize(traced.output_count());
      traced.run(inputs.data(), trail_velocity_[k].data(), scratch_traced.data());
      for (std::size_t i = 0; 2 * i + 1 < trail_velocity_[k].size(); ++i) {
        trail_velocity_[k][2 * i] -= frame_velocity.x();
        trail_velocity_[k][2 * i + 1] -= frame_velocity.y();
        largest_velocity[k] =
            std::max(largest_velocity[k], std::hypot(trail_velocity_[k][2 * i], trail_velocity_[k][2 * i + 1]));
      }
    }
  }
  for (const auto& [name, at] : geometry_.ground) bounds_.include(at);
  // The trails' points too: a point off its body's outline may swing past it.
  for (const std::vector<double>& pose : motion_.trail_poses)
    for (const BodyPoint& trail : trails_) bounds_.include(world_point(pose, trail));
  if (geometry_.grounded() && !bounds_.empty())
    extent_ = std::max(bounds_.max.x() - bounds_.min.x(), bounds_.max.y() - bounds_.min.y());
  else
    extent_ = 2 * reach_;
  if (!(extent_ > 0)) extent_ = 1;

  // "common": every force shown to one scale, from the typical largest of them all.
  std::vector<double> largest_any(samples, 0);
  for (std::size_t k = 0; k < samples; ++k)
    largest_any[k] = std::max({largest_force[k], shown_.has(Element::gravity) ? largest_gravity[k] : 0.0,
                               shown_.has(Element::spring_force) ? largest_spring[k] : 0.0});
  double common_scale = 0;
  if (const double typical = typical_of(largest_any); typical > 0 && std::isfinite(typical))
    common_scale = kTypicalShare * extent_ / typical;
  if (arrows.common_units_per_cm > 0) common_scale = arrow_scale_of(arrows.common_units_per_cm).metres_per_unit;
  const double typical_force = typical_of(largest_force);
  if (typical_force > 0 && std::isfinite(typical_force)) {
    force_scale_ = kTypicalShare * extent_ / typical_force;
    if (arrows.common) force_scale_ = common_scale;
    applied_scale_ = force_scale_;
    if (const double fixed = arrows.fixed_for("joint"); fixed > 0) force_scale_ = arrow_scale_of(fixed).metres_per_unit;
    if (const double fixed = arrows.fixed_for("applied"); fixed > 0)
      applied_scale_ = arrow_scale_of(fixed).metres_per_unit;
    arrow_cap_ = kCapFactor * kTypicalShare * extent_;
    // The reference arrow: the typical force by default, else a round force about a
    // typical arrow long at the scale asked for.
    const auto reference = [&](double scale) {
      return arrows.is_default() ? round_near(typical_force) : round_near(kTypicalShare * extent_ / scale);
    };
    legend_.newtons = reference(force_scale_);
    legend_.metres = legend_.newtons * force_scale_;
    legend_.value = format_quantity(legend_.newtons, "N");
    legend_.applied_newtons = reference(applied_scale_);
    legend_.applied_metres = legend_.applied_newtons * applied_scale_;
    legend_.applied_value = format_quantity(legend_.applied_newtons, "N");
    legend_.joint_scale = describe_arrow_scale(arrow_scale_of(0.01 / force_scale_), "N");
    legend_.applied_scale = describe_arrow_scale(arrow_scale_of(0.01 / applied_scale_), "N");
    for (const MechanismGeometry::JointShape& joint : geometry_.joints)
      legend_.joint = legend_.joint || joint.points[0].body >= 0 || joint.points[1].body >= 0;
    legend_.joint = legend_.joint && joints_shown;
    legend_.applied = !geometry_.forces.empty() && loads_shown;
    const double largest = *std::max_element(largest_force.begin(), largest_force.end());
    legend_.cut = largest * std::max(force_scale_, applied_scale_) > arrow_cap_;
  }
  // Gravity, springs and velocities: each kind its own scale (a typical frame's largest
  // a sixth of the extent), the forces' common one when asked, or as fixed.
  using Kind = MechanismDrawList::Arrow::Kind;
  const auto own_scale = [&](Kind kind, Element element, const std::vector<double>& largest, const char* name,
                             const char* unit, bool force) {
    const double typical = typical_of(largest);
    if (!shown_.has(element) || !(typical > 0) || !std::isfinite(typical)) return 0.0;
    double scale = kTypicalShare * extent_ / typical;
    if (force && arrows.common) scale = common_scale;
    if (const double fixed = arrows.fixed_for(name); fixed > 0) scale = arrow_scale_of(fixed).metres_per_unit;
    if (arrow_cap_ <= 0) arrow_cap_ = kCapFactor * kTypicalShare * extent_;
    const double reference = arrows.is_default() ? round_near(typical) : round_near(kTypicalShare * extent_ / scale);
    legend_.rows.push_back({kind, reference * scale, format_quantity(reference, unit),
                            describe_arrow_scale(arrow_scale_of(0.01 / scale), unit)});
    const double most = *std::max_element(largest.begin(), largest.end());
    legend_.cut = legend_.cut || most * scale > arrow_cap_;
    return scale;
  };
  gravity_scale_ = own_scale(Kind::gravity, Element::gravity, largest_gravity, "gravity", "N", true);
  spring_scale_ = own_scale(Kind::spring, Element::spring_force, largest_spring, "spring", "N", true);
  velocity_scale_ = own_scale(Kind::velocity, Element::velocity, largest_velocity, "velocity", "m/s", false);
  legend_.relative_velocity = relative_velocities_ && velocity_scale_ > 0;
  acceleration_scale_ =
      own_scale(Kind::acceleration, Element::acceleration, largest_acceleration, "acceleration", "m/s²", false);
  driver_scale_ = own_scale(Kind::driver, Element::motor, largest_driver_force, "driver", "N", true);
  // A driver's torque: an arc whose sweep is its size, a typical one a turn and a quarter,
  // the legend's reference arc a round torque.
  if (const double typical = typical_of(largest_driver_torque);
      shown_.has(Element::motor) && typical > 0 && std::isfinite(typical)) {
    driver_torque_scale_ = kTypicalSweep / typical;
    const double reference = round_near(typical);
    legend_.rows.push_back({Kind::driver, 0, format_quantity(reference, "N m"),
                            "a half turn = " + format_quantity(std::numbers::pi / driver_torque_scale_, "N m"),
                            reference * driver_torque_scale_});
  }
  for (const BodyPoint& trail : trails_) {  // "path of P": the point's own name
    const std::vector<std::pair<std::string, Vec2>>& named =
        trail.body < 0 ? geometry_.ground : geometry_.bodies[static_cast<std::size_t>(trail.body)].points;
    for (const auto& [name, at] : named)
      if (at == trail.local) legend_.trails.push_back("path of " + name);
  }
  legend_.trail_seconds = trail_seconds_;
  legend_.com = shown_.has(Element::com) && !geometry_.bodies.empty();
  const double typical_torque = typical_of(largest_torque);
  if (typical_torque > 0 && std::isfinite(typical_torque)) torque_scale_ = kTypicalSweep / typical_torque;

  view_bounds_ = bounds_;
  view_reach_ = reach_;
  MechanismDrawList list;
  const bool arrows_drawn = force_scale_ > 0 || torque_scale_ > 0 || !legend_.rows.empty();
  for (std::size_t k = 0; (arrows_drawn || free_body_) && k < samples; ++k) {
    frame(k, list);
    const Vec2 c = centroid(k);
    const auto include = [&](const Vec2& p) {
      view_bounds_.include(p);
      view_reach_ = std::max(view_reach_, (p - c).norm());
    };
    for (const MechanismDrawList::Arrow& arrow : list.arrows) include(arrow.tail + arrow.vector);
    for (const MechanismDrawList::Outline& outline : list.outlines)
      for (const Vec2& p : outline.points) include(p);  // pulled apart in the free-body view
    for (const MechanismDrawList::Torque& torque : list.torques) {
      include(torque.centre - Vec2(torque.radius, torque.radius));
      include(torque.centre + Vec2(torque.radius, torque.radius));
    }
  }
}

void MechanismScene::set_shortest_arrow(double metres, double drawn) {
  shortest_ = metres;
  stretched_ = drawn > 0 ? drawn : metres;
  legend_.stretched = false;
  for (std::size_t k = 0; k < motion_.samples.size() && !legend_.stretched; ++k) {
    const auto short_at = [&](double newtons, double scale) {
      const double length = newtons * scale;
      return length > 0 && length < shortest_ && length <= arrow_cap_;
    };
    for (std::size_t j = 0; j < geometry_.joints.size(); ++j) {
      const auto& points = geometry_.joints[j].points;
      if ((points[0].body < 0 && points[1].body < 0) || !shown_.has(Element::pin_force)) continue;
      const std::vector<double>& force = motion_.samples[k].force;
      if (short_at(std::hypot(force[3 * j], force[3 * j + 1]), force_scale_)) legend_.stretched = true;
    }
    for (const Vec2& f : applied_[k])
      if (shown_.has(Element::loads) && short_at(f.norm(), applied_scale_)) legend_.stretched = true;
    for (std::size_t i = 0; i < geometry_.loads.size() && !load_[k].empty(); ++i) {
      const double scale = geometry_.loads[i].gravity ? gravity_scale_ : spring_scale_;
      if (scale > 0 && short_at(std::hypot(load_[k][4 * i], load_[k][4 * i + 1]), scale)) legend_.stretched = true;
    }
    const std::vector<double>& rates = motion_.samples[k].rates;
    const Vec2 frame_velocity = relative_velocities_ && !rates.empty() ? centroid_velocity(k) : Vec2::Zero();
    for (std::size_t i = 0; velocity_scale_ > 0 && 3 * i + 1 < rates.size(); ++i)
      if (short_at((Vec2(rates[3 * i], rates[3 * i + 1]) - frame_velocity).norm(), velocity_scale_))
        legend_.stretched = true;
  }
}

Vec2 MechanismScene::centroid(std::size_t k) const {
  const std::vector<double>& pose = motion_.samples[k].pose;
  Vec2 sum = Vec2::Zero();
  double mass = 0;
  for (std::size_t i = 0; i < geometry_.bodies.size(); ++i) {
    sum += geometry_.bodies[i].mass * Vec2(pose[3 * i], pose[3 * i + 1]);
    mass += geometry_.bodies[i].mass;
  }
  return mass > 0 ? Vec2(sum / mass) : sum;
}

Vec2 MechanismScene::centroid_velocity(std::size_t k) const {
  const std::vector<double>& rates = motion_.samples[k].rates;
  Vec2 sum = Vec2::Zero();
  double mass = 0;
  for (std::size_t i = 0; 3 * i + 1 < rates.size() && i < geometry_.bodies.size(); ++i) {
    sum += geometry_.bodies[i].mass * Vec2(rates[3 * i], rates[3 * i + 1]);
    mass += geometry_.bodies[i].mass;
  }
  return mass > 0 ? Vec2(sum / mass) : sum;
}

MechanismDrawList::Arrow MechanismScene::force_arrow(MechanismDrawList::Arrow::Kind kind, const Vec2& at,
                                                     const Vec2& force, std::string label) const {
  // An applied load's and a driver's labels carry their value already.
  const bool applied =
      kind == MechanismDrawList::Arrow::Kind::applied || kind == MechanismDrawList::Arrow::Kind::driver;
  MechanismDrawList::Arrow arrow{kind, at, scale_of(kind) * force, force.norm(), false, std::move(label)};
  const double length = arrow.vector.norm();
  if (length > arrow_cap_ || (length > 0 && length < shortest_)) {
    // Cut to the cap, or stretched to be seen; the label then says the value the length
    // no longer shows.
    arrow.cut = length > arrow_cap_;
    arrow.stretched = !arrow.cut;
    arrow.vector *= (arrow.cut ? arrow_cap_ : stretched_) / length;
    if (!applied && !arrow.label.empty()) arrow.label += ": " + format_quantity(arrow.force, arrow_unit(kind));
  }
  return arrow;
}

const char* arrow_unit(MechanismDrawList::Arrow::Kind kind) {
  using Kind = MechanismDrawList::Arrow::Kind;
  switch (kind) {
    case Kind::joint:
    case Kind::applied:
    case Kind::gravity:
    case Kind::spring:
    case Kind::driver:
      return "N";
    case Kind::velocity:
      return "m/s";
    case Kind::acceleration:
      return "m/s²";
  }
  return "N";
}

double MechanismScene::scale_of(MechanismDrawList::Arrow::Kind kind) const {
  using Kind = MechanismDrawList::Arrow::Kind;
  switch (kind) {
    case Kind::joint:
      return force_scale_;
    case Kind::applied:
      return applied_scale_;
    case Kind::gravity:
      return gravity_scale_;
    case Kind::spring:
      return spring_scale_;
    case Kind::velocity:
      return velocity_scale_;
    case Kind::acceleration:
      return acceleration_scale_;
    case Kind::driver:
      return driver_scale_;
  }
  return 0;
}

void MechanismScene::add_load_arrows(std::size_t k, MechanismDrawList& out) const {
  using Kind = MechanismDrawList::Arrow::Kind;
  const bool tags = shown_.has(Element::labels);
  for (std::size_t i = 0; i < geometry_.loads.size() && !load_[k].empty(); ++i) {
    const MechanismGeometry::LoadShape& load = geometry_.loads[i];
    const Kind kind = load.gravity ? Kind::gravity : Kind::spring;
    const Vec2 force(load_[k][4 * i], load_[k][4 * i + 1]), at(load_[k][4 * i + 2], load_[k][4 * i + 3]);
    if (scale_of(kind) <= 0 || force.norm() == 0) continue;
    const std::string& body = geometry_.bodies[static_cast<std::size_t>(load.body)].name;
    out.arrows.push_back(
        force_arrow(kind, at, force, tags ? (load.gravity ? load.name : load.name + " on " + body) : ""));
    out.arrows.back().body = load.body;
  }
  const std::vector<double>& rates = motion_.samples[k].rates;
  const Vec2 frame_velocity = relative_velocities_ && !rates.empty() ? centroid_velocity(k) : Vec2::Zero();
  for (std::size_t i = 0; velocity_scale_ > 0 && i < geometry_.bodies.size() && !rates.empty(); ++i) {
    const std::vector<double>& pose = motion_.samples[k].pose;
    const Vec2 v = Vec2(rates[3 * i], rates[3 * i + 1]) - frame_velocity;
    if (v.norm() == 0) continue;
    out.arrows.push_back(force_arrow(Kind::velocity, Vec2(pose[3 * i], pose[3 * i + 1]), v,
                                     tags ? "v of " + geometry_.bodies[i].name : ""));
    out.arrows.back().body = static_cast<int>(i);
  }
  const std::vector<double>& traced = trail_velocity_[k];
  for (std::size_t i = 0; velocity_scale_ > 0 && 2 * i + 1 < traced.size(); ++i) {
    const Vec2 v(traced[2 * i], traced[2 * i + 1]);
    if (v.norm() == 0) continue;
    const BodyPoint& point = traced_[i].point;
    out.arrows.push_back(force_arrow(Kind::velocity, world_point(motion_.samples[k].pose, point), v,
                                     tags ? "v of " + point_name(point) : ""));
    if (traced_[i].valued) with_value(out.arrows.back(), "m/s");
    out.arrows.back().body = point.body;
  }
  add_acceleration_arrows(k, out);
}

void MechanismScene::add_acceleration_arrows(std::size_t k, MechanismDrawList& out) const {
  const eval::MechanismSample& s = motion_.samples[k];
  const bool tags = shown_.has(Element::labels);
  using Kind = MechanismDrawList::Arrow::Kind;
  for (std::size_t i = 0; acceleration_scale_ > 0 && 3 * i + 1 < s.accelerations.size(); ++i) {
    const Vec2 a(s.accelerations[3 * i], s.accelerations[3 * i + 1]);
    if (a.norm() == 0) continue;
    out.arrows.push_back(force_arrow(Kind::acceleration, Vec2(s.pose[3 * i], s.pose[3 * i + 1]), a,
                                     tags ? "a of " + geometry_.bodies[i].name : ""));
    out.arrows.back().body = static_cast<int>(i);
  }
  for (const auto& [m, p] : traced_points_) {
    if (acceleration_scale_ <= 0 || 6 * p + 5 >= s.points.size()) continue;
    const Vec2 a(s.points[6 * p + 4], s.points[6 * p + 5]);
    if (a.norm() == 0) continue;
    const BodyPoint& point = marked_[m].point;
    out.arrows.push_back(force_arrow(Kind::acceleration, Vec2(s.points[6 * p], s.points[6 * p + 1]), a,
                                     tags ? "a of " + point_name(point) : ""));
    if (marked_[m].valued) with_value(out.arrows.back(), "m/s²");
    out.arrows.back().body = point.body;
  }
}

std::string MechanismScene::point_name(const BodyPoint& point) const {
  const MechanismGeometry::BodyShape& body = geometry_.bodies[static_cast<std::size_t>(point.body)];
  std::string name;
  for (const auto& [n, at] : body.points)
    if (at == point.local) name = n;
  return body.name + "." + name;
}

void MechanismScene::with_value(MechanismDrawList::Arrow& arrow, const char* unit) {
  // A cut or stretched arrow's label has its value already (force_arrow).
  if (arrow.label.empty() || arrow.cut || arrow.stretched) return;
  arrow.label += ": " + format_quantity(arrow.force, unit);
}

void MechanismScene::add_torsion(const MechanismGeometry::JointShape& joint, const std::vector<double>& pose,
                                 MechanismDrawList& out) const {
  // A spiral about the pin, its inner end fixed to bodies[0], its outer end turning with
  // bodies[1]: kTorsionTurns turns at the rest angle, winding up as the joint turns past it.
  constexpr double kTorsionTurns = 2.5;
  constexpr int kSteps = 120;
  const auto angle = [&](int body) { return body < 0 ? 0.0 : pose[3 * static_cast<std::size_t>(body) + 2]; };
  const double a = angle(joint.points[0].body), b = angle(joint.points[1].body);
  const Vec2 centre = world_point(pose, joint.points[1]);
  const double inner = extent_ / 40, outer = extent_ / 14;
  const double sweep = 2 * std::numbers::pi * kTorsionTurns + (b - a - joint.rest);
  MechanismDrawList::Line spiral{MechanismDrawList::Line::Kind::spring, {}};
  for (int k = 0; k <= kSteps; ++k) {
    const double f = static_cast<double>(k) / kSteps;
    const double r = inner + f * (outer - inner),
                 phi = a + joint.rest + f * sweep - 2 * std::numbers::pi * kTorsionTurns;
    spiral.points.push_back(centre + r * Vec2(std::cos(phi), std::sin(phi)));
  }
  out.lines.push_back(std::move(spiral));
}

void MechanismScene::add_gear(const MechanismGeometry::JointShape& joint, const std::vector<double>& pose,
                              MechanismDrawList& out) const {
  // Each gear's pitch circle, with tooth marks one pitch apart on both (kGearMarks on the
  // smaller) turning with it. A mark of gear 1 at the pitch point P sits at its local angle
  // 2 pi k / N1; the row r1 b1 + s r2 b2 = c_G (b: an angle less the carrier's) then puts
  // gear 2's material point at P at alpha2 - 2 pi k s / N2, so its marks start at alpha2.
  constexpr int kGearMarks = 12, kCircleSteps = 120;
  using Kind = MechanismDrawList::Line::Kind;
  const auto angle = [&](int body) { return body < 0 ? 0.0 : pose[3 * static_cast<std::size_t>(body) + 2]; };
  const std::array<Vec2, 2> centre{world_point(pose, joint.points[0]), world_point(pose, joint.points[1])};
  const double r1 = joint.radii[0], r2 = joint.radii[1], s = joint.mesh;
  const Vec2 e = (centre[1] - centre[0]) / (r1 + s * r2);  // from C1 towards P
  const double phi = std::atan2(e.y(), e.x()) - angle(joint.carrier);
  const double pitch = 2 * std::numbers::pi * std::min(r1, r2) / kGearMarks;
  const std::array<double, 2> phase{0.0,
                                    phi + (s > 0 ? std::numbers::pi : 0.0) - (joint.constant - r1 * phi) / (s * r2)};
  for (std::size_t side = 0; side < 2; ++side) {
    const int body = joint.points[side].body;
    const double r = joint.radii[side], theta = angle(body);
    MechanismDrawList::Line circle{Kind::teeth, {}, {}, body};
    for (int k = 0; k <= kCircleSteps; ++k) {
      const double a = 2 * std::numbers::pi * k / kCircleSteps;
      circle.points.push_back(centre[side] + r * Vec2(std::cos(a), std::sin(a)));
    }
    out.lines.push_back(std::move(circle));
    const int marks = std::max(3, static_cast<int>(std::lround(2 * std::numbers::pi * r / pitch)));
    for (int k = 0; k < marks; ++k) {
      const double a = theta + phase[side] + 2 * std::numbers::pi * k / marks;
      const Vec2 radial(std::cos(a), std::sin(a));
      out.lines.push_back({Kind::teeth,
                           {centre[side] + (r - 0.3 * pitch) * radial, centre[side] + (r + 0.3 * pitch) * radial},
                           {},
                           body});
    }
  }
}

void MechanismScene::add_spring(const MechanismGeometry::SpringShape& spring, std::size_t index,
                                const std::vector<double>& pose, MechanismDrawList& out) const {
  using Kind = MechanismDrawList::Line::Kind;
  // Straight leads a sixth of the length at each end, a zig-zag of fixed turns between,
  // as wide as a twentieth of the mechanism. With damping, the coil runs beside a
  // dashpot, joined to it by a bar across each end.
  const Vec2 a = world_point(pose, spring.ends[0]), b = world_point(pose, spring.ends[1]);
  const Vec2 along = b - a;
  const double length = along.norm();
  MechanismDrawList::Line coil{Kind::spring, {a}};
  if (length > 0) {
    const Vec2 unit = along / length, normal(-unit.y(), unit.x());
    const bool damped = spring.damping > 0;
    const double offset = damped ? extent_ / 30 : 0.0;
    const double amplitude = damped ? 0.55 * offset : extent_ / 40;
    const Vec2 start = a + along / 6, end = b - along / 6, side = offset * normal;
    coil.points.push_back(start);
    if (damped) coil.points.push_back(start + side);
    const int zigs = 2 * kSpringTurns;
    for (int z = 0; z < zigs; ++z) {
      const double f = (z + 0.5) / zigs;
      coil.points.push_back(start + side + f * (end - start) + (z % 2 == 0 ? amplitude : -amplitude) * normal);
    }
    if (damped) coil.points.push_back(end + side);
    coil.points.push_back(end);
    if (damped) {
      // The cylinder hangs from the first bar, the piston from the second; sized on the
      // lengths the motion takes so the plate stays inside while it slides.
      const Vec2 s0 = start - side, e0 = end - side;
      const double branch = (end - start).norm();
      const double shortest = 2.0 / 3 * spring_span_[index][0], longest = 2.0 / 3 * spring_span_[index][1];
      const double cylinder = 0.55 * shortest, half = 0.7 * offset;
      const double rod = 0.5 * (shortest + longest) - 0.5 * cylinder;
      const double plate = std::clamp(branch - rod, 0.15 * cylinder, 0.9 * cylinder);
      out.lines.push_back({Kind::dashpot, {start, s0}});
      out.lines.push_back({Kind::dashpot, {end, e0}});
      out.lines.push_back({Kind::dashpot,
                           {s0 + cylinder * unit + half * normal, s0 + half * normal, s0 - half * normal,
                            s0 + cylinder * unit - half * normal}});
      out.lines.push_back({Kind::dashpot, {e0, s0 + plate * unit}});
      out.lines.push_back(
          {Kind::dashpot, {s0 + plate * unit + 0.75 * half * normal, s0 + plate * unit - 0.75 * half * normal}});
    }
  }
  coil.points.push_back(b);
  out.lines.push_back(std::move(coil));
}

void MechanismScene::add_loads(std::size_t k, MechanismDrawList& out) const {
  const std::vector<double>& pose = motion_.samples[k].pose;
  const std::size_t forces = geometry_.forces.size();
  const bool tags = shown_.has(Element::labels);
  for (std::size_t i = 0; force_scale_ > 0 && shown_.has(Element::loads) && i < forces; ++i) {
    const Vec2 force = applied_[k][i];
    std::string label = "F";
    if (forces > 1) label.append(std::to_string(i + 1));
    label.append(" = ").append(format_quantity(force.norm(), "N"));
    if (!tags) label.clear();
    out.arrows.push_back(force_arrow(MechanismDrawList::Arrow::Kind::applied, world_point(pose, geometry_.forces[i].at),
                                     force, std::move(label)));
    out.arrows.back().body = geometry_.forces[i].at.body;
  }
  for (std::size_t i = 0; torque_scale_ > 0 && shown_.has(Element::loads) && i < geometry_.torques.size(); ++i) {
    const double torque = torque_[k][i];
    if (torque == 0) continue;
    const auto body = static_cast<std::size_t>(geometry_.torques[i].body);
    const double radius = torque_radius(geometry_.bodies[body]);
    const double sweep = std::copysign(std::min(torque_scale_ * std::fabs(torque), kLongestSweep), torque);
    // Centred on the body's own "up", so the arc turns with it.
    const double start = pose[3 * body + 2] + 0.5 * std::numbers::pi - 0.5 * sweep;
    std::string label = "τ";
    if (geometry_.torques.size() > 1) label.append(std::to_string(i + 1));
    label.append(" = ").append(format_quantity(std::fabs(torque), "N m"));
    if (!tags) label.clear();
    out.torques.push_back(
        {Vec2(pose[3 * body], pose[3 * body + 1]), radius, start, sweep, std::move(label), static_cast<int>(body)});
  }
}

double MechanismScene::torque_radius(const MechanismGeometry::BodyShape& shape) const {
  // About a third of the body's size, but readable on a point mass and not past a long rod.
  const double size = std::max({shape.length, shape.width, 2 * shape.radius});
  return std::clamp(0.3 * size, extent_ / 30, extent_ / 12);
}

void MechanismScene::add_motors(std::size_t k, MechanismDrawList& out) const {
  // Each driver at its joint: a pin's motor at the joint's point with its torque on
  // bodies[1] as an arc (counter-clockwise positive), centred opposite that body's x axis
  // (a crank's arm); a slider's at the guide, with its force along the axis.
  const eval::MechanismSample& s = motion_.samples[k];
  if (!shown_.has(Element::motor)) return;
  for (std::size_t d = 0; d < geometry_.drivers.size() && d < s.drivers.size(); ++d) {
    const MechanismGeometry::DriverShape& driver = geometry_.drivers[d];
    const MechanismGeometry::JointShape& joint = geometry_.joints[driver.joint];
    const double value = s.drivers[d];
    if (!std::isfinite(value)) continue;  // not solved at this sample
    const int moved = joint.points[1].body, held = joint.points[0].body;
    const double theta1 = moved < 0 ? 0 : s.pose[3 * static_cast<std::size_t>(moved) + 2];
    const double theta0 = held < 0 ? 0 : s.pose[3 * static_cast<std::size_t>(held) + 2];
    const std::string label =
        shown_.has(Element::labels)
            ? driver.name + ": " + format_quantity(value, sym::joint_stages(joint.type).driver_unit)
            : "";
    switch (joint_type_info(joint.type).motion) {
      case JointMotion::revolute: {
        const Vec2 at = world_point(s.pose, joint.points[0]);
        // With the body it turns in the free-body view, as the joint's pin on the ground is.
        out.motors.push_back({at, Vec2::UnitX(), false, moved});
        if (driver_torque_scale_ <= 0 || value == 0) break;
        // Clear of the motor's symbol around the joint.
        const double radius =
            std::max(extent_ / 16, moved < 0 ? 0.0 : torque_radius(geometry_.bodies[static_cast<std::size_t>(moved)]));
        const double sweep = std::copysign(std::min(driver_torque_scale_ * std::fabs(value), kLongestSweep), value);
        out.torques.push_back({at, radius, theta1 + std::numbers::pi - 0.5 * sweep, sweep, label, moved, true});
        break;
      }
      case JointMotion::prismatic: {
        // At the slider's guide on its rail when the joints are drawn (placed under the body).
        Vec2 at = world_point(s.pose, joint.points[1]);
        const Vec2 axis = rotated(theta0, joint.axis), point = at;
        for (const MechanismDrawList::Marker& m : out.markers)
          if (m.kind == MechanismDrawList::Marker::Kind::guide && m.body == moved &&
              ((m.at - point).norm() < (at - point).norm() || at == point))
            at = m.at;
        out.motors.push_back({at, axis, true, moved});
        if (driver_scale_ <= 0 || value == 0) break;
        out.arrows.push_back(force_arrow(MechanismDrawList::Arrow::Kind::driver, at, value * axis, label));
        out.arrows.back().body = moved;
        break;
      }
      case JointMotion::fixed:  // not drivable
      case JointMotion::rolling:
      case JointMotion::slotted:
      case JointMotion::loop:
        break;
    }
  }
}

void MechanismScene::add_trails(std::size_t k, MechanismDrawList& out) const {
  const double now = motion_.times[k];
  const bool fine = !motion_.trail_times.empty();
  const std::vector<double>& times = fine ? motion_.trail_times : motion_.times;
  // The samples in [now - trail_seconds, now], finer than the frames when the motion has them.
  const auto first = std::lower_bound(times.begin(), times.end(), now - trail_seconds_ - 1e-9);
  const auto last = std::upper_bound(times.begin(), times.end(), now + 1e-9);
  // The trail's start between two samples: its point there, between theirs (a cycle's
  // trail then closes on itself to the samples' resolution).
  const double start = now - trail_seconds_;
  const bool between = first != times.begin() && first<last&& * first> start + 1e-9;
  const auto pose_at = [&](std::size_t i) -> const std::vector<double>& {
    return fine ? motion_.trail_poses[i] : motion_.samples[i].pose;
  };
  for (const BodyPoint& trail : trails_) {
    MechanismDrawList::Line line{MechanismDrawList::Line::Kind::trail, {}, {}};
    if (between) {
      const auto i = static_cast<std::size_t>(first - times.begin());
      const double f = (start - times[i - 1]) / (times[i] - times[i - 1]);
      line.points.push_back((1 - f) * world_point(pose_at(i - 1), trail) + f * world_point(pose_at(i), trail));
      line.fade.push_back(trail_fades_ ? 0.0 : 1.0);
    }
    for (auto it = first; it < last; ++it) {
      const auto i = static_cast<std::size_t>(it - times.begin());
      line.points.push_back(world_point(fine ? motion_.trail_poses[i] : motion_.samples[i].pose, trail));
      line.fade.push_back(trail_fades_ && trail_seconds_ > 0 ? std::clamp(1.0 - (now - *it) / trail_seconds_, 0.0, 1.0)
                                                             : 1.0);
    }
    line.body = trail.body;
    out.lines.push_back(std::move(line));
    // A traced point off its body's outline (a coupler point) is tied to the body's
    // centre by a thin bar, so the picture shows what carries it.
    if (trail.body < 0) continue;
    const std::vector<double>& pose = motion_.samples[k].pose;
    const auto b = static_cast<std::size_t>(trail.body);
    const Vec2 at = world_point(pose, trail), centre(pose[3 * b], pose[3 * b + 1]);
    // Grown by 5 % about the centre: a point on the outline (a rod's end) is the body's own.
    std::vector<Vec2> outline = body_outline(geometry_.bodies[b], pose, b);
    for (Vec2& v : outline) v = centre + 1.05 * (v - centre);
    if (!inside(outline, at)) out.lines.push_back({MechanismDrawList::Line::Kind::spin, {centre, at}, {}, trail.body});
  }
}

namespace {

// The clip's legend cut down to what this frame draws: a row per arrow kind present, and
// the cut and dashed notes only when such an arrow is in the frame.
void legend_for_frame(MechanismDrawList& out) {
  using Kind = MechanismDrawList::Arrow::Kind;
  MechanismDrawList::Legend& legend = out.legend;
  const auto present = [&](Kind kind) {
    return std::any_of(out.arrows.begin(), out.arrows.end(), [&](const auto& a) { return a.kind == kind; });
  };
  legend.joint = legend.joint && present(Kind::joint);
  const bool driver_torque =
      std::any_of(out.torques.begin(), out.torques.end(), [](const auto& t) { return t.driver; });
  legend.applied = legend.applied && (present(Kind::applied) || std::any_of(out.torques.begin(), out.torques.end(),
                                                                            [](const auto& t) { return !t.driver; }));
  std::erase_if(legend.rows, [&](const MechanismDrawList::Legend::Row& row) {
    return row.kind == Kind::driver && row.sweep > 0 ? !driver_torque : !present(row.kind);
  });
  legend.relative_velocity = legend.relative_velocity && present(Kind::velocity);
  legend.cut = std::any_of(out.arrows.begin(), out.arrows.end(), [](const auto& a) { return a.cut; });
  legend.stretched = std::any_of(out.arrows.begin(), out.arrows.end(), [](const auto& a) { return a.stretched; });
  if (std::none_of(out.lines.begin(), out.lines.end(),
                   [](const auto& l) { return l.kind == MechanismDrawList::Line::Kind::trail; }))
    legend.trails.clear();
  legend.com = legend.com && std::any_of(out.markers.begin(), out.markers.end(),
                                         [](const auto& m) { return m.kind == MechanismDrawList::Marker::Kind::com; });
}

}  // namespace

void MechanismScene::frame(std::size_t k, MechanismDrawList& out) const {
  out.clear();
  out.legend = legend_;
  out.shown = shown_;
  const eval::MechanismSample& s = motion_.samples[k];
  out.centre_of_mass = centroid(k);
  out.hud = {};
  if (k < motion_.energy_error.size()) out.hud.energy_error = motion_.energy_error[k];
  out.hud.constraint = motion_.constraints_kept;
  out.hud.energy = !motion_.prescribed;
  for (const double c : s.constraint) out.hud.constraint_error = std::max(out.hud.constraint_error, c);
  const std::vector<double>& pose = s.pose;
  const bool bodies = shown_.has(Element::blocks);
  for (std::size_t i = 0; bodies && i < geometry_.bodies.size(); ++i) {
    const MechanismGeometry::BodyShape& body = geometry_.bodies[i];
    out.outlines.push_back({i, body_outline(body, pose, i), body.shape});
    const Vec2 centre(pose[3 * i], pose[3 * i + 1]);
    if (body.shape == Shape::disc || body.shape == Shape::ring)  // a radius along body x, so the spin shows
      out.lines.push_back({MechanismDrawList::Line::Kind::spin,
                           {centre, centre + rotated(pose[3 * i + 2], {body.radius, 0.0})},
                           {},
                           static_cast<int>(i)});
    if (shown_.has(Element::labels)) out.labels.push_back({centre, body.name, static_cast<int>(i)});
  }
  for (std::size_t i = 0; shown_.has(Element::com) && i < geometry_.bodies.size(); ++i)
    out.markers.push_back(
        {MechanismDrawList::Marker::Kind::com, Vec2(pose[3 * i], pose[3 * i + 1]), Vec2::UnitX(), static_cast<int>(i)});
  for (const auto& [name, at] : geometry_.ground) out.markers.push_back({MechanismDrawList::Marker::Kind::ground, at});
  // In the free-body view a spring is the force it exerts, not a part.
  for (std::size_t i = 0; !free_body_ && i < geometry_.springs.size(); ++i)
    add_spring(geometry_.springs[i], i, pose, out);
  for (const MechanismGeometry::JointShape& joint : geometry_.joints)
    if (joint.torsion && !free_body_) add_torsion(joint, pose, out);

  const std::size_t first_marker = out.markers.size(), first_line = out.lines.size();
  for (std::size_t j = 0; j < geometry_.joints.size(); ++j) {
    const MechanismGeometry::JointShape& joint = geometry_.joints[j];
    const Vec2 p0 = world_point(pose, joint.points[0]), p1 = world_point(pose, joint.points[1]);
    std::array<Vec2, 2> force_at{p0, p1};
    switch (sym::joint_stages(joint.type).drawing) {  // the drawing of each joint type
      case sym::JointDrawing::marker:
        out.markers.push_back({MechanismDrawList::Marker::Kind::pin, p0});
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({p0, joint.name});
        break;
      case sym::JointDrawing::rail: {
        const double theta0 =
            joint.points[0].body < 0 ? 0 : pose[3 * static_cast<std::size_t>(joint.points[0].body) + 2];
        const Vec2 axis = rotated(theta0, joint.axis);
        const double margin = 0.1 * extent_;
        out.lines.push_back({MechanismDrawList::Line::Kind::rail,
                             {p0 + (rail_span_[j][0] - margin) * axis, p0 + (rail_span_[j][1] + margin) * axis}});
        out.markers.push_back({MechanismDrawList::Marker::Kind::guide, p1, axis});
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({p1, joint.name});
        break;
      }
      case sym::JointDrawing::rolling: {  // the line as a surface under the contact point K
        const double theta0 =
            joint.points[0].body < 0 ? 0 : pose[3 * static_cast<std::size_t>(joint.points[0].body) + 2];
        const Vec2 axis = rotated(theta0, joint.axis), normal(-axis.y(), axis.x());
        const Vec2 contact = p1 - joint.radius * normal;
        const double margin = 0.1 * extent_ + joint.radius;
        out.lines.push_back({MechanismDrawList::Line::Kind::surface,
                             {p0 + (rail_span_[j][0] - margin) * axis, p0 + (rail_span_[j][1] + margin) * axis},
                             {},
                             joint.points[0].body});
        out.markers.push_back({MechanismDrawList::Marker::Kind::pin, contact, axis, joint.points[1].body});
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({contact, joint.name});
        force_at = {contact, contact};
        break;
      }
      case sym::JointDrawing::slot: {  // a channel in bodies[0] over the pin's travel, the pin in it
        const double theta0 =
            joint.points[0].body < 0 ? 0 : pose[3 * static_cast<std::size_t>(joint.points[0].body) + 2];
        const Vec2 axis = rotated(theta0, joint.axis), normal(-axis.y(), axis.x());
        const double half = 0.025 * extent_;  // the channel's half width, a round end past each end of the travel
        const Vec2 start = p0 + rail_span_[j][0] * axis, end = p0 + rail_span_[j][1] * axis;
        MechanismDrawList::Line channel{MechanismDrawList::Line::Kind::slot, {}, {}, joint.points[0].body};
        constexpr int kArc = 12;
        for (int side = 0; side < 2; ++side)  // half a circle round each end, the sides between
          for (int i = 0; i <= kArc; ++i) {
            const double a = std::numbers::pi * (static_cast<double>(i) / kArc - 0.5);
            const Vec2 rim = side == 0 ? Vec2(std::cos(a) * axis + std::sin(a) * normal)
                                       : Vec2(-std::cos(a) * axis - std::sin(a) * normal);
            channel.points.push_back((side == 0 ? end : start) + half * rim);
          }
        out.lines.push_back(std::move(channel));
        out.markers.push_back({MechanismDrawList::Marker::Kind::pin, p1});
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({p1, joint.name});
        force_at = {p1, p1};
        break;
      }
      case sym::JointDrawing::gear: {  // labelled at the pitch point, where its force acts
        add_gear(joint, pose, out);
        const Vec2 pitch = p0 + joint.radii[0] / (joint.radii[0] + joint.mesh * joint.radii[1]) * (p1 - p0);
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({pitch, joint.name});
        force_at = {pitch, pitch};
        break;
      }
      case sym::JointDrawing::bracket: {
        // A leg toward each body's centre (along its x axis when the centre is at the point),
        // the second turned square when both would lie along one line.
        const auto leg = [&](std::size_t side) {
          const int body = joint.points[side].body;
          if (body < 0) return Vec2(Vec2::UnitX());
          const auto b = 3 * static_cast<std::size_t>(body);
          const Vec2 towards = Vec2(pose[b], pose[b + 1]) - p0;
          return towards.norm() > 1e-9 * extent_ ? Vec2(towards.normalized()) : rotated(pose[b + 2], Vec2::UnitX());
        };
        const Vec2 first = leg(0);
        Vec2 second = leg(1);
        if (std::fabs(first.x() * second.y() - first.y() * second.x()) < 0.5) second = Vec2(-first.y(), first.x());
        out.markers.push_back({MechanismDrawList::Marker::Kind::bracket, p0, first, -1, second});
        if (shown_.has(Element::labels) && !free_body_) out.joint_labels.push_back({p0, joint.name});
        break;
      }
    }
    if (force_scale_ <= 0) continue;
    const Vec2 force(s.force[3 * j], s.force[3 * j + 1]);
    for (std::size_t side = 0; side < 2 && shown_.has(Element::pin_force); ++side) {
      const int body = joint.points[side].body;
      if (body < 0) continue;  // the ground's reaction is not drawn
      // Named by its alias when it has one ("F on 1", "−F on 2"), else by its joint.
      const std::string by = joint.force_name.empty() ? joint.name : (side == 0 ? "" : "\u2212") + joint.force_name;
      out.arrows.push_back(force_arrow(
          MechanismDrawList::Arrow::Kind::joint, force_at[side], side == 0 ? force : Vec2(-force),
          shown_.has(Element::labels) ? by + " on " + geometry_.bodies[static_cast<std::size_t>(body)].name : ""));
      out.arrows.back().body = body;
    }
  }
  place_joints(pose, first_marker, first_line, out);
  add_loads(k, out);
  add_motors(k, out);
  add_load_arrows(k, out);
  add_trails(k, out);
  if (free_body_) pull_apart(k, out);
  legend_for_frame(out);
}

namespace {

// A slider's rail fixed to the body carrying it, as a drawing shows one: along the
// guided body's underside (not through its centre) and past its ends over the whole
// travel (not just its centre's), the guide where the body meets it; the ground's
// support at the rail's end when the slider is its only joint there (not inside the cart).
void rail_under_body(const std::vector<MechanismGeometry::JointShape>& joints, std::size_t j,
                     MechanismDrawList::Line& rail, MechanismDrawList::Marker& guide, MechanismDrawList& out) {
  const MechanismGeometry::JointShape& joint = joints[j];
  const auto body = std::find_if(out.outlines.begin(), out.outlines.end(),
                                 [&](const auto& o) { return static_cast<int>(o.body) == joint.points[1].body; });
  if (body == out.outlines.end() || rail.points.size() != 2) return;
  const Vec2 start = rail.points[0], end = rail.points[1];
  if ((end - start).norm() <= 0) return;
  const Vec2 along = (end - start).normalized(), across(-along.y(), along.x());
  double first = 0, last = 0, under = 0;
  for (const Vec2& p : body->points) {
    first = std::min(first, (p - guide.at).dot(along));
    last = std::max(last, (p - guide.at).dot(along));
    under = std::min(under, (p - guide.at).dot(across));
  }
  rail.points = {start + first * along + under * across, end + last * along + under * across};
  guide.at += under * across;
  if (joint.points[0].body >= 0) return;
  // The ground's support moves to the rail's start unless another joint also uses that point.
  const Vec2 anchor = joint.points[0].local;
  for (std::size_t other = 0; other < joints.size(); ++other)
    for (const BodyPoint& p : joints[other].points)
      if (other != j && p.body < 0 && (p.local - anchor).norm() < 1e-12) return;
  for (MechanismDrawList::Marker& m : out.markers)
    if (m.kind == MechanismDrawList::Marker::Kind::ground && (m.at - anchor).norm() < 1e-12) m.at = rail.points[0];
}

}  // namespace

void MechanismScene::place_joints(const std::vector<double>& pose, std::size_t first_marker, std::size_t first_line,
                                  MechanismDrawList& out) const {
  // The joints' drawing (one marker per joint, in order, a slider's rail with its guide):
  // gone with the joints hidden; else each part tied to its body, and pulled apart, a pin
  // on every body it joins (the ground's side is its support).
  if (!shown_.has(Element::pin)) {
    out.markers.erase(out.markers.begin() + static_cast<std::ptrdiff_t>(first_marker), out.markers.end());
    out.lines.erase(out.lines.begin() + static_cast<std::ptrdiff_t>(first_line), out.lines.end());
    return;
  }
  std::vector<MechanismDrawList::Marker> halves;
  for (std::size_t j = 0, m = first_marker, l = first_line; j < geometry_.joints.size(); ++j, ++m) {
    const auto& points = geometry_.joints[j].points;
    MechanismDrawList::Marker& marker = out.markers[m];
    const bool guide = marker.kind == MechanismDrawList::Marker::Kind::guide;
    if (guide) {
      while (out.lines[l].kind != MechanismDrawList::Line::Kind::rail) ++l;  // past another joint's line
      out.lines[l].body = points[0].body;
      rail_under_body(geometry_.joints, j, out.lines[l++], marker, out);
    }
    marker.body = points[guide ? 1 : 0].body;
    if (!free_body_ || guide) continue;
    if (points[0].body < 0) {
      marker.at = world_point(pose, points[1]);
      marker.body = points[1].body;
    } else if (points[1].body >= 0) {
      MechanismDrawList::Marker half = marker;  // a pin's circle or a weld's bracket
      half.at = world_point(pose, points[1]);
      half.body = points[1].body;
      halves.push_back(half);
    }
  }
  out.markers.insert(out.markers.end(), halves.begin(), halves.end());
}

void MechanismScene::pull_apart(std::size_t k, MechanismDrawList& out) const {
  // Each body moved away from the centroid by half its centre's distance from it: joined
  // bodies separate at their joints, each carrying its own forces and half of each pin.
  const Vec2 c = centroid(k);
  const std::vector<double>& pose = motion_.samples[k].pose;
  const auto offset = [&](int body) {
    if (body < 0) return Vec2(Vec2::Zero());
    const auto b = 3 * static_cast<std::size_t>(body);
    return Vec2(kApart * (Vec2(pose[b], pose[b + 1]) - c));
  };
  for (MechanismDrawList::Outline& o : out.outlines)
    for (Vec2& p : o.points) p += offset(static_cast<int>(o.body));
  for (MechanismDrawList::Line& l : out.lines)
    for (Vec2& p : l.points) p += offset(l.body);
  for (MechanismDrawList::Marker& m : out.markers) m.at += offset(m.body);
  for (MechanismDrawList::Arrow& a : out.arrows) a.tail += offset(a.body);
  for (MechanismDrawList::Torque& t : out.torques) t.centre += offset(t.body);
  for (MechanismDrawList::Motor& m : out.motors) m.at += offset(m.body);
  for (MechanismDrawList::Label& l : out.labels) l.at += offset(l.body);
}

}  // namespace linkage
