#include "symbolic/validate.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "model/joint_types.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/joints.hpp"

namespace linkage::sym {

namespace {

// The quantity's value at the parameters (t = 0; a load's at the initial state too), or an
// error naming it.
double checked_value(const System& system, const Quantity& q, bool time_allowed, const std::string& what,
                     bool state_allowed = false) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants())
    values[symbol] = expression.subs(system.parameter_values());
  values[system.time()] = 0;
  double v = std::nan("");
  try {
    GiNaC::ex e = system.quantity(q, time_allowed, state_allowed);
    if (system.depends_on_state(e)) {
      const GiNaC::exmap state = system.initial_state();
      e = e.subs(system.to_generalized(), GiNaC::subs_options::no_pattern).subs(state);
    }
    v = to_double(e.subs(values));
  } catch (const Error&) {
    throw;
  } catch (const std::exception&) {
    v = std::nan("");
  }
  if (!std::isfinite(v))
    throw Error::input(where(q.pos) + what + " \"" + q.text +
                       "\" is not a finite number at the parameters (a division by zero, or the square root or "
                       "logarithm of a negative number); valid: an expression finite at the given values");
  return v;
}

void require_positive(const System& system, const Quantity& q, const std::string& what) {
  const double v = checked_value(system, q, false, what);
  if (!(v > 0))
    throw Error::input(where(q.pos) + what + " \"" + q.text + "\" is " + format_significant(v, 6) +
                       " at the parameters; valid: > 0");
}

void require_non_negative(const System& system, const Quantity& q, const std::string& what,
                          bool state_allowed = false) {
  const double v = checked_value(system, q, false, what, state_allowed);
  if (!(v >= 0))
    throw Error::input(where(q.pos) + what + " \"" + q.text + "\" is " + format_significant(v, 6) +
                       " at the parameters; valid: >= 0");
}

}  // namespace

void validate_quantities(const System& system) {
  const Mechanism& m = system.mechanism();
  for (const Definition& d : m.definitions) (void)checked_value(system, d.value, false, "definition " + d.name);
  for (const Driver& d : m.drivers) (void)checked_value(system, d.motion, true, "motion of driver " + d.name);
  if (m.gravity) require_non_negative(system, *m.gravity, "gravity");  // a magnitude: it acts along -y
  for (const NamedPoint& p : m.ground_points) {
    (void)checked_value(system, p.at.x, false, "ground point " + p.name + " x");
    (void)checked_value(system, p.at.y, false, "ground point " + p.name + " y");
  }
  for (const Body& b : m.bodies) {
    require_positive(system, b.mass, "mass of body " + b.name);
    if (b.length) require_positive(system, *b.length, "length of body " + b.name);
    if (b.width) require_positive(system, *b.width, "width of body " + b.name);
    if (b.radius) require_positive(system, *b.radius, "radius of body " + b.name);
    if (b.inertia) require_positive(system, *b.inertia, "inertia of body " + b.name);
    for (const NamedPoint& p : b.points) {
      (void)checked_value(system, p.at.x, false, "point " + b.name + "." + p.name + " x");
      (void)checked_value(system, p.at.y, false, "point " + b.name + "." + p.name + " y");
    }
  }
  for (const Joint& j : m.joints) {
    if (j.stiffness) require_non_negative(system, *j.stiffness, "stiffness of joint " + j.name, true);
    if (j.damping) require_non_negative(system, *j.damping, "damping of joint " + j.name, true);
    if (j.rest_angle) (void)checked_value(system, *j.rest_angle, false, "rest angle of joint " + j.name, true);
    if (j.angle) (void)checked_value(system, *j.angle, false, "angle of joint " + j.name);
    if (j.stiffness || j.damping)
      for (const std::string& body : j.bodies) {
        const Body* b = m.find_body(body);
        if (b != nullptr && !body_rotates(*b))
          throw Error::input(where(j.pos) + "the torsional spring-damper of joint " + j.name +
                             " acts on the point mass '" + body +
                             "', which has no angle; valid: a pin between bodies with a shape or an inertia");
      }
    const JointTypeInfo& info = joint_type_info(j.type);
    const std::string type = joint_type_name(j.type);
    if (info.axis) {
      const double ax = checked_value(system, j.axis->x, false, "axis x of joint " + j.name);
      const double ay = checked_value(system, j.axis->y, false, "axis y of joint " + j.name);
      if (ax == 0 && ay == 0)
        throw Error::input(where(j.axis->x.pos) + "the axis of " + type + " " + j.name +
                           " is zero at the parameters; valid: a direction of non-zero length");
    }
    if (info.radius && j.radius) {
      require_positive(system, *j.radius, "radius of " + type + " joint " + j.name);
      const Body* rolling = m.find_body(j.bodies[1]);
      if (rolling != nullptr && !body_rotates(*rolling))
        throw Error::input(where(j.pos) + type + " joint " + j.name + " rolls the point mass '" + j.bodies[1] +
                           "', which has no angle; valid: a rolling body with a shape or an inertia");
    }
    if (info.mesh && j.radii)
      for (std::size_t i = 0; i < 2; ++i)
        require_positive(system, (*j.radii)[i], "pitch radius of " + j.bodies[i] + " in " + type + " " + j.name);
    if (info.keeps_angle)
      for (const std::string& body : j.bodies) {
        const Body* b = m.find_body(body);
        if (b != nullptr && !body_rotates(*b))
          throw Error::input(where(j.pos) + type + " " + j.name + " joins the point mass '" + body +
                             "', which has no angle to keep; valid: bodies with a shape or an inertia");
      }
  }
  for (const Spring& s : m.springs) {
    require_non_negative(system, s.stiffness, "stiffness of spring " + s.name, true);
    require_non_negative(system, s.rest_length, "rest length of spring " + s.name, true);
    require_non_negative(system, s.damping, "damping of spring " + s.name, true);
  }
  for (const AppliedForce& f : m.forces) {
    (void)checked_value(system, f.value.x, true, "force on " + f.body + " x", true);
    (void)checked_value(system, f.value.y, true, "force on " + f.body + " y", true);
  }
  for (const AppliedTorque& t : m.torques) (void)checked_value(system, t.value, true, "torque on " + t.body, true);
}

