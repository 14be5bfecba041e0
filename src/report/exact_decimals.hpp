#pragma once
// A mechanism's decimals as exact fractions, for the exported code (code_export.hpp).
// GiNaC reads "0.15" in an expression as a float and then adds and multiplies floats in
// an order that follows its internal (hash) order, so a sum that should cancel can keep
// a residue (2.7e-19 c s' s / ...) in one run and not in the next. Written as fractions
// the same expressions are exact and come out the same in every run.
#include <string>

#include "model/mechanism.hpp"

namespace linkage {

/// `expression` with every number that has a decimal point or an exponent written as an
/// exact fraction or whole number: "L/2 - 0.04" -> "L/2 - (4/100)", "1.5e3*k" ->
/// "1500*k". Names ("L1", "tau0"), integers and numbers needing more than 30 zeros stay
/// as they are.
[[nodiscard]] std::string exact_decimal_text(const std::string& expression);

/// The mechanism with exact_decimal_text applied to every quantity.
[[nodiscard]] Mechanism with_exact_decimals(Mechanism mechanism);

}  // namespace linkage
