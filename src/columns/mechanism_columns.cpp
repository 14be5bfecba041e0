#include "columns/mechanism_columns.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "columns/expression_column.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/parse_text.hpp"
#include "model/spanning_tree.hpp"
#include "symbolic/joints.hpp"

namespace linkage {

namespace {

/// Whether anything holds the mechanism to the ground: then its momenta are not constant.
bool grounded(const Mechanism& m) {
  for (const Joint& j : m.joints)
    if (j.bodies[0] == kGround || j.bodies[1] == kGround) return true;
  for (const Spring& s : m.springs)
    if (s.between[0].body == kGround || s.between[1].body == kGround) return true;
  return false;
}

}  // namespace

std::vector<MechanismColumn> mechanism_columns(const sym::System& system) {
  const Mechanism& m = system.mechanism();
  std::vector<MechanismColumn> out;
  using Q = MechanismQuantity;
  out.push_back({"t", "s", "time", Q::time, 0, true});
  const char* axes[] = {"x", "y", "theta"};
  for (std::size_t b = 0; b < system.bodies().size(); ++b) {
    const sym::BodySystem& body = system.bodies()[b];
    for (std::size_t c = 0; c < (body.rotates ? 3U : 2U); ++c)
      out.push_back({body.name + "." + axes[c], c == 2 ? "rad" : "m",
                     c == 2 ? "angle of body " + body.name + " (not wrapped)"
                            : std::string(axes[c]) + " of body " + body.name + "'s centre of mass",
                     Q::position, 3 * b + c, true});
  }
  for (std::size_t j = 0; j < m.joints.size(); ++j)
    if (const sym::OwnCoordinate* own = sym::joint_stages(m.joints[j].type).own)
      out.push_back(
          {m.joints[j].name + "." + own->base, own->units[0], own->meanings[0] + m.joints[j].name, Q::slider, j, true});
  for (std::size_t b = 0; b < system.bodies().size(); ++b) {
    const sym::BodySystem& body = system.bodies()[b];
    for (std::size_t c = 0; c < (body.rotates ? 3U : 2U); ++c)
      out.push_back({body.name + "." + axes[c] + "_dot", c == 2 ? "rad/s" : "m/s",
                     "rate of " + body.name + "." + axes[c], Q::rate, 3 * b + c, false});
  }
  for (std::size_t b = 0; b < system.bodies().size(); ++b) {
    const sym::BodySystem& body = system.bodies()[b];
    for (std::size_t c = 0; c < (body.rotates ? 3U : 2U); ++c)
      out.push_back({body.name + "." + axes[c] + "_ddot", c == 2 ? "rad/s^2" : "m/s^2",
                     "acceleration of " + body.name + "." + axes[c], Q::acceleration, 3 * b + c, false});
  }
  for (std::size_t j = 0; j < m.joints.size(); ++j)
    if (const sym::OwnCoordinate* own = sym::joint_stages(m.joints[j].type).own)
      out.push_back({m.joints[j].name + "." + own->base + "_ddot", own->units[2], own->meanings[2] + m.joints[j].name,
                     Q::slider_acceleration, j, false});
  const std::vector<eval::NamedPoint> points = eval::named_points(system);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const std::string name = system.bodies()[points[p].body].name + "." + points[p].name;
    static const char* const suffix[] = {"x", "y", "vx", "vy", "ax", "ay"};
    static const char* const unit[] = {"m", "m", "m/s", "m/s", "m/s^2", "m/s^2"};
    static const char* const what[] = {"x", "y", "velocity, x", "velocity, y", "acceleration, x", "acceleration, y"};
    for (std::size_t c = 0; c < 6; ++c)
      out.push_back({name + "." + suffix[c], unit[c], std::string(what[c]) + " of point " + name + " (world frame)",
                     Q::point, 6 * p + c, false});
  }
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    const Joint& joint = m.joints[j];
    const std::string on = "force of joint " + joint.name + " on " +
                           (joint.bodies[0] == kGround ? std::string("the ground") : "body " + joint.bodies[0]);
    out.push_back({joint.name + ".force_x", "N", on + ", x", Q::force, 3 * j, false});
    out.push_back({joint.name + ".force_y", "N", on + ", y", Q::force, 3 * j + 1, false});
    const sym::JointStages& stages = sym::joint_stages(joint.type);
    if (stages.moment_column)
      out.push_back({joint.name + ".moment", "N m", "moment of joint " + joint.name, Q::force, 3 * j + 2, false});
    if (stages.unknown_columns) {
      const std::vector<sym::ForceUnknown> unknowns = stages.unknowns(joint, false, on.substr(on.find(" on ") + 4));
      for (std::size_t u = 0; u < 2 && u < unknowns.size(); ++u)
        out.push_back({joint.name + "." + unknowns[u].key, unknowns[u].unit,
                       unknowns[u].meaning + " (joint " + joint.name + ")", Q::force, 3 * m.joints.size() + 2 * j + u,
                       false});
    }
    out.push_back({joint.name + ".constraint_error", stages.constraint_unit,
                   "|C| of joint " + joint.name + "'s position constraint", Q::constraint, j, false});
    out.push_back({joint.name + ".constraint_velocity_error", stages.constraint_rate_unit,
                   "|C'| of joint " + joint.name + "'s position constraint", Q::constraint_rate, j, false});
  }
  for (std::size_t d = 0; d < system.drivers().size(); ++d) {
    const Driver& driver = m.drivers[static_cast<std::size_t>(system.drivers()[d].index)];
    const Joint& joint = m.joints[static_cast<std::size_t>(system.drivers()[d].joint)];
    const sym::JointStages& stages = sym::joint_stages(joint.type);
    const std::string column = joint_type_info(joint.type).driver_column;
    out.push_back({driver.name + "." + column, stages.driver_unit,
                   "driver " + driver.name + "'s " + column + " on " +
                       (joint.bodies[1] == kGround ? std::string("the ground") : "body " + joint.bodies[1]) +
                       " at joint " + joint.name,
                   Q::driver, d, false});
  }
  if (!m.joints.empty()) {
    out.push_back({"constraint_position_error", "m", "|C| of every joint's position constraints together",
                   Q::constraints, 0, false});
    out.push_back({"constraint_velocity_error", "m/s", "|C'| of every joint's position constraints together",
                   Q::constraints_rate, 0, false});
  }
  static const char* const com_suffix[] = {"x", "y", "x_dot", "y_dot"};
  static const char* const com_what[] = {"x", "y", "velocity, x", "velocity, y"};
  for (std::size_t c = 0; c < 4; ++c)
    out.push_back({std::string("com.") + com_suffix[c], c < 2 ? "m" : "m/s",
                   std::string(com_what[c]) + " of the mechanism's centre of mass G", Q::com, c, false});
  for (std::size_t b = 0; b < system.bodies().size(); ++b)
    for (std::size_t c = 0; c < 2; ++c)
      out.push_back({system.bodies()[b].name + "." + axes[c] + "_from_com", "m",
                     std::string(axes[c]) + " of body " + system.bodies()[b].name + "'s centre of mass less G's",
                     Q::from_com, 2 * b + c, false});
  out.push_back({"energy", "J", "kinetic plus potential energy", Q::energy, 0, false});
  // Kinematic analysis integrates nothing: the work is the power's quadrature along the
  // solved path (integrate/kinematic_path.hpp), so the balance checks the torques to round-off.
  const bool kinematic = !system.drivers().empty() && degrees_of_freedom(m) == 0;
  out.push_back({"work", "J",
                 system.drivers().empty() ? "work done by dampers and applied loads since t = 0"
                 : kinematic ? "work done by dampers, applied loads and drivers since t = 0 (their power integrated "
                               "along the solved motion by Gauss-Legendre quadrature to round-off)"
                             : "work done by dampers, applied loads and drivers since t = 0",
                 Q::work, system.drivers().empty() ? 0U : 1U, false});  // index 1: with the drivers'
  out.push_back({"energy_error", "J",
                 kinematic ? "energy balance E - E(0) - work: 0 up to round-off (kinematic analysis)"
                           : "energy balance E - E(0) - work: 0 up to the integration error",
                 Q::energy_error, 0, false});
  out.push_back({"energy_error_relative", "", "|E - E(0) - work| / the energy scale (simulate's energy_scale)",
                 Q::energy_error_relative, 0, false});
  if (grounded(m)) {
    out.push_back({"shaking_force_x", "N",
                   "shaking force, x: the resultant the moving bodies exert on the ground through its joints, "
                   "drivers and springs",
                   Q::shaking, 0, false});
    out.push_back({"shaking_force_y", "N", "shaking force, y", Q::shaking, 1, false});
    out.push_back({"shaking_moment", "N m",
                   "shaking moment: the moment of the shaking force about the world origin, with the drivers' "
                   "reaction torques and the ground pins' spring-damper torques",
                   Q::shaking, 2, false});
  }
  if (!grounded(m)) {
    out.push_back({"momentum_x", "kg m/s", "linear momentum, x", Q::momentum_x, 0, false});
    out.push_back({"momentum_y", "kg m/s", "linear momentum, y", Q::momentum_y, 0, false});
    out.push_back(
        {"angular_momentum", "kg m^2/s", "angular momentum about the centre of mass", Q::angular_momentum, 0, false});
    out.push_back(
        {"momentum_x_error", "kg m/s", "|p_x - p_x(0)|: 0 up to the integration error", Q::momentum_x_error, 0, false});
    out.push_back({"momentum_y_error", "kg m/s", "|p_y - p_y(0) + M g t|: 0 up to the integration error",
                   Q::momentum_y_error, 0, false});
    out.push_back({"angular_momentum_error", "kg m^2/s", "|H_G - H_G(0)|: 0 up to the integration error",
                   Q::angular_momentum_error, 0, false});
    out.push_back({"com_parabola_error", "m", "distance of G from its free-fall parabola G(0) + G'(0) t - g t^2/2",
                   Q::com_parabola_error, 0, false});
  }
  for (MechanismColumn& c : out)
    if (const std::size_t dot = c.name.rfind('.'); dot != std::string::npos) c.owner = c.name.substr(0, dot);
  return out;
}

