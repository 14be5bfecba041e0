#pragma once
// How a worked derivation prints, for every human-readable format (text, LaTeX,
// Markdown): the digits, the text symbols, the width and which parts show.
#include <array>
#include <cstddef>

#include "core/angle_unit.hpp"
#include "core/style.hpp"

namespace linkage {

/// The parts of a worked solution, in the order they print: the inputs, the derivation
/// groups, and within each case its equations and symbolic matrices, numeric matrices,
/// solution, and residual with condition number; then the cases' comparison.
enum class ReportPart { inputs, inertia, constraints, energy, symbolic, numeric, solution, residual, comparison };
inline constexpr std::size_t kReportPartCount = 9;

struct ReportOptions {
  int digits = 6;                     // significant digits; JSON always prints full precision
  Style text_style = Style::unicode;  // the text format's symbols: unicode or ascii
  std::size_t width = 80;             // the text format's line width, display columns
  AngleUnit angles = AngleUnit::rad;  // the text format's state and solution tables (derivations stay in rad)
  /// Which parts print (`linkage solve` prints all; a lesson's solve step chooses).
  std::array<bool, kReportPartCount> parts{true, true, true, true, true, true, true, true, true};
  [[nodiscard]] bool shows(ReportPart p) const { return parts[static_cast<std::size_t>(p)]; }
};

/// Unicode when the environment's locale (LC_ALL, LC_CTYPE, LANG) uses UTF-8, else
/// ASCII. Reads the locale with setlocale(LC_CTYPE, "") and restores the previous one.
[[nodiscard]] Style text_style_from_locale();

}  // namespace linkage
