#pragma once
// The columns of a trajectory table (`linkage simulate`): the state, the quantities
// derived from it, and which derivations each column needs, so a run computes
// accelerations, forces, invariants or constraint errors only at output samples and
// only when a requested column uses them.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "integrate/simulation.hpp"

namespace linkage {

enum class Column {
  t,
  x1,
  y1,
  theta1,
  theta2,
  x1_dot,
  y1_dot,
  theta1_dot,
  theta2_dot,
  x2,
  y2,
  x2_dot,
  y2_dot,
  x1_ddot,
  y1_ddot,
  theta1_ddot,
  theta2_ddot,
  F_x,
  F_y,
  energy,
  momentum_x,
  momentum_y,
  angular_momentum,
  constraint_position_error,
  constraint_velocity_error,
};

/// What a column is computed from.
enum class ColumnSource { time, state, dynamics, invariants, constraint };

struct ColumnInfo {
  Column column;
  std::string_view name;  // CSV header and JSON key
  std::string_view unit;
  std::string_view description;
  ColumnSource source;
};

inline constexpr std::array<ColumnInfo, 25> kColumns{{
    {Column::t, "t", "s", "time", ColumnSource::time},
    {Column::x1, "x1", "m", "x of block 1's centre of mass", ColumnSource::state},
    {Column::y1, "y1", "m", "y of block 1's centre of mass", ColumnSource::state},
    {Column::theta1, "theta1", "rad", "angle of block 1 (not wrapped)", ColumnSource::state},
    {Column::theta2, "theta2", "rad", "angle of block 2 (not wrapped)", ColumnSource::state},
    {Column::x1_dot, "x1_dot", "m/s", "x velocity of block 1", ColumnSource::state},
    {Column::y1_dot, "y1_dot", "m/s", "y velocity of block 1", ColumnSource::state},
    {Column::theta1_dot, "theta1_dot", "rad/s", "angular velocity of block 1", ColumnSource::state},
    {Column::theta2_dot, "theta2_dot", "rad/s", "angular velocity of block 2", ColumnSource::state},
    {Column::x2, "x2", "m", "x of block 2's centre of mass", ColumnSource::state},
    {Column::y2, "y2", "m", "y of block 2's centre of mass", ColumnSource::state},
    {Column::x2_dot, "x2_dot", "m/s", "x velocity of block 2", ColumnSource::state},
    {Column::y2_dot, "y2_dot", "m/s", "y velocity of block 2", ColumnSource::state},
    {Column::x1_ddot, "x1_ddot", "m/s^2", "x acceleration of block 1", ColumnSource::dynamics},
    {Column::y1_ddot, "y1_ddot", "m/s^2", "y acceleration of block 1", ColumnSource::dynamics},
    {Column::theta1_ddot, "theta1_ddot", "rad/s^2", "angular acceleration of block 1", ColumnSource::dynamics},
    {Column::theta2_ddot, "theta2_ddot", "rad/s^2", "angular acceleration of block 2", ColumnSource::dynamics},
    {Column::F_x, "F_x", "N", "pin force on block 1, x", ColumnSource::dynamics},
    {Column::F_y, "F_y", "N", "pin force on block 1, y", ColumnSource::dynamics},
    {Column::energy, "energy", "J", "kinetic + m g (y1 + y2)", ColumnSource::invariants},
    {Column::momentum_x, "momentum_x", "kg m/s", "m (x1_dot + x2_dot), constant", ColumnSource::invariants},
    {Column::momentum_y, "momentum_y", "kg m/s", "m (y1_dot + y2_dot), falls at 2 m g", ColumnSource::invariants},
    {Column::angular_momentum, "angular_momentum", "kg m^2/s", "about the system's centre of mass, constant",
     ColumnSource::invariants},
    {Column::constraint_position_error, "constraint_position_error", "m", "|C|, distance of block 2 from the pin",
     ColumnSource::constraint},
    {Column::constraint_velocity_error, "constraint_velocity_error", "m/s", "|C'|", ColumnSource::constraint},
}};

[[nodiscard]] constexpr const ColumnInfo& info(Column c) { return kColumns[static_cast<std::size_t>(c)]; }

/// "t,x1,..." or "all"; throws Error::input naming `origin`, the bad name and the valid
/// ones for an unknown or repeated column or an empty list.
[[nodiscard]] std::vector<Column> parse_columns(std::string_view list, const std::string& origin);

/// Computes one table row: `columns` of the sample `state` at time t, into `values`
/// (resized to columns.size()). Asks the simulation for accelerations and pin force
/// only if a dynamics column is requested.
void compute_row(Simulation& simulation, double t, const BodyState& state, const std::vector<Column>& columns,
                 std::vector<double>& values);

}  // namespace linkage