// Past this many characters the list of valid columns is shortened (a long chain has
// thousands); an error stays one readable line.
constexpr std::size_t kLongestValidList = 400;

MechanismColumn find_mechanism_column(const std::vector<MechanismColumn>& all, const std::string& name,
                                      const std::string& origin, bool groups, const sym::System* system) {
  if (defines_column(name)) return expression_column(all, system, name, origin);
  std::vector<std::string> names;
  if (groups) names = {"default", "all"};
  std::string nearest;
  std::size_t best = std::numeric_limits<std::size_t>::max();
  const std::string owner = name.substr(0, name.find('.') + 1);  // "S." prefers "S.s" to "t" for "S.x"
  for (const MechanismColumn& c : all) {
    if (c.name == name) return c;
    names.push_back(c.name);
    const std::size_t d = 2 * typo_distance(name, c.name) + (c.name.rfind(owner, 0) == 0 ? 0 : 1);
    if (d < best) {
      best = d;
      nearest = c.name;
    }
  }
  std::string valid = join_names(names);
  if (valid.size() > kLongestValidList) {
    // A large mechanism has hundreds of columns: the nearest one's body, point or joint
    // and the columns of none, and how to see the rest, keep the error to one short line.
    const std::string near_owner = nearest.substr(0, nearest.rfind('.') + 1);
    std::vector<std::string> some;
    if (groups) some = {"default", "all"};
    for (const MechanismColumn& c : all)
      if (c.name.find('.') == std::string::npos || (!near_owner.empty() && c.name.rfind(near_owner, 0) == 0 &&
                                                    c.name.find('.', near_owner.size()) == std::string::npos))
        some.push_back(c.name);
    valid = join_names(some) + " and " + std::to_string(all.size() + (groups ? 2 : 0) - some.size()) +
            " more (the columns of every body, point and joint; 'all' selects every one)";
  }
  throw Error::input(origin + ": unknown column '" + name + "'; nearest '" + nearest + "'; valid: " + valid);
}

