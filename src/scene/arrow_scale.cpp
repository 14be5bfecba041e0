#include "scene/arrow_scale.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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
// (15, -4) -> "1.5 m", (3, -4) -> "300 µ", (2, 0) -> "2 ".
std::string with_prefix(int mantissa, int exponent) {
  static constexpr std::array<const char*, 9> kPrefixes{"p", "n", "µ", "m", "", "k", "M", "G", "T"};
  std::string digits = std::to_string(mantissa);
  while (digits.size() > 1 && digits.back() == '0') {
    digits.pop_back();
    ++exponent;
  }
  const int magnitude = static_cast<int>(digits.size()) - 1 + exponent;  // floor(log10(value))
  const int group = std::clamp(floor_div(magnitude, 3), -4, 4);
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
