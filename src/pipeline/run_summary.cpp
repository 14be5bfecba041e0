#include "pipeline/run_summary.hpp"

#include "columns/mechanism_columns.hpp"
#include "core/number_format.hpp"

namespace linkage {
namespace {

// The rows every run's summary opens with: case, method, simulated time, steps, right-hand sides.
ResultTable run_summary(const SimulationOptions& o, const MechanismStats& st) {
  ResultTable t;
  t.headers = {"quantity", "value"};
  t.rows = {
      {"case", std::to_string(o.case_id)},
      {"method", st.kinematic ? std::string("kinematic analysis (0 degrees of freedom)") : method_text(o)},
      {"simulated time", format_significant(o.duration, 6) + " s"},
      {"steps", std::to_string(st.steps_accepted) + " accepted, " + std::to_string(st.steps_rejected) + " rejected"},
      {"right-hand sides", std::to_string(st.rhs_evaluations)},
  };
  return t;
}

/// "angle of body 2 (2.theta)" for a generalized coordinate, from its column's meaning,
/// the key as `built` names it ("(theta2)" on the homework).
std::string coordinate_words(const BuiltMechanism& built, const std::vector<MechanismColumn>& all,
                             const std::string& key, std::string& unit) {
  for (const MechanismColumn& c : all)
    if (c.name == key) {
      unit = c.unit;
      std::string words = c.meaning;  // without a closing remark such as "(not wrapped)"
      if (!words.empty() && words.back() == ')') words.erase(words.rfind(" ("));
      return words + " (" + built.named(key) + ")";
    }
  unit.clear();
  return built.named(key);
}

}  // namespace

std::string method_text(const SimulationOptions& o) {
  const IntegratorInfo& i = info(o.integrator);
  std::string text = std::string(i.name) + (i.adaptive ? " (rtol " + format_significant(o.rtol, 3) + ", atol " +
                                                             format_significant(o.atol, 3) + ")"
                                                       : " (dt " + format_significant(o.dt, 3) + " s)");
  if (o.case_id == 1) text += ", stabilization " + std::string(name(o.stabilization));
  return text;
}

ResultTable mechanism_summary(const Run& run, const MechanismStats& st, const Eigen::VectorXd& end) {
  const SimulationOptions& o = run.options;
  const sym::System& system = *run.built->system;
  ResultTable t = run_summary(o, st);
  t.rows.insert(t.rows.begin(), {"mechanism", system.mechanism().name});
  t.rows.insert(t.rows.end(), {
                                  {"largest energy-balance error",
                                   format_significant(st.max_energy_error, 3) + " of the energy scale"},
                                  {"largest constraint error",
                                   format_significant(st.max_constraint_error, 3) + " m (rad for a slider's angle)"},
                              });
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  const auto& coordinates = system.coordinates();
  for (std::size_t i = 0; i < coordinates.size() && static_cast<Eigen::Index>(i) < end.size(); ++i) {
    std::string unit;
    const std::string words = coordinate_words(*run.built, all, coordinates[i].coordinate.key, unit);
    t.rows.push_back({"final " + words,
                      format_significant(end[static_cast<Eigen::Index>(i)], 6) + (unit.empty() ? "" : " " + unit)});
  }
  if (!st.evaluator.empty()) t.rows.push_back({"evaluator", st.evaluator});
  t.rows.push_back({"run time", format_significant(st.wall_seconds * 1e3, 3) + " ms"});
  return t;
}

}  // namespace linkage
