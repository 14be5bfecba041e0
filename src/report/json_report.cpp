#include "report/json_report.hpp"

#include <nlohmann/json.hpp>

namespace linkage {

std::string json_report(const WorkedSolution& w) {
  using nlohmann::ordered_json;
  ordered_json doc;
  ordered_json params = ordered_json::object();
  ordered_json state = ordered_json::object();
  for (const auto& key : kInputKeys)
    (key.param != nullptr ? params : state)[std::string(key.key)] = w.inputs.value(key);
  doc["parameters"] = params;
  doc["state"] = state;

  const Derived& d = w.derived;
  doc["derived"] = {
      {"I_zz_C", d.I_zz_C},
      {"D", d.D},
      {"I_zz_P", d.I_zz_P},
      {"x_P", d.pin.x()},
      {"y_P", d.pin.y()},
      {"x2", d.C2.x()},
      {"y2", d.C2.y()},
      {"x2_dot", d.C2_dot.x()},
      {"y2_dot", d.C2_dot.y()},
      {"kinetic_energy", d.invariants.kinetic_energy},
      {"potential_energy", d.invariants.potential_energy},
      {"energy", d.invariants.energy},
      {"momentum_x", d.invariants.momentum.x()},
      {"momentum_y", d.invariants.momentum.y()},
      {"angular_momentum", d.invariants.angular_momentum},
  };

  ordered_json cases = ordered_json::array();
  for (const CaseSolution& c : w.cases) {
    ordered_json item;
    item["case"] = c.id;
    ordered_json unknowns = ordered_json::array();
    ordered_json solution = ordered_json::object();
    for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
      const std::string key(info(c.unknowns[i]).key);
      unknowns.push_back(key);
      solution[key] = c.solution[static_cast<Eigen::Index>(i)];
    }
    item["unknowns"] = unknowns;
    ordered_json A = ordered_json::array();
    for (Eigen::Index r = 0; r < c.A.rows(); ++r) {
      ordered_json row = ordered_json::array();
      for (Eigen::Index col = 0; col < c.A.cols(); ++col) row.push_back(c.A(r, col));
      A.push_back(row);
    }
    item["A"] = A;
    item["B"] = std::vector<double>(c.B.data(), c.B.data() + c.B.size());
    item["solution"] = solution;
    item["residual"] = c.residual;
    item["condition_number"] = c.condition_number;
    item["equations"] = std::vector<std::string>(c.equations.begin(), c.equations.end());
    cases.push_back(item);
  }
  doc["cases"] = cases;
  return doc.dump(2) + "\n";
}

}  // namespace linkage
