#include "symbolic/system.hpp"

#include <cln/float.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "model/body_phrase.hpp"
#include "model/joint_types.hpp"
#include "symbolic/expression_reader.hpp"
#include "symbolic/joints.hpp"
#include "symbolic/spelling.hpp"
#include "symbolic/units.hpp"

namespace linkage::sym {

using GiNaC::ex;
using GiNaC::symbol;

Vec2 rotate(const ex& angle, const Vec2& v) {
  const ex c = GiNaC::cos(angle);
  const ex s = GiNaC::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

ex cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

ex simplify_trig(const ex& e) {
  ex out = GiNaC::expand(e);
  // Only the arguments whose sine occurs squared or higher: a substitution that matches
  // nothing leaves the expression as it was, and costs a pass over it.
  GiNaC::exset arguments;
  for (auto i = out.preorder_begin(); i != out.preorder_end(); ++i)
    if (GiNaC::is_a<GiNaC::power>(*i) && GiNaC::is_a<GiNaC::function>(i->op(0)) &&
        GiNaC::ex_to<GiNaC::function>(i->op(0)).get_name() == "sin")
      arguments.insert(i->op(0).op(0));
  for (const ex& x : arguments)
    out = GiNaC::expand(
        out.subs(GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2), GiNaC::subs_options::algebraic));
  return out;
}

namespace {

// As IEEE arithmetic rounds: beyond double range inf, below it 0, where CLN would throw
// (so the finiteness checks name the values, not "floating point overflow").
double rounded(const GiNaC::numeric& n) {
  try {
    return n.to_double();
  } catch (const cln::floating_point_overflow_exception&) {
    return n.is_negative() ? -HUGE_VAL : HUGE_VAL;
  } catch (const cln::floating_point_underflow_exception&) {
    return n.is_negative() ? -0.0 : 0.0;
  }
}

}  // namespace

double evaluate(const ex& e, const GiNaC::exmap& values) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
    return n.is_real() ? rounded(n) : std::nan("");
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const auto it = values.find(e);
    if (it == values.end())
      throw std::logic_error("not a number: no value for " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return evaluate(it->second, values);
  }
  if (GiNaC::is_a<GiNaC::constant>(e)) return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double();
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    const ex distributed = in_double_range(e);
    if (!distributed.is_equal(e)) return evaluate(distributed, values);
  }
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    const bool sum = GiNaC::is_a<GiNaC::add>(e);
    std::vector<double> parts;
    parts.reserve(e.nops());
    for (std::size_t k = 0; k < e.nops(); ++k) {
      parts.push_back(evaluate(e.op(k), values));
      if (std::isnan(parts.back())) return std::nan("");
    }
    // By magnitude, so the order does not depend on the signs: GiNaC writes (b - a)^2 or
    // (a - b)^2 as its hash order falls from run to run, and a sum of the negated parts in
    // ascending order would round differently.
    std::sort(parts.begin(), parts.end(),
              [](double x, double y) { return std::fabs(x) != std::fabs(y) ? std::fabs(x) < std::fabs(y) : x > y; });
    double acc = sum ? 0.0 : 1.0;
    for (const double p : parts) acc = sum ? acc + p : acc * p;
    return acc;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const double base = evaluate(e.op(0), values);
    const ex exponent = e.op(1);
    if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer())
      return std::pow(base, GiNaC::ex_to<GiNaC::numeric>(exponent).to_int());
    if (exponent.is_equal(GiNaC::numeric(1, 2))) return std::sqrt(base);
    if (exponent.is_equal(GiNaC::numeric(-1, 2))) return 1 / std::sqrt(base);
    return std::pow(base, evaluate(exponent, values));
  }
  if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const double x = evaluate(e.op(0), values);
    if (name == "sin") return std::sin(x);
    if (name == "cos") return std::cos(x);
    if (name == "tan") return std::tan(x);
    if (name == "exp") return std::exp(x);
    if (name == "log") return x < 0 ? std::nan("") : std::log(x);
    if (name == "abs") return std::abs(x);
    if (name == "asin") return std::asin(x);
    if (name == "acos") return std::acos(x);
    if (name == "atan") return std::atan(x);
  }
  if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 2 && GiNaC::ex_to<GiNaC::function>(e).get_name() == "atan2")
    return std::atan2(evaluate(e.op(0), values), evaluate(e.op(1), values));
  std::ostringstream text;
  text << e;
  throw std::logic_error("not a number: " + text.str());
}

