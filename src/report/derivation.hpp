#pragma once
// The worked steps before the equations of motion, each a formula in earlier symbols:
//   inertia and pin offset   I_zz^C = m (w² + L²) / 12,  D = L/2 - b,  I_zz^P = I_zz^C + m D²
//   the pin constraint       x_P = x₁ + D cos θ₁, ..., x₂ = x_P + D cos θ₂, ẋ₂ = ẋ₁ - D (...)
//   energy and momentum      T, V = m g (y₁ + y₂), E = T + V, p_x, p_y, H_c
// The value shown for each step is the model's (derive()); a test checks that every
// formula evaluates to it, so the printed formula cannot drift from the code.
#include <string_view>
#include <vector>

#include "report/formula.hpp"
#include "report/worked_solution.hpp"

namespace linkage {

struct DerivationStep {
  Symbol quantity;        // the left-hand side; its value is the model's
  Formula formula;        // the definition in inputs and earlier quantities
  std::string_view unit;  // ASCII, e.g. "kg m^2" (see unit_text)
};

struct DerivationGroup {
  std::string_view title;
  std::string_view note;  // one plain sentence for the reader (no symbols, any format)
  std::vector<DerivationStep> steps;
  ReportPart part = ReportPart::inertia;  // which ReportOptions::parts entry shows it
};

/// The three groups of steps at the worked solution's inputs.
[[nodiscard]] std::vector<DerivationGroup> derivation(const WorkedSolution& worked);

}  // namespace linkage
