#include "report/json_report.hpp"

#include <algorithm>

namespace linkage {

using nlohmann::ordered_json;

namespace {

bool all_scalars(const ordered_json& container) {
  return std::none_of(container.begin(), container.end(), [](const ordered_json& v) { return v.is_structured(); });
}

// The container on one line: [1, 2] or {"a": 1, "b": 2}.
std::string one_line(const ordered_json& container) {
  std::string out(1, container.is_array() ? '[' : '{');
  bool first = true;
  for (const auto& [key, value] : container.items()) {
    if (!first) out += ", ";
    first = false;
    if (container.is_object()) out += ordered_json(key).dump() + ": ";
    out += value.dump();
  }
  return out + (container.is_array() ? ']' : '}');
}

void layout(const ordered_json& value, std::size_t indent, std::size_t used, std::string& out) {
  if (!value.is_structured() || value.empty()) {
    out += value.dump();
    return;
  }
  if (all_scalars(value)) {
    const std::string line = one_line(value);
    if (value.is_array() || used + line.size() <= 80) {
      out += line;
      return;
    }
  }
  const std::string inner(indent + 2, ' ');
  out += value.is_array() ? "[\n" : "{\n";
  bool first = true;
  for (const auto& [key, item] : value.items()) {
    if (!first) out += ",\n";
    first = false;
    out += inner;
    std::size_t prefix = inner.size();
    if (value.is_object()) {
      const std::string name = ordered_json(key).dump() + ": ";
      out += name;
      prefix += name.size();
    }
    layout(item, indent + 2, prefix, out);
  }
  out += '\n';
  out.append(indent, ' ');
  out += value.is_array() ? ']' : '}';
}

ordered_json case_json(const CaseSolution& c, const Params& p) {
  ordered_json item;
  item["case"] = c.id;
  item["title"] = std::string(c.title);
  ordered_json unknowns = ordered_json::array();
  ordered_json solution = ordered_json::object();
  for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
    const std::string key(info(c.unknowns[i]).key);
    unknowns.push_back(key);
    solution[key] = c.solution[static_cast<Eigen::Index>(i)];
  }
  ordered_json recovered = ordered_json::object();
  for (const UnknownInfo& u : kUnknowns) {
    const auto id = static_cast<Unknown>(&u - kUnknowns.data());
    if (std::find(c.unknowns.begin(), c.unknowns.end(), id) == c.unknowns.end())
      recovered[std::string(u.key)] = solution_value(c, id, p);
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
  item["recovered"] = recovered;
  item["residual"] = c.residual;
  item["condition_number"] = c.condition_number;
  item["equations"] = std::vector<std::string>(c.equations.begin(), c.equations.end());
  return item;
}

}  // namespace

std::string json_layout(const ordered_json& value) {
  std::string out;
  layout(value, 0, 0, out);
  return out + "\n";
}

std::string json_report(const WorkedSolution& w) {
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
  for (const CaseSolution& c : w.cases) cases.push_back(case_json(c, w.inputs.params()));
  doc["cases"] = cases;
  if (!w.agreement.empty()) {
    ordered_json agreement = ordered_json::object();
    for (const Agreement& a : w.agreement) agreement[std::string(info(a.unknown).key)] = a.max_abs_difference;
    doc["agreement"] = agreement;
  }
  return json_layout(doc);
}

}  // namespace linkage
