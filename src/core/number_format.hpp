#pragma once
// Number to text: shortest round-trip form for machine output, fixed significant
// digits for people.
#include <string>

namespace linkage {

/// The shortest decimal that parses back to exactly `value` (JSON, CSV).
[[nodiscard]] std::string format_roundtrip(double value);
/// `digits` significant digits, trailing zeros trimmed, exponent only when needed
/// (e.g. 0.0129194, -9.80725, 2.04333e-03 -> 0.00204333).
[[nodiscard]] std::string format_significant(double value, int digits);

}  // namespace linkage