void validate_meshes(const System& system, const GiNaC::exmap& state) {
  const Mechanism& m = system.mechanism();
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants()) values[symbol] = expression;
  for (const auto& [symbol, value] : state) values[symbol] = value;
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    const Joint& joint = m.joints[j];
    if (!joint_type_info(joint.type).mesh) continue;
    const std::array<GiNaC::ex, 2> radii = joint_radii(system, joint);
    const double r1 = evaluate(radii[0], values), r2 = evaluate(radii[1], values);
    const auto centre = [&](std::size_t i) {
      const Vec2 p = system.point_position(m.body_index(joint.bodies[i]), joint.points[i]);
      return std::array<double, 2>{
          evaluate(p.x.subs(system.to_generalized(), GiNaC::subs_options::no_pattern), values),
          evaluate(p.y.subs(system.to_generalized(), GiNaC::subs_options::no_pattern), values)};
    };
    const auto c1 = centre(0), c2 = centre(1);
    const double apart = std::hypot(c2[0] - c1[0], c2[1] - c1[1]);
    const double want = joint.internal ? std::fabs(r1 - r2) : r1 + r2;
    const std::string what = joint.internal ? "|r1 - r2|" : "r1 + r2";
    const std::string mesh = joint.internal ? "an internal mesh" : "an external mesh";
    if (joint.internal && !(want > 1e-9 * std::max(r1, r2)))
      throw Error::input(where(joint.pos) + "gear " + joint.name +
                         ": an internal mesh of equal pitch radii r1 = r2 = " + format_significant(r1, 6) +
                         " m has one centre; valid: r1 != r2 (the ring the larger)");
    if (!(std::fabs(apart - want) <= 1e-9 * want))
      throw Error::input(where(joint.pos) + "gear " + joint.name + ": the centres " + joint.bodies[0] + "." +
                         joint.points[0] + " and " + joint.bodies[1] + "." + joint.points[1] + " are " +
                         format_significant(apart, 10) + " m apart at the initial state, not " + what + " = " +
                         format_significant(want, 10) + " m (" + mesh + "); valid: pins on the carrier " + what +
                         " apart, within a relative 1e-9");
  }
}

