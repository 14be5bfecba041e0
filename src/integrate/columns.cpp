#include "integrate/columns.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "model/kinematics.hpp"

namespace linkage {

std::vector<Column> parse_columns(std::string_view list, const std::string& origin) {
  std::vector<Column> columns;
  if (list == "all") {
    for (const ColumnInfo& c : kColumns) columns.push_back(c.column);
    return columns;
  }
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view name = list.substr(start, comma - start);
    const auto found =
        std::find_if(kColumns.begin(), kColumns.end(), [&](const ColumnInfo& c) { return c.name == name; });
    if (found == kColumns.end()) {
      std::vector<std::string> names{"all"};
      for (const ColumnInfo& c : kColumns) names.emplace_back(c.name);
      throw Error::invalid(origin, "'" + std::string(name) + "' is not a column" + did_you_mean(name, names) +
                                       "; valid: " + join_names(names));
    }
    if (std::find(columns.begin(), columns.end(), found->column) != columns.end())
      throw Error::invalid(origin, "column '" + std::string(name) + "' is listed twice");
    columns.push_back(found->column);
    start = comma + 1;
  }
  return columns;
}

void compute_row(Simulation& simulation, double t, const BodyState& s, const std::vector<Column>& columns,
                 std::vector<double>& values) {
  auto needs = [&](ColumnSource source) {
    return std::any_of(columns.begin(), columns.end(), [&](Column c) { return info(c).source == source; });
  };
  const Params& p = simulation.params();
  const Dynamics d = needs(ColumnSource::dynamics) ? simulation.dynamics(s) : Dynamics{};
  const Invariants inv = needs(ColumnSource::invariants) ? invariants(p, s) : Invariants{};
  const ConstraintError ce = needs(ColumnSource::constraint) ? constraint_error(p, s) : ConstraintError{};

  values.resize(columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    double& v = values[i];
    switch (columns[i]) {
      case Column::t:
        v = t;
        break;
      case Column::x1:
        v = s.x1;
        break;
      case Column::y1:
        v = s.y1;
        break;
      case Column::theta1:
        v = s.theta1;
        break;
      case Column::theta2:
        v = s.theta2;
        break;
      case Column::x1_dot:
        v = s.x1_dot;
        break;
      case Column::y1_dot:
        v = s.y1_dot;
        break;
      case Column::theta1_dot:
        v = s.theta1_dot;
        break;
      case Column::theta2_dot:
        v = s.theta2_dot;
        break;
      case Column::x2:
        v = s.x2;
        break;
      case Column::y2:
        v = s.y2;
        break;
      case Column::x2_dot:
        v = s.x2_dot;
        break;
      case Column::y2_dot:
        v = s.y2_dot;
        break;
      case Column::x1_ddot:
        v = d.x1_ddot;
        break;
      case Column::y1_ddot:
        v = d.y1_ddot;
        break;
      case Column::theta1_ddot:
        v = d.theta1_ddot;
        break;
      case Column::theta2_ddot:
        v = d.theta2_ddot;
        break;
      case Column::F_x:
        v = d.F_x;
        break;
      case Column::F_y:
        v = d.F_y;
        break;
      case Column::energy:
        v = inv.energy;
        break;
      case Column::momentum_x:
        v = inv.momentum.x();
        break;
      case Column::momentum_y:
        v = inv.momentum.y();
        break;
      case Column::angular_momentum:
        v = inv.angular_momentum;
        break;
      case Column::constraint_position_error:
        v = ce.position.norm();
        break;
      case Column::constraint_velocity_error:
        v = ce.velocity.norm();
        break;
    }
  }
}

}  // namespace linkage
