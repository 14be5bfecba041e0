#include "scene/arrow_scale.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "core/error.hpp"

namespace linkage {
namespace {

double power_of_ten(int exponent) { return std::pow(10.0, exponent); }

// The smallest m x 10^k (m one of `mantissas`, ascending within [first, 10 first)) not
// below `value` (> 0). A value a hair above a round number (from rounding in the
// division that produced it) rounds down to it.
template <std::size_t N>
RoundLength round_up(double value, const std::array<int, N>& mantissas) {
  int exponent = static_cast<int>(std::floor(std::log10(value / mantissas[0])));
  for (int attempt = 0; attempt < 2; ++attempt, ++exponent) {
    for (const int mantissa : mantissas) {
      if (mantissa * power_of_ten(exponent) >= value * (1 - 1e-12)) return {mantissa, exponent};
    }
  }
  return {mantissas[0], exponent};  // unreachable: 10 first x 10^(start) > value
}

// Grid spacings: 1, 2, 5 x 10^k. Arrow scales (in tenths): finer steps, so rounding
// shortens the longest arrow by at most a third (1 -> 1.5) rather than by half.
constexpr std::array<int, 3> kLengthMantissas{1, 2, 5};
constexpr std::array<int, 9> kScaleMantissas{10, 15, 20, 25, 30, 40, 50, 60, 80};

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// mantissa x 10^exponent written with an SI prefix so the number is in 1 .. 999:
// (15, -4) -> "1.5 m", (3, -4) -> "300 µ", (2, 0) -> "2 "; beyond pico and tera in
// scientific notation: (1, -300) -> "1e-300 ".
std::string with_prefix(int mantissa, int exponent) {
  static constexpr std::array<const char*, 9> kPrefixes{"p", "n", "µ", "m", "", "k", "M", "G", "T"};
  std::string digits = std::to_string(mantissa);
  while (digits.size() > 1 && digits.back() == '0') {
    digits.pop_back();
    ++exponent;
  }
  const int magnitude = static_cast<int>(digits.size()) - 1 + exponent;  // floor(log10(value))
  const int group = std::clamp(floor_div(magnitude, 3), -4, 4);
  if (group != floor_div(magnitude, 3)) {      // beyond p .. T: "1.5e-300 ", never a row of zeros
    std::string number = digits.substr(0, 1);  // appended piece by piece: GCC 12's -Wrestrict misfires on "." + ...
    if (digits.size() > 1) number.append(".").append(digits, 1);
    number.append("e").append(std::to_string(magnitude)).append(" ");
    return number;
  }
  const int shift = exponent - 3 * group;  // value / 1000^group = digits x 10^shift
  std::string number;
  if (shift >= 0) {
    number = digits;
    number.append(static_cast<std::size_t>(shift), '0');
  } else {
    // Whole digits, a point, then the rest ("0.0" first when there are no whole digits).
    const int whole = static_cast<int>(digits.size()) + shift;
    if (whole <= 0) {
      number = "0.";
      number.append(static_cast<std::size_t>(-whole), '0');
      number += digits;
    } else {
      number = digits.substr(0, static_cast<std::size_t>(whole));
      number += '.';
      number += digits.substr(static_cast<std::size_t>(whole));
    }
  }
  number += ' ';
  number += kPrefixes[static_cast<std::size_t>(group + 4)];
  return number;
}

}  // namespace

double ArrowScale::units_per_cm() const { return mantissa * power_of_ten(exponent); }

ArrowScale choose_arrow_scale(double largest_magnitude, double longest_arrow) {
  ArrowScale scale;
  if (!(largest_magnitude > 0) || !std::isfinite(largest_magnitude) || !(longest_arrow > 0)) return scale;
  const RoundLength round = round_up(largest_magnitude / (longest_arrow * 100.0), kScaleMantissas);
  scale.mantissa = round.mantissa;
  scale.exponent = round.exponent;
  scale.metres_per_unit = 0.01 / scale.units_per_cm();
  return scale;
}

ArrowScale arrow_scale_of(double units_per_cm) {
  ArrowScale scale;
  if (!(units_per_cm > 0) || !std::isfinite(units_per_cm)) return scale;
  // Three significant digits: mantissa 100 .. 999.
  int exponent = static_cast<int>(std::floor(std::log10(units_per_cm))) - 2;
  auto mantissa = static_cast<int>(std::lround(units_per_cm / power_of_ten(exponent)));
  if (mantissa >= 1000) {
    mantissa = static_cast<int>(std::lround(mantissa / 10.0));
    ++exponent;
  }
  scale.mantissa = mantissa;
  scale.exponent = exponent;
  scale.metres_per_unit = 0.01 / scale.units_per_cm();
  return scale;
}

double ArrowScaleRequest::fixed_for(std::string_view kind) const {
  for (const auto& [name, value] : fixed)
    if (name == kind) return value;
  return 0;
}

ArrowScaleRequest parse_arrow_scale_request(std::string_view text, const std::string& origin,
                                            std::span<const std::string_view> kinds) {
  std::string names;
  for (const std::string_view kind : kinds) {
    if (!names.empty()) names += ", ";
    names += kind;
  }
  const auto bad = [&](std::string_view entry, const std::string& why) {
    std::string message = origin;
    message.append(": '").append(entry).append("' ").append(why);
    message.append(
        "; expected common, common=VALUE or KIND=VALUE (comma-separated; VALUE in units per cm, > 0; KIND "
        "one of ");
    message.append(names).append(")");
    return Error::input(message);
  };
  ArrowScaleRequest request;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view entry = text.substr(start, comma - start);
    start = comma + 1;
    const std::size_t equals = entry.find('=');
    const std::string_view kind = entry.substr(0, equals);
    double value = 0;
    if (equals != std::string_view::npos) {
      const std::string_view number = entry.substr(equals + 1);
      const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
      if (number.empty() || error != std::errc{} || end != number.data() + number.size() || !(value > 0) ||
          !std::isfinite(value))
        throw bad(entry, "has no positive number after '='");
    }
    if (kind == "common") {
      request.common = true;
      request.common_units_per_cm = value;
    } else if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
      throw bad(entry, "names no kind of arrow");
    } else if (equals == std::string_view::npos) {
      throw bad(entry, "needs a value (KIND=VALUE)");
    } else {
      request.fixed.emplace_back(std::string(kind), value);
    }
  }
  return request;
}

std::string describe_arrow_scale(const ArrowScale& scale, std::string_view unit) {
  if (!scale.drawable()) return "0 " + std::string(unit) + " throughout";
  return "1 cm = " + with_prefix(scale.mantissa, scale.exponent) + std::string(unit);
}

std::string describe_length(int mantissa, int exponent) {
  // Centimetres read better than tens of millimetres on a lecture slide.
  if (exponent == -2 || exponent == -1) return std::to_string(mantissa * (exponent == -1 ? 10 : 1)) + " cm";
  return with_prefix(mantissa, exponent) + "m";
}

double RoundLength::metres() const { return mantissa * power_of_ten(exponent); }

RoundLength round_length_at_least(double at_least) { return round_up(at_least, kLengthMantissas); }

}  // namespace linkage
