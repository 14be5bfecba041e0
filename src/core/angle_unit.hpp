#pragma once
// Angles as a reader wants them printed or plotted: radians (what every computation
// uses) or degrees. Only output converts; inputs stay in radians.
#include <string>
#include <string_view>

namespace linkage {

enum class AngleUnit { rad, deg };

/// "rad" or "deg"; Error::input naming `origin`, the nearer choice for a typo and both
/// choices otherwise.
[[nodiscard]] AngleUnit parse_angle_unit(std::string_view text, const std::string& origin);

/// The factor a value in `unit` (e.g. "rad", "rad/s", "rad/s^2", "m") is multiplied by
/// to print it with angles in `angles`: 180/pi for an angular unit in degrees, else 1.
[[nodiscard]] double angle_factor(std::string_view unit, AngleUnit angles);
/// `unit` with its leading "rad" written "deg" when `angles` is deg ("rad/s" -> "deg/s").
[[nodiscard]] std::string angle_unit_text(std::string_view unit, AngleUnit angles);

}  // namespace linkage
