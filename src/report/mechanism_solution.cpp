#include "report/mechanism_solution.hpp"

#include <nlohmann/json.hpp>
#include <set>

#include "columns/mechanism_columns.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "evaluate/case_evaluator.hpp"
#include "model/mechanism_toml.hpp"
#include "report/json_layout.hpp"
#include "report/mechanism_parts.hpp"
#include "report/notation.hpp"
#include "symbolic/energy.hpp"
#include "symbolic/joints.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/validate.hpp"

namespace linkage {

namespace {

// Case 1's unknowns, in its order: every body's accelerations, then every joint's force
// components, then every driver's torque or force.
std::vector<GiNaC::symbol> case1_unknowns(const sym::System& system) {
  std::vector<GiNaC::symbol> out;
  for (const sym::BodySystem& b : system.bodies()) {
    out.push_back(b.x.q_ddot);
    out.push_back(b.y.q_ddot);
    if (b.rotates) out.push_back(b.theta.q_ddot);
  }
  for (const sym::JointSystem& j : system.joints()) out.insert(out.end(), j.unknowns.begin(), j.unknowns.end());
  for (const sym::DriverSystem& d : system.drivers()) out.push_back(d.unknown);
  return out;
}

double solved_value(const MechanismSolution& s, const SolvedCase& c, const GiNaC::symbol& u) {
  const auto value = case_value(c.system, c.numbers, s.values, u);
  if (!value) throw std::logic_error("a case has no value for a Case 1 unknown");
  return *value;
}

// Every number the reports print besides the matrices (solve_matrices checks those):
// the definitions and inertias (state_values checks them), the energy and momenta.
void require_printed_finite(const MechanismSolution& s) {
  const sym::System& system = *s.system;
  const GiNaC::ex T = sym::kinetic_energy(system), V = sym::potential_energy(system);
  const sym::Vec2 p = sym::linear_momentum(system);
  const std::pair<const char*, GiNaC::ex> quantities[] = {
      {"the kinetic energy T", T},
      {"the potential energy V", V},
      {"the energy E = T + V", T + V},
      {"the power P", sym::nonconservative_power(system)},
      {"the momentum p_x", p.x},
      {"the momentum p_y", p.y},
      {"the angular momentum H_O", sym::angular_momentum(system)},
      {"the angular momentum H_c", sym::angular_momentum_about_centre(system)}};
  for (const auto& [name, e] : quantities) require_finite(name, value_at(e, s.values));
}

void work_out_numbers(MechanismSolution& out, const std::vector<CaseId>& cases, CaseForm form) {
  const sym::System& system = *out.system;
  out.values = state_values(system, out.state, 0);
  require_printed_finite(out);
  for (CaseId id : cases) {
    const bool lagrange = form == CaseForm::lagrange && id == CaseId::reduced;
    SolvedCase solved{lagrange ? lagrange_case(system) : derive_case(system, id), {}};
    // The numbers from the case's own expressions, compiled.
    const eval::CaseEvaluator evaluator(system, solved.system);
    Eigen::MatrixXd A;
    Eigen::VectorXd B;
    evaluator.evaluate(evaluator.inputs(out.values), A, B);
    solved.numbers = solve_matrices(id, std::move(A), std::move(B));
    out.cases.push_back(std::move(solved));
  }
  if (out.cases.size() >= 2) {
    const CaseSystem reference = maximal_case(system);
    for (const GiNaC::symbol& u : reference.unknowns) {
      MechanismAgreement row{u, {}, {}, 0};
      for (const SolvedCase& c : out.cases) {
        bool recovered = false;
        row.values.push_back(case_value(c.system, c.numbers, out.values, u, &recovered));
        row.recovered.push_back(recovered);
      }
      for (std::size_t a = 0; a < row.values.size(); ++a)
        for (std::size_t b = a + 1; b < row.values.size(); ++b)
          if (row.values[a] && row.values[b])
            row.max_abs_difference = std::max(row.max_abs_difference, std::abs(*row.values[a] - *row.values[b]));
      out.agreement.push_back(std::move(row));
    }
  }
  for (const SolvedCase& c : out.cases) {
    for (Eigen::Index i = 0; i < c.numbers.solution.size(); ++i)
      require_finite(concat({"the Case ", std::to_string(case_number(c.system.id)), " solution"}),
                     c.numbers.solution(i));
    require_finite(concat({"the Case ", std::to_string(case_number(c.system.id)), " residual"}), c.numbers.residual);
  }
  for (const MechanismAgreement& row : out.agreement) {
    for (const auto& v : row.values)
      if (v) require_finite("a recovered value", *v);
    require_finite("a difference between cases", row.max_abs_difference);
  }
}

// What the worked derivation computes before the cases, keyed as the symbols are: the
// definitions and inertias, the inertias about the pins, each joint's position, the
// maximal coordinates and rates the generalized ones imply, the energy and momenta; and
// the unit of each in `units`.
nlohmann::ordered_json derived_json(const MechanismSolution& s, nlohmann::ordered_json& units) {
  const sym::System& system = *s.system;
  nlohmann::ordered_json derived = nlohmann::ordered_json::object();
  auto put = [&](const std::string& key, const GiNaC::ex& e, const std::string& unit) {
    derived[key] = value_at(e, s.values);
    units[key] = unit;
  };
  for (const sym::SymbolInfo& info : system.table().all())
    if (info.role == sym::Role::definition || info.role == sym::Role::inertia) put(info.key, info.symbol, info.unit);
  for (const PinInertia& p : pin_inertias(system)) put(p.ascii, p.formula, "kg m^2");
  const Mechanism& m = system.mechanism();
  for (const Joint& joint : m.joints) {
    const int body = m.body_index(joint.bodies[0]);
    const sym::Vec2 at = system.point_position(body, joint.points[0]);
    put(joint.name + ".x", at.x, "m");
    put(joint.name + ".y", at.y, "m");
  }
  for (const sym::SymbolInfo& info : system.table().all()) {
    if (info.role != sym::Role::coordinate && info.role != sym::Role::rate && info.role != sym::Role::length) continue;
    if (info.key.ends_with(".s") || info.key.ends_with(".s_dot")) continue;
    if (s.state.find(info.symbol) != s.state.end()) continue;  // in "state" already
    put(info.key, info.symbol, info.unit);
  }
  const GiNaC::ex T = sym::kinetic_energy(system), V = sym::potential_energy(system);
  put("kinetic_energy", T, "J");
  put("potential_energy", V, "J");
  put("energy", T + V, "J");
  const GiNaC::ex P = sym::nonconservative_power(system);
  if (!P.is_zero()) put("power", P, "W");
  const sym::Vec2 p = sym::linear_momentum(system);
  put("momentum_x", p.x, "kg m/s");
  put("momentum_y", p.y, "kg m/s");
  put("angular_momentum_O", sym::angular_momentum(system), "kg m^2/s");
  if (!touches_ground(system.mechanism()))
    put("angular_momentum_c", sym::angular_momentum_about_centre(system), "kg m^2/s");
  return derived;
}

// The [aliases] rename keys the JSON has or columns `simulate` writes, each to a name no
// other key has.
void check_aliases(const MechanismSolution& s) {
  const sym::System& system = *s.system;
  const Mechanism& m = system.mechanism();
  if (m.aliases.empty()) return;
  std::set<std::string> keys;
  for (const Parameter& p : m.parameters) keys.insert(p.name);
  nlohmann::ordered_json units;
  const nlohmann::ordered_json derived = derived_json(s, units);
  for (const auto& [key, value] : derived.items()) keys.insert(key);
  for (const sym::SymbolInfo& info : system.table().all()) keys.insert(info.key);
  for (const MechanismColumn& c : mechanism_columns(system)) keys.insert(c.name);  // simulate's, lessons' plots
  std::set<std::string> renamed;
  for (const Alias& a : m.aliases) renamed.insert(a.key);
  for (const Alias& a : m.aliases) {
    if (!keys.contains(a.key))
      throw Error::input(concat({where(a.pos), "[aliases]: '", a.key,
                                 "' is not a key of the JSON of the worked solution nor a trajectory column; valid: a "
                                 "key of its parameters, state, derived values or unknowns (linkage solve --mechanism ",
                                 m.name, " --format json) or a column (linkage simulate --mechanism ", m.name,
                                 " --columns all), e.g. 'I', '1.theta_ddot', 'com.x'"}));
    if (keys.contains(a.name) && !renamed.contains(a.name))
      throw Error::input(concat({where(a.pos), "[aliases]: '", a.key, "' = '", a.name, "' names the key '", a.name,
                                 "' the JSON already has; choose another alias"}));
  }
}

// [table]'s columns, each one of the mechanism's, at its entry's position in the file.
void check_table(const sym::System& system) {
  const Mechanism& m = system.mechanism();
  if (m.table.empty()) return;
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  for (const TableColumn& c : m.table) (void)find_mechanism_column(all, c.name, where(c.pos) + "[table]: columns");
}

// `object` with each key that has an alias renamed to it, in the same order.
nlohmann::ordered_json renamed(const nlohmann::ordered_json& object, const Mechanism& m) {
  auto name = [&](const std::string& key) { return m.aliased(key); };
  if (object.is_array()) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& key : object) out.push_back(name(key.get<std::string>()));
    return out;
  }
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : object.items()) out[name(key)] = value;
  return out;
}

