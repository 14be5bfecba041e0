#include "core/angle_unit.hpp"

#include <numbers>

#include "core/error.hpp"
#include "core/name_match.hpp"

namespace linkage {
namespace {
// "rad", "rad/s", "rad/s^2" (not "radius" or a mixed "m, rad").
bool angular(std::string_view unit) { return unit.substr(0, 3) == "rad" && (unit.size() == 3 || unit[3] == '/'); }
}  // namespace

AngleUnit parse_angle_unit(std::string_view text, const std::string& origin) {
  if (text == "rad") return AngleUnit::rad;
  if (text == "deg") return AngleUnit::deg;
  std::string message = origin;
  message += ": '";
  message += text;
  message += "' is not an angle unit";
  message += did_you_mean(text, {"rad", "deg"});
  message += "; valid: rad, deg";
  throw Error::input(message);
}

double angle_factor(std::string_view unit, AngleUnit angles) {
  return angles == AngleUnit::deg && angular(unit) ? 180 / std::numbers::pi : 1.0;
}

std::string angle_unit_text(std::string_view unit, AngleUnit angles) {
  std::string text(unit);
  if (angles == AngleUnit::deg && angular(unit)) text.replace(0, 3, "deg");
  return text;
}

}  // namespace linkage