double to_double(const ex& e) { return evaluate(e, {}); }

ex in_double_range(const ex& e) {
  if (!GiNaC::is_a<GiNaC::mul>(e)) return e;
  const GiNaC::numeric largest(std::numeric_limits<double>::max()), smallest(std::numeric_limits<double>::min());
  for (std::size_t k = 0; k < e.nops(); ++k) {
    if (!GiNaC::is_a<GiNaC::numeric>(e.op(k))) continue;
    const GiNaC::numeric size = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(k)));
    if (size > largest || (!size.is_zero() && size < smallest)) return GiNaC::expand(e);
  }
  return e;
}

namespace {

int body_index(const Mechanism& m, const std::string& name) {
  for (std::size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

System::System(const Mechanism& mechanism) : mechanism_(mechanism), tree_(spanning_tree(mechanism)) {
  // The state's names, known before the bodies' symbols are: a mass or a definition that
  // names one is refused as such, not as an unknown name.
  for (const Body& body : mechanism_.bodies)
    for (const char* base : {"x", "y", "theta"})
      if (std::string_view(base) != "theta" || body_rotates(body))
        for (const char* suffix : {"", "_dot"}) refused_[body.name + "." + base + suffix] = t_;
  for (const Joint& joint : mechanism_.joints)
    if (const OwnCoordinate* own = joint_stages(joint.type).own)
      for (const char* suffix : {"", "_dot"}) refused_[joint.name + "." + own->base + suffix] = t_;
  add_parameters();
  // The time of applied loads, printed like any symbol.
  table_.add({t_, Role::time, "t", "t", "t", "t", "s", "time"});
  add_bodies();
  add_joints();
  add_drivers();
  add_state_names();
  add_loads();
  add_generalized();
  set_joint_constants();
  add_newton_euler();
}

ex System::quantity(const Quantity& q, bool time_allowed, bool state_allowed) const {
  GiNaC::symtab names = names_;
  if (time_allowed) names["t"] = t_;
  if (state_allowed) names.insert(state_.begin(), state_.end());
  std::string origin = where(q.pos);
  if (origin.size() >= 2 && origin.compare(origin.size() - 2, 2, ": ") == 0) origin.resize(origin.size() - 2);
  return read_expression(q.text, origin,
                         {names, time_allowed ? std::string_view() : "(t only in [[force]] and [[torque]] values)",
                          &equation_functions(), state_allowed ? nullptr : &refused_,
                          std::string(time_allowed ? "parameters, definitions and t" : "parameters and definitions") +
                              " (the state's coordinates and rates only in [[force]] and [[torque]] values, a "
                              "spring's stiffness, rest_length and damping, and a pin's stiffness, damping and "
                              "rest_angle)"});
}

bool System::depends_on_state(const ex& e) const {
  for (const BodySystem& b : bodies_)
    for (const CoordinateSymbols* c : {&b.x, &b.y, &b.theta})
      if ((b.rotates || c != &b.theta) && (e.has(c->q) || e.has(c->q_dot))) return true;
  return false;
}

void System::add_state_names() {
  // As the columns name them; a slider's s is not a maximal coordinate: its expression.
  for (const BodySystem& b : bodies_)
    for (const CoordinateSymbols* c : {&b.x, &b.y, &b.theta}) {
      if (c == &b.theta && !b.rotates) continue;
      const std::string& key = table_.find(c->q)->key;
      state_[key] = c->q;
      state_[key + "_dot"] = c->q_dot;
    }
  for (std::size_t j = 0; j < mechanism_.joints.size(); ++j) {
    const Joint& joint = mechanism_.joints[j];
    const JointStages& stages = joint_stages(joint.type);
    if (stages.own == nullptr) continue;
    const ex s = stages.coordinate(maximal_ends(*this, static_cast<int>(j)));
    state_[joint.name + "." + stages.own->base] = s;
    state_[joint.name + "." + stages.own->base + "_dot"] = time_derivative(s);
  }
}

void System::add_parameters() {
  names_["pi"] = GiNaC::Pi;
  for (const Parameter& p : mechanism_.parameters) {
    const Spelling spelling = spell_name(p.name);
    const SymbolInfo& info = table_.add(
        {symbol(p.name), Role::parameter, p.name, spelling.unicode, spelling.ascii, spelling.latex, p.unit, p.meaning});
    names_[p.name] = info.symbol;
    parameter_values_[info.symbol] = GiNaC::numeric(p.value);
  }
  for (const Definition& d : mechanism_.definitions) {
    const ex value = quantity(d.value, false).subs(constants_);
    const Spelling spelling = spell_name(d.name);
    const SymbolInfo& info = table_.add({symbol(d.name), Role::definition, d.name, spelling.unicode, spelling.ascii,
                                         spelling.latex, unit_of(value, table_).value_or(""), ""});
    names_[d.name] = info.symbol;
    constants_[info.symbol] = value;
  }
}

void System::add_bodies() {
  // One inertia symbol "I" when every rotating body has the same formula (the homework's
  // identical blocks), else one per body.
  std::vector<ex> formulas;
  for (const Body& body : mechanism_.bodies) {
    const ex mass = quantity(body.mass, false);
    auto size = [&](const std::optional<Quantity>& q) { return q ? quantity(*q, false) : ex(0); };
    ex formula = 0;
    if (body.inertia) {
      formula = quantity(*body.inertia, false);
    } else {
      switch (body.shape) {
        case Shape::rectangle:
          formula = mass * (GiNaC::pow(size(body.width), 2) + GiNaC::pow(size(body.length), 2)) / 12;
          break;
        case Shape::rod:
          formula = mass * GiNaC::pow(size(body.length), 2) / 12;
          break;
        case Shape::disc:
          formula = mass * GiNaC::pow(size(body.radius), 2) / 2;
          break;
        case Shape::ring:  // all the mass at the rim
          formula = mass * GiNaC::pow(size(body.radius), 2);
          break;
        case Shape::point:
          formula = 0;
          break;
      }
    }
    formulas.push_back(formula);
  }
  bool shared = true;
  const ex* first = nullptr;
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    if (!body_rotates(mechanism_.bodies[i])) continue;
    if (first == nullptr)
      first = &formulas[i];
    else
      shared = shared && (formulas[i] - *first).expand().is_zero();
  }
  ex shared_symbol = 0;
  if (shared && first != nullptr) {
    const SymbolInfo& info =
        table_.add({symbol("I"), Role::inertia, "I", "I", "I", "I_{zz}^{C}", "kg m^2", "centroidal moment of inertia"});
    shared_symbol = info.symbol;
    constants_[info.symbol] = first->subs(constants_);
  }

  for (std::size_t i = 0; i < mechanism_.bodies.size(); ++i) {
    const Body& body = mechanism_.bodies[i];
    BodySystem b;
    b.name = body.name;
    b.mass = quantity(body.mass, false);
    b.rotates = body_rotates(body);
    b.inertia_formula = formulas[i];
    if (b.rotates) {
      if (shared) {
        b.inertia = shared_symbol;
      } else {
        const Spelling s = spell_indexed("I", 0, body.name);
        const SymbolInfo& info =
            table_.add({symbol("I_" + body.name), Role::inertia, body.name + ".inertia", s.unicode, s.ascii, s.latex,
                        "kg m^2", "centroidal moment of inertia of " + body_phrase(body)});
        b.inertia = info.symbol;
        constants_[info.symbol] = formulas[i].subs(constants_);
      }
    }
    const std::string phrase = body_phrase(body);
    auto make = [&](const char* base, const char* unit0, const char* meaning0, const char* unit1, const char* meaning1,
                    const char* unit2, const char* meaning2) {
      CoordinateSymbols c;
      const std::string stem = body.name + "." + base;
      const Spelling s0 = spell_indexed(base, 0, body.name);
      const Spelling s1 = spell_indexed(base, 1, body.name);
      const Spelling s2 = spell_indexed(base, 2, body.name);
      c.q = table_
                .add({symbol(stem), Role::coordinate, stem, s0.unicode, s0.ascii, s0.latex, unit0,
                      std::string(meaning0) + phrase})
                .symbol;
      c.q_dot = table_
                    .add({symbol(stem + "_dot"), Role::rate, stem + "_dot", s1.unicode, s1.ascii, s1.latex, unit1,
                          std::string(meaning1) + phrase})
                    .symbol;
      c.q_ddot = table_
                     .add({symbol(stem + "_ddot"), Role::acceleration, stem + "_ddot", s2.unicode, s2.ascii, s2.latex,
                           unit2, std::string(meaning2) + phrase})
                     .symbol;
      derivative_[c.q] = c.q_dot;
      derivative_[c.q_dot] = c.q_ddot;
      return c;
    };
    b.x = make("x", "m", "x of the centre of mass of ", "m/s", "x velocity of ", "m/s^2", "x acceleration of ");
    b.y = make("y", "m", "y of the centre of mass of ", "m/s", "y velocity of ", "m/s^2", "y acceleration of ");
    if (b.rotates)
      b.theta = make("theta", "rad", "angle from +x of ", "rad/s", "angular velocity of ", "rad/s^2",
                     "angular acceleration of ");
    for (const NamedPoint& p : body.points) {
      const Vec2 at{quantity(p.at.x, false), quantity(p.at.y, false)};
      if (!b.rotates && !(at.x.is_zero() && at.y.is_zero()))
        throw Error::input(where(p.pos) + "point '" + p.name + "' of the point mass '" + body.name +
                           "' is not at its centre; valid: [0, 0] (a point mass has no extent)");
      b.points[p.name] = at;
    }
    bodies_.push_back(std::move(b));
  }
}

Vec2 System::point_position(int body, const std::string& point) const {
  if (body < 0) {
    for (const NamedPoint& p : mechanism_.ground_points)
      if (p.name == point) return {quantity(p.at.x, false), quantity(p.at.y, false)};
    throw std::logic_error("ground point missing: " + point);
  }
  const BodySystem& b = bodies_[static_cast<std::size_t>(body)];
  const Vec2 origin{b.x.q, b.y.q};
  return origin + rotate(b.rotates ? ex(b.theta.q) : ex(0), b.points.at(point));
}

void System::add_drivers() {
  for (std::size_t i = 0; i < mechanism_.drivers.size(); ++i) {
    const Driver& d = mechanism_.drivers[i];
    DriverSystem ds;
    ds.index = static_cast<int>(i);
    for (std::size_t j = 0; j < mechanism_.joints.size(); ++j)
      if (mechanism_.joints[j].name == d.joint) ds.joint = static_cast<int>(j);
    const Joint& joint = mechanism_.joints.at(static_cast<std::size_t>(ds.joint));
    const JointStages& stages = joint_stages(joint.type);
    const GiNaC::ex driven = stages.driven(maximal_ends(*this, ds.joint));
    if (driven.is_zero())  // a pin between two point masses has no angle to drive
      throw Error::input(where(d.pos) + "driver '" + d.name + "': joint '" + joint.name + "' joins bodies without " +
                         "angles; valid: a pin with a body that rotates, or a slider");
    ds.constraint = driven - quantity(d.motion, true);
    const std::string column = joint_type_info(joint.type).driver_column;
    const Spelling spelling = spell_indexed(stages.driver_letter, 0, d.name);
    ds.unknown =
        table_
            .add({symbol(d.name + "." + column), Role::force, d.name + "." + column, spelling.unicode, spelling.ascii,
                  spelling.latex, stages.driver_unit, "driver " + d.name + "'s " + column + " on " + joint.bodies[1]})
            .symbol;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      const BodySystem& body = bodies_[b];
      const Vec2 force{ds.unknown * ds.constraint.diff(body.x.q), ds.unknown * ds.constraint.diff(body.y.q)};
      const GiNaC::ex moment = body.rotates ? ds.unknown * ds.constraint.diff(body.theta.q) : GiNaC::ex(0);
      if (!(force.x.is_zero() && force.y.is_zero() && moment.is_zero()))
        ds.loads.push_back({static_cast<int>(b), force, {body.x.q, body.y.q}, moment, "driver " + d.name});
    }
    drivers_.push_back(std::move(ds));
  }
}

void System::add_joints() {
  const bool single = mechanism_.joints.size() == 1;
  for (const Joint& joint : mechanism_.joints) {
    const JointStages& stages = joint_stages(joint.type);
    if (stages.constant_letter == nullptr) {
      joint_constants_.emplace_back(0);
      continue;
    }
    const Spelling s = spell_indexed(stages.constant_letter, 0, joint.name);
    const std::string key = joint.name + ".constant";
    joint_constants_.emplace_back(
        table_
            .add({symbol(key), Role::definition, key, s.unicode, s.ascii, s.latex, stages.constant_unit,
                  "constant of joint " + joint.name + ", its row's value at the start"})
            .symbol);
  }
  for (std::size_t j = 0; j < mechanism_.joints.size(); ++j) {
    const Joint& joint = mechanism_.joints[j];
    JointSystem js;
    js.index = static_cast<int>(j);
    for (int t : tree_.tree_joints) js.in_tree = js.in_tree || t == js.index;
    const int a = body_index(mechanism_, joint.bodies[0]);
    const JointEnds ends = maximal_ends(*this, js.index);
    const std::string stem = joint.name + ".";
    const std::string on =
        a < 0 ? std::string("the ground") : body_phrase(mechanism_.bodies[static_cast<std::size_t>(a)]);
    const JointStages& stages = joint_stages(joint.type);
    for (const ForceUnknown& u : stages.unknowns(joint, single, on))
      js.unknowns.push_back(table_
                                .add({symbol(stem + u.key), Role::force, stem + u.key, u.spelling.unicode,
                                      u.spelling.ascii, u.spelling.latex, u.unit, u.meaning})
                                .symbol);
    js.constraints = stages.rows(ends);
    stages.force(js, ends);
    joints_.push_back(std::move(js));
  }
}

void System::add_loads() {
  if (mechanism_.gravity) {
    const ex g = quantity(*mechanism_.gravity, false);
    if (!g.is_zero())
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const BodySystem& b = bodies_[i];
        loads_.push_back({static_cast<int>(i), {0, -b.mass * g}, {b.x.q, b.y.q}, 0, "gravity"});
      }
  }
  for (const Spring& spring : mechanism_.springs) {
    const int a = body_index(mechanism_, spring.between[0].body);
    const int b = body_index(mechanism_, spring.between[1].body);
    const Vec2 pa = point_position(a, spring.between[0].point);
    const Vec2 pb = point_position(b, spring.between[1].point);
    const Vec2 d = pb - pa;
    // The length as a symbol of its own, so the loads read k (l - l0) d / l rather than
    // with the square root written out everywhere; its rate is d . d' / l.
    const Spelling spelling = spell_indexed("l", 0, spring.name);
    const ex length = table_
                          .add({symbol("l_" + spring.name), Role::length, spring.name + ".length", spelling.unicode,
                                spelling.ascii, spelling.latex, "m", "length of spring " + spring.name})
                          .symbol;
    lengths_[length] = GiNaC::sqrt(d.x * d.x + d.y * d.y);
    derivative_[length] = (d.x * time_derivative(d.x) + d.y * time_derivative(d.y)) / length;
    const ex tension = quantity(spring.stiffness, false, true) * (length - quantity(spring.rest_length, false, true)) +
                       quantity(spring.damping, false, true) * time_derivative(length);
    // Tension pulls b towards a and a towards b.
    const Vec2 on_b = (-tension / length) * d;
    if (b >= 0) loads_.push_back({b, on_b, pb, 0, spring.name});
    if (a >= 0) loads_.push_back({a, ex(-1) * on_b, pa, 0, spring.name});
  }
  for (const Joint& joint : mechanism_.joints) {
    if (!joint_type_info(joint.type).torsional_spring || (!joint.stiffness && !joint.damping)) continue;
    const int a = body_index(mechanism_, joint.bodies[0]);
    const int b = body_index(mechanism_, joint.bodies[1]);
    auto angle = [&](int i) {
      return i < 0 || !bodies_[static_cast<std::size_t>(i)].rotates ? ex(0)
                                                                    : ex(bodies_[static_cast<std::size_t>(i)].theta.q);
    };
    const ex relative = angle(b) - angle(a);
    const ex rest = joint.rest_angle ? quantity(*joint.rest_angle, false, true) : ex(0);
    ex torque = 0;
    if (joint.stiffness) torque -= quantity(*joint.stiffness, false, true) * (relative - rest);
    if (joint.damping) torque -= quantity(*joint.damping, false, true) * time_derivative(relative);
    if (b >= 0) loads_.push_back({b, {}, {}, torque, joint.name});
    if (a >= 0) loads_.push_back({a, {}, {}, -torque, joint.name});
  }
  int count = 0;
  for (const AppliedForce& force : mechanism_.forces) {
    const int body = body_index(mechanism_, force.body);
    const Vec2 value{quantity(force.value.x, true, true), quantity(force.value.y, true, true)};
    loads_.push_back({body, value, point_position(body, force.point), 0, "force " + std::to_string(++count)});
  }
  count = 0;
  for (const AppliedTorque& torque : mechanism_.torques) {
    const int body = body_index(mechanism_, torque.body);
    loads_.push_back({body, {}, {}, quantity(torque.value, true, true), "torque " + std::to_string(++count)});
  }
}

