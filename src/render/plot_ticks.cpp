#include "render/plot_ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace linkage::plot {
namespace {

constexpr const char* minus_sign = "\u2212";
constexpr const char* times_sign = "\u00d7";
// Slack when deciding whether a tick computed in floating point lies inside the range.
constexpr double slack = 1e-9;

/// floor(log10(v)) for v > 0, robust against log10(1000) = 2.9999...
int floor_log10(double v) { return static_cast<int>(std::floor(std::log10(v) + 1e-12)); }

/// m x 10^k, correctly rounded for |k| <= 22 (dividing by an exact power avoids 0.1's error).
double scaled(double m, int k) { return k >= 0 ? m * std::pow(10.0, k) : m / std::pow(10.0, -k); }

std::string with_minus_sign(std::string text) {
  if (!text.empty() && text.front() == '-') text.replace(0, 1, minus_sign);
  return text;
}

std::string fixed(double value, int decimals) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*f", decimals, value);
  return buffer.data();
}

std::string trim_zeros(std::string text) {
  if (text.find('.') == std::string::npos) return text;
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

/// Axes whose numbers are this small or large are labelled m×10^{k}.
bool wants_scientific(double lo, double hi) {
  const double magnitude = std::max(std::fabs(lo), std::fabs(hi));
  return magnitude >= 1e5 || magnitude < 1e-3;
}

/// `value` labelled to the precision of `step` (the spacing of the labelled ticks).
std::string number_label(double value, double step, bool scientific) {
  // Plain labels share the step's decimals ("0.0", "0.5", "1.0"), like a table column.
  if (!scientific) return with_minus_sign(fixed(value, std::max(0, -floor_log10(step))));
  if (value == 0.0) return "0";
  int exponent = floor_log10(std::fabs(value));
  const int decimals = std::max(0, exponent - floor_log10(step));
  std::string mantissa = fixed(value / scaled(1.0, exponent), decimals);
  if (std::fabs(std::stod(mantissa)) >= 10.0) {  // 9.99 rounded up to 10.0
    ++exponent;
    mantissa = fixed(value / scaled(1.0, exponent), std::max(0, decimals - 1));
  }
  return with_minus_sign(trim_zeros(mantissa)) + times_sign + "10^{" + with_minus_sign(std::to_string(exponent)) + "}";
}

bool inside(double v, double lo, double hi) {
  const double tolerance = slack * (hi - lo);
  return v >= lo - tolerance && v <= hi + tolerance;
}

/// Floor-style modulo so that every third decade means ..., -6, -3, 0, 3, ...
int positive_mod(int a, int b) { return ((a % b) + b) % b; }

}  // namespace

Ticks degree_ticks(double lo, double hi, int max_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) return {};
  max_ticks = std::max(2, max_ticks);
  constexpr std::array<int, 6> steps{15, 30, 45, 90, 180, 360};
  for (const int step : steps) {
    const double first = std::ceil(lo / step - slack);
    const double last = std::floor(hi / step + slack);
    if (last - first + 1 > max_ticks) continue;
    if (last - first + 1 < 3) break;
    Ticks ticks;
    for (double k = first; k <= last; ++k) {
      const double value = k * step == 0 ? 0.0 : k * step;  // no "-0"
      ticks.major.push_back({value, number_label(value, step, false)});
    }
    const int divisions = step == 180 ? 2 : step == 360 ? 4 : 3;
    const double minor_step = static_cast<double>(step) / divisions;
    for (double j = std::ceil(lo / minor_step - slack); j <= std::floor(hi / minor_step + slack); ++j)
      if (std::fmod(std::fabs(j), divisions) != 0.0) ticks.minor.push_back(j * minor_step);
    return ticks;
  }
  return linear_ticks(lo, hi, max_ticks);
}

