#pragma once
// The columns of a mechanism's trajectory table (`linkage simulate --mechanism`), named
// as the mechanism file's contract says: t; for every body <body>.x, <body>.y,
// <body>.theta (no theta for a point mass); <joint>.s for sliders (the default); on
// request the rates and accelerations, each named point's position, velocity and
// acceleration (<body>.<point>.x, .y, .vx, .vy, .ax, .ay), the centre of mass (com.x,
// com.y, com.x_dot, com.y_dot) and each body's place from it, each joint's force and
// constraint errors and all joints' together, the energy and its balance (in J and
// relative to the energy scale), and the momenta and their errors when nothing holds the
// mechanism to the ground.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "symbolic/system.hpp"

namespace linkage {

enum class MechanismQuantity {
  time,
  position,             // index: 3 body + component (x, y, theta)
  rate,                 // the same, of the rates
  acceleration,         // the same, of the accelerations
  slider,               // index: joint
  slider_acceleration,  // index: joint
  point,                // index: 6 named point + component (x, y, vx, vy, ax, ay)
  force,                // index: 3 joint + component (x, y, moment)
  constraint,           // index: joint
  constraint_rate,      // index: joint
  energy,
  energy_error,  // E - E0 - W: the balance, 0 up to the integration error
  work,          // W, of dampers, applied loads and drivers since t = 0
  momentum_x,
  momentum_y,
  angular_momentum,
  com,                     // index: x, y, x', y'
  from_com,                // index: 2 body + component (x, y): the body's centre less G
  driver,                  // index: driver; its torque or force (the case's multiplier)
  constraints,             // |C| of every joint's rows together
  constraints_rate,        // |C'| of the same
  energy_error_relative,   // |E - E0 - W| / energy scale
  momentum_x_error,        // |p_x - p_x0|
  momentum_y_error,        // |p_y - p_y0 + M g t|
  angular_momentum_error,  // |H_G - H_G0|
  com_parabola_error,      // |G - (G0 + G0' t - g t^2 / 2 y)|
  expression,              // NAME=EXPRESSION over other columns (expression_column.hpp)
  shaking,                 // index: 0 force x, 1 force y, 2 moment about the origin (on the ground)
};

/// What the error columns measure a sample against: the run's state at t = 0.
struct ColumnOrigin {
  double energy0 = 0;       // E at t = 0, J
  double energy_scale = 1;  // J: what a relative energy error divides by (MechanismStats)
  double momentum_x0 = 0, momentum_y0 = 0, angular_momentum0 = 0;
  std::array<double, 4> com0{};  // the centre of mass and its velocity at t = 0
  double weight = 0;             // M g, N (along -y)
  double g = 0;                  // m/s^2
};

struct ColumnExpression;  // expression_column.cpp

struct MechanismColumn {
  std::string name;  // "1.theta", "P.force_x", "energy_error"
  std::string unit;
  std::string meaning;
  MechanismQuantity quantity = MechanismQuantity::time;
  std::size_t index = 0;
  bool by_default = false;
  std::string owner{};  // the body, point or joint it belongs to ("2", "3.P"), kept when the name is aliased
  std::shared_ptr<const ColumnExpression> expression{};  // quantity expression only: what it computes
};

/// A column in words for a plot axis or legend, in plot markup and without its unit:
/// "angle θ of body 2", "force of joint B on body 1, x", "energy balance E − E_{0} − W".
[[nodiscard]] std::string column_words(const MechanismColumn& column);
/// Its unit in plot markup ("m/s^{2}"), empty for a pure number.
[[nodiscard]] std::string column_unit_markup(const MechanismColumn& column);

/// Every column this mechanism has, in table order.
[[nodiscard]] std::vector<MechanismColumn> mechanism_columns(const sym::System& system);

/// The column named `name`, or defined by it (NAME=EXPRESSION over `all` and `system`'s
/// parameters: expression_column.hpp); else Error::input "ORIGIN: unknown column 'NAME';
/// nearest 'N'; valid: ..." (the fewest edits, of equals one on the same body or joint;
/// `groups`: "default" and "all" are valid too, and listed).
[[nodiscard]] MechanismColumn find_mechanism_column(const std::vector<MechanismColumn>& all, const std::string& name,
                                                    const std::string& origin, bool groups = false,
                                                    const sym::System* system = nullptr);

/// The columns `names` select, t first: each a column's name or a definition (which may
/// use the definitions before it), or "default" or "all" for theirs (t once); an unknown
/// name is find_mechanism_column's error at `origin(i)`.
[[nodiscard]] std::vector<MechanismColumn> select_mechanism_columns(
    const std::vector<MechanismColumn>& all, const std::vector<std::string>& names,
    const std::function<std::string(std::size_t)>& origin, const sym::System* system = nullptr);
/// The same from a comma-separated list (`simulate --columns`; a comma inside parentheses
/// is an expression's), every error at `origin`.
[[nodiscard]] std::vector<MechanismColumn> select_mechanism_columns(const std::vector<MechanismColumn>& all,
                                                                    const std::string& spec, const std::string& origin,
                                                                    const sym::System* system = nullptr);

/// Whether any of `columns` needs the sample's kinematics (accelerations, points).
[[nodiscard]] bool needs_kinematics(const std::vector<MechanismColumn>& columns);

/// The columns `list` (comma-separated) names exactly, in its order, or every column for
/// "all" (the homework's `--columns`, its names two-blocks' [aliases]); else
/// Error::invalid at `origin` for a name that is no column (with the nearest) or a repeat.
[[nodiscard]] std::vector<MechanismColumn> named_columns(const std::vector<MechanismColumn>& all, std::string_view list,
                                                         const std::string& origin,
                                                         const sym::System* system = nullptr);

/// A column's value at a sample; `y` the state (its last entry W), `origin` the run's t = 0.
[[nodiscard]] double column_value(const MechanismColumn& column, double t, const Eigen::VectorXd& y,
                                  const eval::MechanismSample& sample, const ColumnOrigin& origin);
/// An expression column's value: its expression at its columns' values (expression_column.cpp).
[[nodiscard]] double expression_value(const ColumnExpression& expression, double t, const Eigen::VectorXd& y,
                                      const eval::MechanismSample& sample, const ColumnOrigin& origin);

}  // namespace linkage
