#pragma once
// How names from a mechanism file are spelt in each style. A name's trailing digits or
// "_suffix" become a subscript and a Greek base name its letter: "tau0" is τ₀ / tau0 /
// \tau_{0}; a body "1" gives x₁ / x1 / x_1, a body "crank" x_crank / x_crank /
// x_{\mathrm{crank}}.
#include <string>

namespace linkage::sym {

struct Spelling {
  std::string unicode, ascii, latex;
};

/// A parameter or definition name.
[[nodiscard]] Spelling spell_name(const std::string& name);

/// A body-indexed quantity: `base` is "x", "y", "theta", "s", "I", "m"; `dots` 0, 1 or 2
/// time derivatives; `index` the body or joint name.
[[nodiscard]] Spelling spell_indexed(const std::string& base, int dots, const std::string& index);

}  // namespace linkage::sym