Ticks linear_ticks(double lo, double hi, int max_ticks) {
  Ticks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) return ticks;
  max_ticks = std::max(2, max_ticks);
  // The finest step m x 10^e (m in 1, 2, 5) that keeps the count within max_ticks.
  constexpr std::array<int, 3> mantissas{1, 2, 5};
  int exponent = floor_log10((hi - lo) / max_ticks) - 1;
  int mantissa = 1;
  double first = 0;
  double last = 0;
  for (bool found = false; !found; ++exponent) {
    for (const int m : mantissas) {
      const double step = scaled(m, exponent);
      first = std::ceil(lo / step - slack);
      last = std::floor(hi / step + slack);
      if (last - first + 1 <= max_ticks) {
        mantissa = m;
        found = true;
        break;
      }
    }
    if (found) break;
  }
  const double step = scaled(mantissa, exponent);
  const bool scientific = wants_scientific(lo, hi);
  for (double k = first; k <= last; ++k) {
    double value = scaled(k * mantissa, exponent);
    if (std::fabs(value) < slack * step) value = 0.0;  // no "-0" or 1e-17 at the origin
    ticks.major.push_back({value, number_label(value, step, scientific)});
  }
  // Minor ticks split a step of 1 or 5 in five and a step of 2 in four.
  const int divisions = mantissa == 2 ? 4 : 5;
  const double minor_step = step / divisions;
  const double minor_first = std::ceil(lo / minor_step - slack);
  const double minor_last = std::floor(hi / minor_step + slack);
  for (double j = minor_first; j <= minor_last; ++j) {
    if (std::fmod(std::fabs(j), divisions) == 0.0) continue;  // a major tick
    ticks.minor.push_back(scaled(j * mantissa, exponent) / divisions);
  }
  return ticks;
}

Ticks log_ticks(double lo, double hi, int max_ticks) {
  Ticks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo > 0) || !(lo < hi)) return ticks;
  max_ticks = std::max(2, max_ticks);
  const int k_lo = static_cast<int>(std::ceil(std::log10(lo) - slack));
  const int k_hi = static_cast<int>(std::floor(std::log10(hi) + slack));
  if (k_hi - k_lo + 1 >= 2) {
    // Label every n-th decade, n from a short list of round strides.
    int stride = 1;
    for (const int candidate : {1, 2, 3, 5, 10, 20, 25, 50, 100, 200, 500}) {
      stride = candidate;
      int count = 0;
      for (int k = k_lo; k <= k_hi; ++k) count += positive_mod(k, stride) == 0 ? 1 : 0;
      if (count <= max_ticks) break;
    }
    for (int k = k_lo; k <= k_hi; ++k) {
      const double value = scaled(1.0, k);
      if (positive_mod(k, stride) == 0)
        ticks.major.push_back({value, "10^{" + with_minus_sign(std::to_string(k)) + "}"});
      else
        ticks.minor.push_back(value);
    }
    if (stride == 1) {
      for (int k = k_lo - 1; k <= k_hi; ++k)
        for (int m = 2; m <= 9; ++m)
          if (const double value = scaled(m, k); value >= lo && value <= hi) ticks.minor.push_back(value);
      std::sort(ticks.minor.begin(), ticks.minor.end());
    }
    return ticks;
  }
  // Less than two decades: label m x 10^k for m in 1..9, or only 1, 2, 5 when crowded.
  std::vector<std::pair<double, int>> candidates;  // value, power of ten
  for (int k = floor_log10(lo); k <= floor_log10(hi); ++k)
    for (int m = 1; m <= 9; ++m)
      if (const double value = scaled(m, k); inside(value, lo, hi)) candidates.emplace_back(value, k);
  const auto round_mantissa = [](const std::pair<double, int>& c) {
    const double m = std::round(c.first / scaled(1.0, c.second));
    return m == 1.0 || m == 2.0 || m == 5.0;
  };
  const bool crowded = std::ssize(candidates) > max_ticks;
  const bool scientific = wants_scientific(lo, hi);
  for (const auto& candidate : candidates) {
    if (crowded && !round_mantissa(candidate))
      ticks.minor.push_back(candidate.first);
    else
      ticks.major.push_back(
          {candidate.first, number_label(candidate.first, scaled(1.0, candidate.second), scientific)});
  }
  if (ticks.major.size() < 2) return linear_ticks(lo, hi, max_ticks);
  return ticks;
}

}  // namespace linkage::plot
