#pragma once
// A column the user defines as NAME=EXPRESSION over other columns, the parameters and
// definitions (`simulate --columns 't,gamma=4.theta-3.theta'`, a panel, a lesson plot):
// the transmission angle, a gear ratio, a power `M.torque*2.theta_dot`. Read once in the
// mechanism files' expression language; its value at a sample is computed from the
// columns it names at that sample.
#include <string>
#include <string_view>
#include <vector>

#include "columns/mechanism_columns.hpp"

namespace linkage {

/// What an expression column computes.
struct ColumnExpression {
  std::string name, text, origin;
  GiNaC::ex value;
  std::vector<std::pair<GiNaC::symbol, MechanismColumn>> inputs;  // the columns it names
  GiNaC::exmap fixed;                   // parameters -> values, definitions -> their expressions
  std::vector<std::string> parameters;  // the parameters and definitions it uses, by name
};

/// Whether `spec` defines a column (NAME=EXPRESSION) rather than naming one.
[[nodiscard]] bool defines_column(std::string_view spec);

/// The column `spec` (NAME=EXPRESSION) defines over `available` (each by its name, and by
/// its file's key when the mechanism speaks aliases) and `system`'s parameters and
/// definitions (none when null). Its unit follows from its columns' units (one unit kept
/// through a sum of them, else by dimensional analysis; empty when unknown). Error::input
/// "ORIGIN: ..." for a bad name (not NAME, or an existing column's), or a bad expression
/// (with the nearest name and the valid ones).
[[nodiscard]] MechanismColumn expression_column(const std::vector<MechanismColumn>& available,
                                                const sym::System* system, const std::string& spec,
                                                const std::string& origin);

}  // namespace linkage