// The file's aliases in place of the quantity keys they rename (bodies and joints keep
// their names).
void apply_aliases(nlohmann::ordered_json& doc, const Mechanism& m) {
  for (const char* section : {"parameters", "state", "derived", "solution", "units", "agreement"})
    if (doc.contains(section)) doc[section] = renamed(doc[section], m);
  for (auto& one : doc["cases"])
    for (const char* section : {"unknowns", "solution", "recovered"}) one[section] = renamed(one[section], m);
}

}  // namespace

MechanismSolution work_out_mechanism(const Mechanism& mechanism, const std::vector<CaseId>& cases, CaseForm form) {
  return work_out_mechanism(std::make_shared<const sym::System>(mechanism), cases, form);
}

MechanismSolution work_out_mechanism(std::shared_ptr<const sym::System> derived, const std::vector<CaseId>& cases,
                                     CaseForm form) {
  MechanismSolution out;
  out.system = std::move(derived);
  const sym::System& system = *out.system;
  const Mechanism& mechanism = system.mechanism();
  const sym::ClosedState closed = sym::checked_initial_state(system);
  out.state = closed.state;
  out.closure_note = closed.note;
  try {  // a number that overflows, or a singular matrix: name the values that likely caused it
    work_out_numbers(out, cases, form);
  } catch (const Error& e) {
    const std::string causes = likely_causes(mechanism);
    throw causes.empty() ? e : e.rephrased(concat({e.what(), "; likely causes: ", causes}));
  }
  check_aliases(out);
  check_table(system);
  return out;
}

