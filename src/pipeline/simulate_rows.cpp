#include "pipeline/simulate_rows.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"

namespace linkage {

void WrittenColumns::add(const std::string& name, std::string_view unit, AngleUnit angles) {
  const double factor = angle_factor(unit, angles);
  units.push_back(angle_unit_text(unit, angles));
  names.push_back(factor == 1 ? name : name + " (" + units.back() + ")");
  factors.push_back(factor);
}

void WrittenColumns::scale(std::vector<double>& values) const {
  for (std::size_t j = 0; j < values.size(); ++j) values[j] *= factors[j];
}

WrittenColumns written_columns(const std::vector<MechanismColumn>& columns, AngleUnit angles) {
  WrittenColumns written;
  for (const MechanismColumn& c : columns) written.add(c.name, c.unit, angles);
  return written;
}

void mechanism_row(MechanismSimulation& simulation, int case_id, double t, const Eigen::VectorXd& y,
                   const std::vector<MechanismColumn>& columns, eval::MechanismSample& sample,
                   std::vector<double>& values) {
  simulation.sample(t, y, sample, needs_kinematics(columns));
  values.resize(columns.size());
  for (std::size_t j = 0; j < columns.size(); ++j) {
    values[j] = column_value(columns[j], t, y, sample, simulation.origin());
    if (!std::isfinite(values[j]))
      throw Error::diverged(columns[j].name + " at t = " + format_roundtrip(t) +
                            " s is not a finite number; the run stopped (Case " + std::to_string(case_id) + ")");
  }
}

Eigen::VectorXd mechanism_trajectory(MechanismSimulation& simulation, int case_id, const TrajectoryRows& rows,
                                     const std::vector<MechanismColumn>& columns, AngleUnit angles,
                                     const RowSink& row) {
  const WrittenColumns written = written_columns(columns, angles);
  eval::MechanismSample sample;
  std::vector<double> values;
  Eigen::VectorXd y;
  for (long i = 0; i < rows.count; ++i) {
    const double t = rows.at(i);
    y = simulation.state_at(t);
    mechanism_row(simulation, case_id, t, y, columns, sample, values);
    written.scale(values);
    row(t, values);
    throw_if_interrupted();
  }
  return y;
}

std::string joined_values(const std::vector<double>& values, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += separator;
    out += format_roundtrip(values[i]);
  }
  return out;
}

std::string joined_names(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ',';
    out += names[i];
  }
  return out;
}

}  // namespace linkage