std::vector<MechanismColumn> select_mechanism_columns(const std::vector<MechanismColumn>& all,
                                                      const std::vector<std::string>& names,
                                                      const std::function<std::string(std::size_t)>& origin,
                                                      const sym::System* system) {
  std::vector<MechanismColumn> out, defined = all;  // a definition may use those before it
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] != "default" && names[i] != "all") {
      out.push_back(find_mechanism_column(defined, names[i], origin(i), true, system));
      if (out.back().quantity == MechanismQuantity::expression) defined.push_back(out.back());
      continue;
    }
    for (const MechanismColumn& c : all)
      if ((c.by_default || names[i] == "all") && (c.quantity != MechanismQuantity::time || out.empty()))
        out.push_back(c);
  }
  if (!out.empty() && out.front().quantity != MechanismQuantity::time) out.insert(out.begin(), all.front());
  return out;
}

std::vector<MechanismColumn> select_mechanism_columns(const std::vector<MechanismColumn>& all, const std::string& spec,
                                                      const std::string& origin, const sym::System* system) {
  std::vector<std::string> names = split_commas(spec);
  if (!names.empty() && names.back().empty()) names.pop_back();  // "a,b," as getline read it
  if (names.empty()) {
    for (const MechanismColumn& c : all) names.push_back(c.name);
    throw Error::input(origin + ": empty list; valid: default, all, " + join_names(names));
  }
  return select_mechanism_columns(
      all, names, [&](std::size_t) { return origin; }, system);
}