BodyMotion body_motion(const MechanismSolution& s, const SolvedCase& c, std::size_t body) {
  const sym::BodySystem& b = s.system->bodies()[body];
  BodyMotion m;
  m.ax = solved_value(s, c, b.x.q_ddot);
  m.ay = solved_value(s, c, b.y.q_ddot);
  if (b.rotates) m.alpha = solved_value(s, c, b.theta.q_ddot);
  return m;
}

JointForce joint_force(const MechanismSolution& s, const SolvedCase& c, std::size_t joint) {
  const sym::JointSystem& j = s.system->joints()[joint];
  GiNaC::exmap unknowns = s.values;
  for (const GiNaC::symbol& u : j.unknowns) unknowns[u] = GiNaC::numeric(solved_value(s, c, u));
  JointForce f;
  f.fx = value_at(j.force.x, unknowns);
  f.fy = value_at(j.force.y, unknowns);
  if (sym::joint_stages(s.system->mechanism().joints[joint].type).moment_column)
    f.moment = value_at(j.moment, unknowns);
  return f;
}

std::string mechanism_json(const MechanismSolution& s, JsonKeys keys) {
  using nlohmann::ordered_json;
  const sym::System& system = *s.system;
  const Mechanism& m = system.mechanism();
  ordered_json doc;
  doc["mechanism"] = m.name;
  doc["title"] = m.title;
  ordered_json units = ordered_json::object();  // of every quantity the document gives
  for (const Parameter& p : m.parameters)
    if (!p.unit.empty()) units[p.name] = p.unit;
  ordered_json parameters = ordered_json::object();
  for (const Parameter& p : m.parameters) parameters[p.name] = p.value;
  doc["parameters"] = parameters;
  ordered_json state = ordered_json::object();
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    state[g.coordinate.key] = sym::to_double(s.state.at(g.symbols.q));
    state[g.coordinate.key + "_dot"] = sym::to_double(s.state.at(g.symbols.q_dot));
    units[g.coordinate.key] = system.table().find(g.symbols.q)->unit;
    units[g.coordinate.key + "_dot"] = system.table().find(g.symbols.q_dot)->unit;
  }
  doc["state"] = state;
  if (!s.closure_note.empty()) doc["loop_closure"] = s.closure_note;
  doc["derived"] = derived_json(s, units);
  auto key = [&](const GiNaC::symbol& u) { return system.table().find(u)->key; };
  ordered_json cases = ordered_json::array();
  for (const SolvedCase& c : s.cases) {
    ordered_json one;
    one["case"] = case_number(c.system.id);
    one["title"] = "Case " + std::to_string(case_number(c.system.id)) + ": " + c.system.title;
    ordered_json unknowns = ordered_json::array();
    for (const GiNaC::symbol& u : c.system.unknowns) unknowns.push_back(key(u));
    one["unknowns"] = unknowns;
    ordered_json A = ordered_json::array();
    for (Eigen::Index i = 0; i < c.numbers.A.rows(); ++i) {
      ordered_json row = ordered_json::array();
      for (Eigen::Index j = 0; j < c.numbers.A.cols(); ++j) row.push_back(c.numbers.A(i, j));
      A.push_back(row);
    }
    one["A"] = A;
    one["B"] = ordered_json(std::vector<double>(c.numbers.B.begin(), c.numbers.B.end()));
    ordered_json solution = ordered_json::object();
    for (std::size_t j = 0; j < c.system.unknowns.size(); ++j)
      solution[key(c.system.unknowns[j])] = c.numbers.solution(static_cast<Eigen::Index>(j));
    one["solution"] = solution;
    ordered_json recovered = ordered_json::object();
    for (const Recovered& r : c.system.recovered) recovered[key(r.symbol)] = solved_value(s, c, r.symbol);
    one["recovered"] = recovered;
    one["residual"] = c.numbers.residual;
    one["condition_number"] = c.numbers.condition;
    one["equations"] = c.system.labels;
    ordered_json bodies = ordered_json::object();
    for (std::size_t b = 0; b < system.bodies().size(); ++b) {
      throw_if_interrupted();  // a long chain's bodies and joints take seconds
      const BodyMotion motion = body_motion(s, c, b);
      bodies[system.bodies()[b].name] = {{"acceleration", {motion.ax, motion.ay}},
                                         {"angular_acceleration", motion.alpha}};
    }
    one["bodies"] = bodies;
    ordered_json joints = ordered_json::object();
    for (std::size_t j = 0; j < system.joints().size(); ++j) {
      throw_if_interrupted();
      const JointForce f = joint_force(s, c, j);
      ordered_json entry = {{"force", {f.fx, f.fy}}};
      if (f.moment) entry["moment"] = *f.moment;
      joints[m.joints[j].name] = entry;
    }
    one["joints"] = joints;
    if (!system.drivers().empty()) {
      ordered_json drivers = ordered_json::object();
      for (const sym::DriverSystem& d : system.drivers()) {
        const Driver& driver = m.drivers[static_cast<std::size_t>(d.index)];
        const Joint& joint = m.joints[static_cast<std::size_t>(d.joint)];
        drivers[driver.name] = {{joint_type_info(joint.type).driver_column, solved_value(s, c, d.unknown)}};
      }
      one["drivers"] = drivers;
    }
    cases.push_back(one);
  }
  doc["cases"] = cases;
  // The solution as example.json has it: every body's acceleration and every joint force,
  // from the first case shown (the cases agree to round-off; "agreement" says how well).
  if (!s.cases.empty()) {
    ordered_json solution = ordered_json::object();
    for (const GiNaC::symbol& u : case1_unknowns(system)) {
      solution[key(u)] = solved_value(s, s.cases.front(), u);
      units[key(u)] = system.table().find(u)->unit;
    }
    doc["solution"] = solution;
  }
  doc["units"] = units;
  if (!s.agreement.empty()) {
    ordered_json agreement = ordered_json::object();
    for (const MechanismAgreement& a : s.agreement) agreement[key(a.unknown)] = a.max_abs_difference;
    doc["agreement"] = agreement;
  }
  if (keys == JsonKeys::aliases) apply_aliases(doc, m);
  return json_layout(doc);
}

}  // namespace linkage
