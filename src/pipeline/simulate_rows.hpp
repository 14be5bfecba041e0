#pragma once
// The rows of `linkage simulate`, for the command and a lesson's simulate step alike: a
// mechanism's columns, each value checked finite, angles in rad or deg.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "columns/trajectory_rows.hpp"
#include "core/angle_unit.hpp"
#include "integrate/mechanism_simulation.hpp"

namespace linkage {

/// The columns as written with --angles: angular ones (rad, rad/s, rad/s^2) scaled, and
/// named with their unit in a CSV header when in degrees ("theta1 (deg)").
struct WrittenColumns {
  std::vector<std::string> names;  // CSV header
  std::vector<std::string> units;  // JSON "units"
  std::vector<double> factors;

  void add(const std::string& name, std::string_view unit, AngleUnit angles);
  void scale(std::vector<double>& values) const;
};
[[nodiscard]] WrittenColumns written_columns(const std::vector<MechanismColumn>& columns, AngleUnit angles);

/// A mechanism's `columns` at time t (y: the simulation's state at t) into `values`;
/// Error::diverged naming the column, the time and the case when one is not finite.
void mechanism_row(MechanismSimulation& simulation, int case_id, double t, const Eigen::VectorXd& y,
                   const std::vector<MechanismColumn>& columns, eval::MechanismSample& sample,
                   std::vector<double>& values);

/// Receives each row: its time and its values as written (angles scaled).
using RowSink = std::function<void(double t, const std::vector<double>& values)>;

/// A mechanism's table at `rows`' times, row by row; returns the state y = (q, q', W) at
/// the last row.
Eigen::VectorXd mechanism_trajectory(MechanismSimulation& simulation, int case_id, const TrajectoryRows& rows,
                                     const std::vector<MechanismColumn>& columns, AngleUnit angles, const RowSink& row);

/// Values as the tables print them: round-trip numbers joined by `separator`.
[[nodiscard]] std::string joined_values(const std::vector<double>& values, std::string_view separator);
/// A CSV header line's text: the names joined by commas.
[[nodiscard]] std::string joined_names(const std::vector<std::string>& names);

}  // namespace linkage
