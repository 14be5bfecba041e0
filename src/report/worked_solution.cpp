#include "report/worked_solution.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage {
namespace {

void require_finite(double value, const std::string& name, const Inputs& inputs) {
  if (std::isfinite(value)) return;
  const std::string causes = likely_causes(inputs);
  throw Error::input(name + " = " + format_roundtrip(value) +
                     " overflows double precision; the inputs must keep every derived quantity finite" +
                     (causes.empty() ? "" : " (inputs: " + causes + ")"));
}

void check_derived(const Derived& d, const Inputs& inputs) {
  const Invariants& v = d.invariants;
  const std::pair<const char*, double> values[] = {{"I_zz^C", d.I_zz_C},
                                                   {"D", d.D},
                                                   {"I_zz^P", d.I_zz_P},
                                                   {"x_P", d.pin.x()},
                                                   {"y_P", d.pin.y()},
                                                   {"x2", d.C2.x()},
                                                   {"y2", d.C2.y()},
                                                   {"x2_dot", d.C2_dot.x()},
                                                   {"y2_dot", d.C2_dot.y()},
                                                   {"kinetic energy", v.kinetic_energy},
                                                   {"potential energy", v.potential_energy},
                                                   {"energy", v.energy},
                                                   {"momentum_x", v.momentum.x()},
                                                   {"momentum_y", v.momentum.y()},
                                                   {"angular momentum", v.angular_momentum}};
  for (const auto& [name, value] : values) require_finite(value, name, inputs);
}

void check_case(const CaseSolution& c, const Inputs& inputs) {
  const std::string where = "a Case " + std::to_string(c.id) + " ";
  for (Eigen::Index i = 0; i < c.A.size(); ++i) require_finite(c.A.data()[i], where + "matrix entry", inputs);
  for (Eigen::Index i = 0; i < c.B.size(); ++i) require_finite(c.B[i], where + "right-hand side", inputs);
  for (Eigen::Index i = 0; i < c.solution.size(); ++i) require_finite(c.solution[i], where + "solution value", inputs);
  require_finite(c.residual, where + "residual", inputs);
  require_finite(c.condition_number, where + "condition number", inputs);
}

std::vector<Agreement> compare_cases(const std::vector<CaseSolution>& cases, const Params& p) {
  std::vector<Agreement> table;
  if (cases.size() < 2) return table;
  for (const UnknownInfo& u : kUnknowns) {
    Agreement row;
    row.unknown = static_cast<Unknown>(&u - kUnknowns.data());
    for (const CaseSolution& c : cases) {
      row.values.push_back(solution_value(c, row.unknown, p));
      row.recovered.push_back(std::find(c.unknowns.begin(), c.unknowns.end(), row.unknown) == c.unknowns.end());
    }
    const auto [lo, hi] = std::minmax_element(row.values.begin(), row.values.end());
    row.max_abs_difference = *hi - *lo;
    table.push_back(std::move(row));
  }
  return table;
}

}  // namespace

WorkedSolution work_out(const Inputs& inputs, const std::vector<int>& case_ids) {
  WorkedSolution w{inputs, derive(inputs.params(), inputs.state()), {}, {}};
  check_derived(w.derived, inputs);
  for (int id : case_ids) {
    w.cases.push_back(solve_case(id, inputs.params(), inputs.state()));
    check_case(w.cases.back(), inputs);
  }
  w.agreement = compare_cases(w.cases, inputs.params());
  return w;
}

}  // namespace linkage