bool needs_kinematics(const std::vector<MechanismColumn>& columns) {
  for (const MechanismColumn& c : columns) switch (c.quantity) {
      case MechanismQuantity::acceleration:
      case MechanismQuantity::slider_acceleration:
      case MechanismQuantity::point:
        return true;
      case MechanismQuantity::expression:
        for (const auto& [symbol, input] : c.expression->inputs)
          if (needs_kinematics({input})) return true;
        break;
      case MechanismQuantity::time:
      case MechanismQuantity::position:
      case MechanismQuantity::rate:
      case MechanismQuantity::slider:
      case MechanismQuantity::force:
      case MechanismQuantity::driver:
      case MechanismQuantity::constraint:
      case MechanismQuantity::constraint_rate:
      case MechanismQuantity::energy:
      case MechanismQuantity::energy_error:
      case MechanismQuantity::work:
      case MechanismQuantity::momentum_x:
      case MechanismQuantity::momentum_y:
      case MechanismQuantity::angular_momentum:
      case MechanismQuantity::com:
      case MechanismQuantity::from_com:
      case MechanismQuantity::constraints:
      case MechanismQuantity::constraints_rate:
      case MechanismQuantity::energy_error_relative:
      case MechanismQuantity::momentum_x_error:
      case MechanismQuantity::momentum_y_error:
      case MechanismQuantity::angular_momentum_error:
      case MechanismQuantity::com_parabola_error:
      case MechanismQuantity::shaking:
        break;
    }
  return false;
}

std::vector<MechanismColumn> named_columns(const std::vector<MechanismColumn>& all, std::string_view list,
                                           const std::string& origin, const sym::System* system) {
  if (list == "all") return all;
  std::vector<MechanismColumn> out, defined = all;
  for (const std::string& name : (list.empty() ? std::vector<std::string>{""} : split_commas(std::string(list)))) {
    if (defines_column(name)) {
      out.push_back(expression_column(defined, system, name, origin));
      defined.push_back(out.back());
      continue;
    }
    const auto named = [&](const MechanismColumn& c) { return c.name == name; };
    const auto found = std::find_if(all.begin(), all.end(), named);
    if (found == all.end()) {
      std::vector<std::string> names{"all"};
      for (const MechanismColumn& c : all) names.push_back(c.name);
      throw Error::invalid(
          origin, "'" + name + "' is not a column" + did_you_mean(name, names) + "; valid: " + join_names(names));
    }
    if (std::any_of(out.begin(), out.end(), named))
      throw Error::invalid(origin, "column '" + name + "' is listed twice");
    out.push_back(*found);
  }
  return out;
}

namespace {

/// The norm of per-joint norms: |C| of all the rows together.
double norm_of(const std::vector<double>& parts) {
  double sum = 0;
  for (const double p : parts) sum += p * p;
  return std::sqrt(sum);
}

}  // namespace

double column_value(const MechanismColumn& c, double t, const Eigen::VectorXd& y, const eval::MechanismSample& s,
                    const ColumnOrigin& o) {
  const double work = eval::work_of(y);
  const double energy0 = o.energy0;
  switch (c.quantity) {
    case MechanismQuantity::time:
      return t;
    case MechanismQuantity::position:
      return s.pose[c.index];
    case MechanismQuantity::rate:
      return s.rates[c.index];
    case MechanismQuantity::acceleration:
      return s.accelerations.at(c.index);
    case MechanismQuantity::slider:
      return s.slider[c.index];
    case MechanismQuantity::slider_acceleration:
      return s.slider_accelerations.at(c.index);
    case MechanismQuantity::point:
      return s.points.at(c.index);
    case MechanismQuantity::force:
      return s.force[c.index];
    case MechanismQuantity::driver:
      return s.drivers.at(c.index);
    case MechanismQuantity::constraint:
      return s.constraint[c.index];
    case MechanismQuantity::constraint_rate:
      return s.constraint_rate[c.index];
    case MechanismQuantity::energy:
      return s.kinetic + s.potential;
    case MechanismQuantity::energy_error:
      return s.kinetic + s.potential - energy0 - work;
    case MechanismQuantity::work:
      return work;
    case MechanismQuantity::momentum_x:
      return s.momentum_x;
    case MechanismQuantity::momentum_y:
      return s.momentum_y;
    case MechanismQuantity::angular_momentum:
      return s.angular_momentum;
    case MechanismQuantity::com:
      return s.com[c.index];
    case MechanismQuantity::from_com:
      return s.pose[3 * (c.index / 2) + c.index % 2] - s.com[c.index % 2];
    case MechanismQuantity::constraints:
      return norm_of(s.constraint);
    case MechanismQuantity::constraints_rate:
      return norm_of(s.constraint_rate);
    case MechanismQuantity::energy_error_relative:
      return std::fabs(s.kinetic + s.potential - energy0 - work) / o.energy_scale;
    case MechanismQuantity::momentum_x_error:
      return std::fabs(s.momentum_x - o.momentum_x0);
    case MechanismQuantity::momentum_y_error:
      return std::fabs(s.momentum_y - (o.momentum_y0 - o.weight * t));
    case MechanismQuantity::angular_momentum_error:
      return std::fabs(s.angular_momentum - o.angular_momentum0);
    case MechanismQuantity::expression:
      return expression_value(*c.expression, t, y, s, o);
    case MechanismQuantity::com_parabola_error:
      return std::hypot(s.com[0] - (o.com0[0] + o.com0[2] * t),
                        s.com[1] - (o.com0[1] + o.com0[3] * t - 0.5 * o.g * t * t));
    case MechanismQuantity::shaking:
      return s.shaking.at(c.index);
  }
  return 0;
}

