#pragma once
// The unknowns of the three formulations, with their names in every output style.
#include <array>
#include <string_view>

namespace linkage {

enum class Unknown { x1_ddot, y1_ddot, theta1_ddot, x2_ddot, y2_ddot, theta2_ddot, F_x, F_y };

struct UnknownInfo {
  std::string_view key;      // JSON key, e.g. "theta1_ddot"
  std::string_view unicode;  // e.g. "θ̈₁"
  std::string_view ascii;    // e.g. "th1''"
  std::string_view latex;    // e.g. "\ddot{\theta}_1"
  std::string_view unit;     // e.g. "rad/s^2"
  std::string_view description;
};

inline constexpr std::array<UnknownInfo, 8> kUnknowns{{
    {"x1_ddot", "ẍ₁", "x1''", "\\ddot{x}_1", "m/s^2", "x acceleration of block 1"},
    {"y1_ddot", "ÿ₁", "y1''", "\\ddot{y}_1", "m/s^2", "y acceleration of block 1"},
    {"theta1_ddot", "θ̈₁", "th1''", "\\ddot{\\theta}_1", "rad/s^2", "angular acceleration of block 1"},
    {"x2_ddot", "ẍ₂", "x2''", "\\ddot{x}_2", "m/s^2", "x acceleration of block 2"},
    {"y2_ddot", "ÿ₂", "y2''", "\\ddot{y}_2", "m/s^2", "y acceleration of block 2"},
    {"theta2_ddot", "θ̈₂", "th2''", "\\ddot{\\theta}_2", "rad/s^2", "angular acceleration of block 2"},
    {"F_x", "Fx", "Fx", "F_x", "N", "pin force on block 1, x"},
    {"F_y", "Fy", "Fy", "F_y", "N", "pin force on block 1, y"},
}};

[[nodiscard]] constexpr const UnknownInfo& info(Unknown u) { return kUnknowns[static_cast<std::size_t>(u)]; }

}  // namespace linkage
