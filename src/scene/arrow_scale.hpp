#pragma once
// One length scale per kind of arrow: pin forces are milli-newtons while gravity is
// about a newton, so a shared scale would hide one or the other. Each scale is a round
// number of units per world centimetre (1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 times a power of ten),
// chosen so the largest arrow over the clip is at most a given length, and stated in
// the legend
// ("1 cm = 2 mN").
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace linkage {

struct ArrowScale {
  int mantissa = 0;  // 10, 15, 20, 25, 30, 40, 50, 60 or 80; 0 when there is nothing to draw
  int exponent = 0;  // units per centimetre = mantissa x 10^exponent
  double metres_per_unit = 0;

  [[nodiscard]] bool drawable() const { return mantissa != 0; }
  [[nodiscard]] double units_per_cm() const;
};

/// The scale at which an arrow of `largest_magnitude` is at most `longest_arrow`
/// metres long and at least two thirds of that. Not drawable when the magnitude is 0
/// or not finite.
[[nodiscard]] ArrowScale choose_arrow_scale(double largest_magnitude, double longest_arrow);

/// "1 cm = 2 mN" for unit "N", with an SI prefix keeping the number in 1 .. 999.
[[nodiscard]] std::string describe_arrow_scale(const ArrowScale& scale, std::string_view unit);

/// The scale of `units_per_cm` (> 0, finite) rounded to three significant digits.
[[nodiscard]] ArrowScale arrow_scale_of(double units_per_cm);

/// What `--arrow-scale` asks for. By default each kind gets its own scale (the largest
/// arrow of the clip at a set length); `common` gives every force one scale (so their
/// lengths compare: the pin force beside gravity); `KIND=VALUE` fixes a kind's scale at
/// VALUE units per centimetre, over either.
struct ArrowScaleRequest {
  bool common = false;
  double common_units_per_cm = 0;                     // "common=VALUE"; 0: chosen from the clip
  std::vector<std::pair<std::string, double>> fixed;  // kind name, units per cm

  /// The fixed units per cm of `kind`, else 0.
  [[nodiscard]] double fixed_for(std::string_view kind) const;
  [[nodiscard]] bool is_default() const { return !common && fixed.empty(); }
};

/// "common", "common=VALUE" and "KIND=VALUE" entries, comma-separated; KIND one of
/// `kinds`. Error::input naming `origin`, the bad entry and the valid forms otherwise.
[[nodiscard]] ArrowScaleRequest parse_arrow_scale_request(std::string_view text, const std::string& origin,
                                                          std::span<const std::string_view> kinds);

/// A length in metres as people write it: "5 cm", "1 m", "200 m", "2 mm".
[[nodiscard]] std::string describe_length(int mantissa, int exponent);

/// The round length (1, 2 or 5 x 10^k metres) nearest above `at_least` metres.
struct RoundLength {
  int mantissa = 1;
  int exponent = 0;
  [[nodiscard]] double metres() const;
};
[[nodiscard]] RoundLength round_length_at_least(double at_least);

}  // namespace linkage