ex System::time_derivative(const ex& e) const {
  // de/dt + sum over the symbols q that e holds of de/dq q'. A sum is differentiated term
  // by term, each term by the symbols it holds only: a long chain's positions hold a term
  // per link, and differentiating the whole sum by each of its symbols would cost their
  // product (n^3 over the chain). The sum of the terms' derivatives is the same canonical
  // expression as GiNaC's diff of the whole sum.
  const std::size_t count = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
  std::map<ex, GiNaC::exvector, GiNaC::ex_is_less> by_symbol;  // q (or t) -> d term / dq
  for (std::size_t k = 0; k < count; ++k) {
    const ex term = count == 1 ? e : e.op(k);
    GiNaC::exset held;
    for (auto i = term.preorder_begin(); i != term.preorder_end(); ++i)
      if (GiNaC::is_a<symbol>(*i)) held.insert(*i);
    for (const ex& q : held)
      if (q.is_equal(t_) || derivative_.count(q) != 0)
        by_symbol[q].push_back(GiNaC::diff(term, GiNaC::ex_to<symbol>(q)));
  }
  GiNaC::exvector out;
  out.reserve(by_symbol.size());
  for (const auto& [q, parts] : by_symbol) {
    const ex derivative = GiNaC::add(parts);
    out.push_back(q.is_equal(t_) ? derivative : derivative * derivative_.at(q));
  }
  return GiNaC::add(out);
}

