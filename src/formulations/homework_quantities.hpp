#pragma once
// The homework's named quantities, by the names of its statement (example.json's): the
// thirteen inputs, what the derivation derives, the accelerations and pin force (the
// case unknowns), each case matrix's condition number, the system's centre of mass. A
// lesson's exercise answers and {{...}} are expressions over these names, so it never
// carries a number the tool could get wrong.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "model/inputs.hpp"

namespace linkage {

struct QuantityInfo {
  std::string_view name;  // e.g. "I_zz_P"
  std::string_view unit;  // e.g. "kg m^2"; empty for pure numbers
  std::string_view description;
};

inline constexpr std::array<QuantityInfo, 45> kQuantities{{
    {"L", "m", "block length"},
    {"w", "m", "block width"},
    {"b", "m", "pin distance from one end of each block"},
    {"m", "kg", "mass of each block"},
    {"g", "m/s^2", "gravitational acceleration"},
    {"x1", "m", "x of block 1's centre of mass"},
    {"y1", "m", "y of block 1's centre of mass"},
    {"theta1", "rad", "angle of block 1"},
    {"theta2", "rad", "angle of block 2"},
    {"x1_dot", "m/s", "x velocity of block 1"},
    {"y1_dot", "m/s", "y velocity of block 1"},
    {"theta1_dot", "rad/s", "angular velocity of block 1"},
    {"theta2_dot", "rad/s", "angular velocity of block 2"},
    {"I_zz_C", "kg m^2", "centroidal moment of inertia m (w^2 + L^2) / 12"},
    {"D", "m", "distance from each centre of mass to the pin, L/2 - b"},
    {"I_zz_P", "kg m^2", "moment of inertia about the pin, I_zz_C + m D^2"},
    {"x_P", "m", "x of the pin P"},
    {"y_P", "m", "y of the pin P"},
    {"x2", "m", "x of block 2's centre of mass"},
    {"y2", "m", "y of block 2's centre of mass"},
    {"x2_dot", "m/s", "x velocity of block 2"},
    {"y2_dot", "m/s", "y velocity of block 2"},
    {"x_com", "m", "x of the system's centre of mass"},
    {"y_com", "m", "y of the system's centre of mass"},
    {"x_com_dot", "m/s", "x velocity of the system's centre of mass"},
    {"y_com_dot", "m/s", "y velocity of the system's centre of mass"},
    {"kinetic_energy", "J", "kinetic energy"},
    {"potential_energy", "J", "potential energy m g (y1 + y2)"},
    {"energy", "J", "total energy"},
    {"momentum_x", "kg m/s", "linear momentum, x"},
    {"momentum_y", "kg m/s", "linear momentum, y"},
    {"angular_momentum", "kg m^2/s", "angular momentum about the system's centre of mass"},
    {"x1_ddot", "m/s^2", "x acceleration of block 1"},
    {"y1_ddot", "m/s^2", "y acceleration of block 1"},
    {"theta1_ddot", "rad/s^2", "angular acceleration of block 1"},
    {"x2_ddot", "m/s^2", "x acceleration of block 2"},
    {"y2_ddot", "m/s^2", "y acceleration of block 2"},
    {"theta2_ddot", "rad/s^2", "angular acceleration of block 2"},
    {"F_x", "N", "pin force on block 1, x"},
    {"F_y", "N", "pin force on block 1, y"},
    {"cond1", "", "condition number of the Case 1 matrix (8x8)"},
    {"cond2", "", "condition number of the Case 2 matrix (6x6)"},
    {"cond3", "", "condition number of the Case 3 matrix (4x4)"},
    {"residual1", "", "||A q - B|| of the Case 1 solve"},
    {"pi", "", "the constant 3.14159..."},
}};

using QuantityValues = std::array<double, kQuantities.size()>;

/// Index of the quantity called `name`, if there is one.
[[nodiscard]] std::optional<std::size_t> find_quantity(std::string_view name);

/// Every quantity at the inputs. Accelerations and the pin force come from Case 1
/// (the three cases agree to round-off; the tests check that). Throws Error::diverged
/// when a case matrix is singular.
[[nodiscard]] QuantityValues evaluate_quantities(const Inputs& inputs);

}  // namespace linkage
