#pragma once
// Exercise answers and {{...}} in lesson text: the mechanism files' expression language
// (symbolic/expression_reader.hpp) over the names of quantities.hpp, read once (names
// resolved, errors found at validation) and evaluated at each step's values.
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "lesson/quantities.hpp"

namespace GiNaC {
class ex;
}
namespace linkage::sym {
class System;
}

namespace linkage::lesson {

/// Names a lesson that names a mechanism may use besides the quantities, each with its
/// value: the mechanism's parameters, definitions and body inertias (I, I_1), at its
/// parameter values; its initial coordinates and rates ("2.theta", "S.s_dot") and the Case 3
/// unknowns at the start with what that case recovers ("2.theta_ddot", "B.force_x",
/// "O.force_y", "S.normal"), named and valued as `linkage solve --mechanism --format json`.
/// Where a name is also a quantity's, the mechanism's wins.
using MechanismNames = std::map<std::string, GiNaC::ex>;
[[nodiscard]] MechanismNames mechanism_names(const sym::System& system);

class Expression {
 public:
  /// Parses `text`; throws Error::input starting with `origin` (e.g. "file:3:10: answer")
  /// naming the problem and where in the text it is.
  static Expression parse(std::string_view text, const std::string& origin, const MechanismNames* mechanism = nullptr);

  [[nodiscard]] double evaluate(const QuantityValues& values) const;
  [[nodiscard]] const std::string& text() const { return text_; }
  /// The single quantity this expression names, when it is just a name (for units).
  [[nodiscard]] const QuantityInfo* single_quantity() const;

 private:
  std::string text_;
  std::shared_ptr<const GiNaC::ex> value_;  // shared: an expression is read once and never changes
};

}  // namespace linkage::lesson
