#pragma once
// Tick positions and labels for plot axes. Pure functions, no drawing: linear axes get
// "nice" steps (1, 2 or 5 times a power of ten), log axes get decades with minor ticks
// at 2..9 times each decade. Labels use the plot text markup (^{...} is a superscript)
// and a real minus sign (U+2212), e.g. "10^{−8}" or "2.5×10^{−9}".
#include <string>
#include <vector>

namespace linkage::plot {

/// A labelled (major) tick.
struct Tick {
  double value = 0;
  std::string label{};  ///< In plot text markup.
};

/// The ticks of one axis within its limits, in increasing order.
struct Ticks {
  std::vector<Tick> major{};
  std::vector<double> minor{};  ///< Unlabelled short ticks between the major ones.
};

/// Ticks at every multiple of the finest step s = {1, 2, 5} x 10^k that puts at most
/// `max_ticks` (>= 2) ticks in [lo, hi]. Minor ticks divide each step in 4 or 5.
/// Labels are plain decimals, or m×10^{k} when the axis magnitude is below 1e-3 or
/// at least 1e5. Empty when !(lo < hi) or either limit is not finite.
[[nodiscard]] Ticks linear_ticks(double lo, double hi, int max_ticks);

/// Ticks for an angle in degrees: at multiples of the finest of 15, 30, 45, 90, 180
/// and 360 that puts at most `max_ticks` ticks in [lo, hi] (0, 90, 180, 270, 360 for a
/// turn), minor ticks dividing it in 3 (2 for 180, 4 for 360); like linear_ticks when
/// that leaves fewer than three ticks or the range spans more than 12 turns.
[[nodiscard]] Ticks degree_ticks(double lo, double hi, int max_ticks);

/// Ticks for a logarithmic axis on [lo, hi], 0 < lo < hi: major ticks at the decades
/// 10^k inside the range, every n-th decade (n in 1, 2, 3, 5, 10, ...) when there
/// are more than `max_ticks`; minor ticks at m×10^k (m = 2..9) when every decade is
/// labelled, otherwise at the unlabelled decades. A range holding fewer than two
/// decades is labelled at 1, 2 and 5 (or all of 1..9) times its powers of ten, and
/// failing that like a linear axis. Empty for an invalid range.
[[nodiscard]] Ticks log_ticks(double lo, double hi, int max_ticks);

}  // namespace linkage::plot