std::string column_words(const MechanismColumn& c) {
  const std::string& owner = c.owner;
  static const char* const position[] = {"x of body ", "y of body ", "angle θ of body "};
  static const char* const rate[] = {"velocity ẋ of body ", "velocity ẏ of body ", "angular velocity θ̇ of body "};
  static const char* const acceleration[] = {"acceleration ẍ of body ", "acceleration ÿ of body ",
                                             "angular acceleration θ̈ of body "};
  static const char* const point[] = {"x of point ",
                                      "y of point ",
                                      "velocity v_{x} of point ",
                                      "velocity v_{y} of point ",
                                      "acceleration a_{x} of point ",
                                      "acceleration a_{y} of point "};
  using Q = MechanismQuantity;
  switch (c.quantity) {
    case Q::time:
      return "time t";
    case Q::position:
      return position[c.index % 3] + owner;
    case Q::rate:
      return rate[c.index % 3] + owner;
    case Q::acceleration:
      return acceleration[c.index % 3] + owner;
    case Q::point:
      return point[c.index % 6] + owner;
    case Q::energy:
      return "energy E = T + V";
    case Q::work:
      return c.index == 1 ? "work W of dampers, loads and drivers" : "work W of dampers and loads";
    case Q::energy_error:
      return "energy balance E − E_{0} − W";
    case Q::momentum_x:
      return "momentum p_{x}";
    case Q::momentum_y:
      return "momentum p_{y}";
    case Q::angular_momentum:
      return "angular momentum H_{G}";
    case Q::com: {
      static const char* const com[] = {"centre of mass x_{G}", "centre of mass y_{G}", "centre of mass velocity ẋ_{G}",
                                        "centre of mass velocity ẏ_{G}"};
      return com[c.index];
    }
    case Q::from_com:
      return (c.index % 2 == 0 ? "x − x_{G} of body " : "y − y_{G} of body ") + owner;
    case Q::constraints:
      return "constraint error |C|";
    case Q::constraints_rate:
      return "constraint rate error |Ċ|";
    case Q::energy_error_relative:
      return "relative energy error |E − E_{0} − W| / E_{scale}";
    case Q::momentum_x_error:
      return "momentum error |p_{x} − p_{x0}|";
    case Q::momentum_y_error:
      return "momentum error |p_{y} − p_{y0} + M g t|";
    case Q::angular_momentum_error:
      return "angular momentum error |H_{G} − H_{G0}|";
    case Q::com_parabola_error:
      return "distance of G from the parabola G_{0} + v_{0} t − g t^{2}/2";
    case Q::shaking: {
      static const char* const shaking[] = {"shaking force F_{x}", "shaking force F_{y}", "shaking moment M_{O}"};
      return shaking[c.index];
    }
    case Q::slider:
    case Q::slider_acceleration:
    case Q::force:
    case Q::driver:
    case Q::constraint:
    case Q::constraint_rate:
    case Q::expression:
      break;
  }
  return c.meaning;
}

std::string column_unit_markup(const MechanismColumn& c) {
  std::string unit;
  for (std::size_t i = 0; i < c.unit.size(); ++i) {
    if (c.unit[i] == '^') {  // "m^2/s" -> "m^{2}/s"
      std::size_t end = i + 1;
      while (end < c.unit.size() && (std::isdigit(static_cast<unsigned char>(c.unit[end])) || c.unit[end] == '-'))
        ++end;
      unit += "^{" + c.unit.substr(i + 1, end - i - 1) + "}";
      i = end - 1;
    } else {
      unit += c.unit[i];
    }
  }
  return unit;
}

}  // namespace linkage
