#include "report/mechanism_solution.hpp"

#include <nlohmann/json.hpp>

#include "evaluate/case_evaluator.hpp"
#include "report/json_report.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/validate.hpp"

namespace linkage {

namespace {

double solved_value(const MechanismSolution& s, const SolvedCase& c, const GiNaC::symbol& u) {
  const auto value = case_value(c.system, c.numbers, s.values, u);
  if (!value) throw std::logic_error("a case has no value for a Case 1 unknown");
  return *value;
}

}  // namespace

MechanismSolution work_out_mechanism(const Mechanism& mechanism, const std::vector<CaseId>& cases) {
  MechanismSolution out;
  out.system = std::make_shared<const sym::System>(mechanism);
  const sym::System& system = *out.system;
  sym::validate_quantities(system);
  sym::validate_constraints(system, system.initial_state());  // structural redundancy, before closing
  const sym::ClosedState closed = sym::close_loops(system, system.initial_state());
  sym::validate_constraints(system, closed.state);
  out.state = closed.state;
  out.closure_note = closed.note;
  out.values = state_values(system, out.state, 0);
  for (CaseId id : cases) {
    SolvedCase solved{derive_case(system, id), {}};
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
  if (s.system->mechanism().joints[joint].type == JointType::slider) f.moment = value_at(j.moment, unknowns);
  return f;
}

std::string mechanism_json(const MechanismSolution& s) {
  using nlohmann::ordered_json;
  const sym::System& system = *s.system;
  const Mechanism& m = system.mechanism();
  ordered_json doc;
  doc["mechanism"] = m.name;
  doc["title"] = m.title;
  ordered_json parameters = ordered_json::object();
  for (const Parameter& p : m.parameters) parameters[p.name] = p.value;
  doc["parameters"] = parameters;
  ordered_json state = ordered_json::object();
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    state[g.coordinate.key] = sym::to_double(s.state.at(g.symbols.q));
    state[g.coordinate.key + "_dot"] = sym::to_double(s.state.at(g.symbols.q_dot));
  }
  doc["state"] = state;
  if (!s.closure_note.empty()) doc["loop_closure"] = s.closure_note;
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
      const BodyMotion motion = body_motion(s, c, b);
      bodies[system.bodies()[b].name] = {{"acceleration", {motion.ax, motion.ay}},
                                         {"angular_acceleration", motion.alpha}};
    }
    one["bodies"] = bodies;
    ordered_json joints = ordered_json::object();
    for (std::size_t j = 0; j < system.joints().size(); ++j) {
      const JointForce f = joint_force(s, c, j);
      ordered_json entry = {{"force", {f.fx, f.fy}}};
      if (f.moment) entry["moment"] = *f.moment;
      joints[m.joints[j].name] = entry;
    }
    one["joints"] = joints;
    cases.push_back(one);
  }
  doc["cases"] = cases;
  if (!s.agreement.empty()) {
    ordered_json agreement = ordered_json::object();
    for (const MechanismAgreement& a : s.agreement) agreement[key(a.unknown)] = a.max_abs_difference;
    doc["agreement"] = agreement;
  }
  return json_layout(doc);
}

}  // namespace linkage