void validate_constraints(const System& system, const GiNaC::exmap& state) {
  // The Jacobian of every joint's rows in maximal coordinates, at the state.
  std::vector<GiNaC::symbol> coordinates;
  for (const BodySystem& b : system.bodies()) {
    coordinates.push_back(b.x.q);
    coordinates.push_back(b.y.q);
    if (b.rotates) coordinates.push_back(b.theta.q);
  }
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants())
    values[symbol] = GiNaC::evalf(expression.subs(system.parameter_values()));
  for (const auto& [symbol, value] : state) values[symbol] = value;
  // Only the coordinates the rows hold: the rates' and accelerations' expressions grow
  // with the depth in the tree, and evaluating them cost a long chain most of this check.
  for (const GiNaC::symbol& q : coordinates) {
    throw_if_interrupted();
    if (const auto it = system.to_generalized().find(q);
        it != system.to_generalized().end() && !it->second.has(system.time()))
      values[q] = GiNaC::evalf(it->second.subs(values));
  }
  const Mechanism& m = system.mechanism();
  // Every joint's rows; a row's derivative by a coordinate it does not hold is 0.
  std::vector<Eigen::MatrixXd> jacobians;
  Eigen::Index total = 0;
  for (std::size_t j = 0; j < system.joints().size(); ++j) {
    throw_if_interrupted();
    const auto& phi = system.joints()[j].constraints;
    Eigen::MatrixXd jacobian =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(phi.size()), static_cast<Eigen::Index>(coordinates.size()));
    for (std::size_t r = 0; r < phi.size(); ++r)
      for (std::size_t c = 0; c < coordinates.size(); ++c)
        if (phi[r].has(coordinates[c]))
          jacobian(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
              to_double(GiNaC::diff(phi[r], coordinates[c]).subs(values));
    if (!jacobian.allFinite()) {  // an overflow, not a redundancy: name the values behind it
      const std::string causes = likely_causes(m);
      throw Error::input(where(m.joints[j].pos) + "the constraint of joint " + m.joints[j].name +
                         " is not a finite number at the initial state (an overflow of double precision)" +
                         (causes.empty() ? std::string() : "; likely causes: " + causes) +
                         "; valid: parameters and initial values of physical sizes");
    }
    total += jacobian.rows();
    jacobians.push_back(std::move(jacobian));
  }
  // All rows independent: no joint is redundant (one factorization, not one per joint).
  Eigen::MatrixXd all(total, static_cast<Eigen::Index>(coordinates.size()));
  for (Eigen::Index at = 0; const Eigen::MatrixXd& jacobian : jacobians) {
    all.middleRows(at, jacobian.rows()) = jacobian;
    at += jacobian.rows();
  }
  Eigen::FullPivLU<Eigen::MatrixXd> whole(all);
  whole.setThreshold(1e-9);
  if (whole.rank() == total) return;
  // Else the first joint that adds less than its rows' count to the rank.
  Eigen::MatrixXd rows(0, static_cast<Eigen::Index>(coordinates.size()));
  Eigen::Index rank = 0;
  for (std::size_t j = 0; j < system.joints().size(); ++j) {
    const auto& phi = system.joints()[j].constraints;
    Eigen::MatrixXd more(rows.rows() + static_cast<Eigen::Index>(phi.size()), rows.cols());
    more.topRows(rows.rows()) = rows;
    more.bottomRows(static_cast<Eigen::Index>(phi.size())) = jacobians[j];
    Eigen::FullPivLU<Eigen::MatrixXd> lu(more);
    lu.setThreshold(1e-9);
    const Eigen::Index new_rank = lu.rank();
    if (new_rank < rank + static_cast<Eigen::Index>(phi.size())) {
      std::string earlier;
      for (std::size_t k = 0; k < j; ++k) earlier += (earlier.empty() ? "" : ", ") + m.joints[k].name;
      if (earlier.empty()) {  // nothing before it to repeat: its own rows are degenerate at these values
        const std::string causes = likely_causes(m);
        throw Error::input(where(m.joints[j].pos) + "the constraint rows of joint " + m.joints[j].name +
                           " are not independent at the initial state (values of very different sizes, or a "
                           "degenerate geometry)" +
                           (causes.empty() ? std::string() : "; likely causes: " + causes) +
                           "; valid: parameters and initial values of physical sizes");
      }
      throw Error::input(where(m.joints[j].pos) + "joint " + m.joints[j].name +
                         " is redundant at the initial state: joints " + earlier +
                         " already fix what it constrains (one joint too many, or links in line at a change "
                         "point); valid: remove the joint, or start away from that position");
    }
    rank = new_rank;
    rows = std::move(more);
  }
}

}  // namespace linkage::sym