void System::add_generalized() {
  std::vector<Placement> placed(bodies_.size());
  auto placement_of = [&](int body) {
    if (body < 0) return Placement{};
    return placed[static_cast<std::size_t>(body)];
  };
  for (int body : tree_.order) {
    throw_if_interrupted();
    const auto i = static_cast<std::size_t>(body);
    const TreeBody& node = tree_.bodies[i];
    const BodySystem& bs = bodies_[i];
    if (node.floating) {
      placed[i] = {{bs.x.q, bs.y.q}, bs.rotates ? ex(bs.theta.q) : ex(0)};
      continue;
    }
    const Joint& joint = mechanism_.joints[static_cast<std::size_t>(node.joint)];
    const int a = body_index(mechanism_, joint.bodies[0]);
    const bool child_is_b = a != body;
    JointEnds ends;
    const int other = child_is_b ? a : body_index(mechanism_, joint.bodies[1]);
    Placement parent = placement_of(other);
    auto local = [&](int b, const std::string& point) {
      return b < 0 ? point_position(-1, point) : bodies_[static_cast<std::size_t>(b)].points.at(point);
    };
    ends.point_a = local(a, joint.points[0]);
    ends.point_b = local(body_index(mechanism_, joint.bodies[1]), joint.points[1]);
    (child_is_b ? ends.a : ends.b) = parent;
    ends.axis = joint_axis(*this, joint);
    ends.angle = joint_angle(*this, joint);
    ends.radius = joint_radius(*this, joint);
    const JointStages& stages = joint_stages(joint.type);
    TreeCoordinates coordinates{bs.rotates ? ex(bs.theta.q) : ex(0), 0};
    if (stages.own != nullptr) {  // the joint's own coordinate: s
      const OwnCoordinate& own = *stages.own;
      const std::string stem = joint.name + "." + own.base;
      CoordinateSymbols c;
      const Role roles[] = {Role::coordinate, Role::rate, Role::acceleration};
      const char* suffixes[] = {"", "_dot", "_ddot"};
      symbol* symbols[] = {&c.q, &c.q_dot, &c.q_ddot};
      for (int k = 0; k < 3; ++k) {
        const Spelling sp = spell_indexed(own.base, k, joint.name);
        const std::string key = stem + suffixes[k];
        *symbols[k] = table_
                          .add({symbol(key), roles[k], key, sp.unicode, sp.ascii, sp.latex, own.units[k],
                                own.meanings[k] + joint.name})
                          .symbol;
      }
      derivative_[c.q] = c.q_dot;
      derivative_[c.q_dot] = c.q_ddot;
      slider_symbols_[node.joint] = c;
      coordinates.travel = c.q;
    }
    placed[i] = stages.place(ends, child_is_b, coordinates);
  }

  for (const Coordinate& c : tree_.coordinates) {
    const BodySystem& b = bodies_[static_cast<std::size_t>(c.body)];
    GeneralizedCoordinate g{c, {}};
    switch (c.kind) {
      case CoordinateKind::x:
        g.symbols = b.x;
        break;
      case CoordinateKind::y:
        g.symbols = b.y;
        break;
      case CoordinateKind::theta:
        g.symbols = b.theta;
        break;
      case CoordinateKind::s:
        g.symbols = slider_symbols_.at(c.joint);
        break;
    }
    coordinates_.push_back(g);
  }

  // Every maximal symbol that is not itself generalized, as an expression in them.
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    throw_if_interrupted();
    const BodySystem& b = bodies_[i];
    const Placement& p = placed[i];
    auto map = [&](const CoordinateSymbols& c, const ex& position) {
      if (position.is_equal(c.q)) return;
      const ex rate = time_derivative(position);
      to_generalized_[c.q] = position;
      to_generalized_[c.q_dot] = rate;
      to_generalized_[c.q_ddot] = time_derivative(rate);
    };
    map(b.x, p.position.x);
    map(b.y, p.position.y);
    if (b.rotates) map(b.theta, p.angle);
  }
}

