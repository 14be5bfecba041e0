#pragma once
// Exercise answers and {{...}} in lesson text: the mechanism files' expression language
// (symbolic/expression_reader.hpp) over the homework's quantities
// (formulations/homework_quantities.hpp) and a mechanism's quotable values, read once
// (names resolved, errors found at validation) and evaluated at each step's values.
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "formulations/homework_quantities.hpp"

namespace GiNaC {
class ex;
}
namespace linkage::sym {
class System;
}

namespace linkage::lesson {

/// Names a lesson that names a mechanism may use besides the quantities, with their values
/// (report's quotable_values); where a name is also a quantity's, the mechanism's wins.
using MechanismNames = std::map<std::string, GiNaC::ex>;

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