void System::add_newton_euler() {
  std::vector<Vec2> sum_force(bodies_.size());
  std::vector<ex> sum_moment(bodies_.size(), ex(0));
  auto apply = [&](int body, const Vec2& force, const Vec2& point, const ex& moment) {
    if (body < 0) return;
    const auto i = static_cast<std::size_t>(body);
    const BodySystem& b = bodies_[i];
    sum_force[i] = sum_force[i] + force;
    if (b.rotates) sum_moment[i] += cross(point - Vec2{b.x.q, b.y.q}, force) + moment;
  };
  // Joint forces first, in joint order, so each row reads as the homework's: "m x1'' - Fx".
  for (const JointSystem& js : joints_) {
    const Joint& joint = mechanism_.joints[static_cast<std::size_t>(js.index)];
    const int a = body_index(mechanism_, joint.bodies[0]);
    const int b = body_index(mechanism_, joint.bodies[1]);
    const auto [at_a, at_b] = force_points(*this, js.index);
    apply(a, js.force, at_a, js.moment);
    apply(b, ex(-1) * js.force, at_b, -js.moment);
  }
  for (const Load& load : loads_) apply(load.body, load.force, load.point, load.moment);
  for (const DriverSystem& d : drivers_)
    for (const Load& load : d.loads) apply(load.body, load.force, load.point, load.moment);
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodySystem& b = bodies_[i];
    NewtonEulerRows rows{static_cast<int>(i), {}};
    rows.rows.push_back(GiNaC::expand(b.mass * b.x.q_ddot - sum_force[i].x));
    rows.rows.push_back(GiNaC::expand(b.mass * b.y.q_ddot - sum_force[i].y));
    if (b.rotates) rows.rows.push_back(GiNaC::expand(b.inertia * b.theta.q_ddot - sum_moment[i]));
    newton_euler_.push_back(std::move(rows));
  }
}

void System::set_joint_constants() {
  // Its value: the rest of its row at the file's initial state, in the parameters.
  const GiNaC::exmap start = initial_state();
  for (const JointSystem& js : joints_) {
    const ex& c = joint_constants_[static_cast<std::size_t>(js.index)];
    if (c.is_zero()) continue;
    const ex rest = GiNaC::expand(js.constraints.at(0) + c);
    constants_[c] = GiNaC::expand(rest.subs(to_generalized_, GiNaC::subs_options::no_pattern)
                                      .subs(start, GiNaC::subs_options::no_pattern)
                                      .subs(constants_));
  }
}

GiNaC::exmap System::initial_state() const {
  GiNaC::exmap state;
  for (const GeneralizedCoordinate& g : coordinates_) {
    double q = 0, rate = 0;
    for (const InitialValue& v : mechanism_.initial) {
      if (v.key == g.coordinate.key) q = v.value;
      if (v.key == g.coordinate.key + "_dot") rate = v.value;
    }
    state[g.symbols.q] = GiNaC::numeric(q);
    state[g.symbols.q_dot] = GiNaC::numeric(rate);
  }
  return state;
}

}  // namespace linkage::sym
