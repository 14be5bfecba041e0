#pragma once
// Arithmetic over the named quantities, for exercise answers and {{...}} in lesson text:
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := '-' unary | power
//   power   := primary ('^' unary)?
//   primary := number | name | function '(' expr (',' expr)* ')' | '(' expr ')'
// Names are those of quantities.hpp; functions: sin cos tan asin acos atan atan2 sqrt
// abs exp log log10 hypot min max. Compiled once (names resolved, errors found at
// validation), evaluated many times.
#include <string>
#include <string_view>
#include <vector>

#include "lesson/quantities.hpp"

namespace linkage::lesson {

class Expression {
 public:
  /// Parses `text`; throws Error::input starting with `origin` (e.g. "file:3:10: answer")
  /// naming the problem and where in the text it is.
  static Expression parse(std::string_view text, const std::string& origin);

  [[nodiscard]] double evaluate(const QuantityValues& values) const;
  [[nodiscard]] const std::string& text() const { return text_; }
  /// True when the expression is one number with no names (a hard-coded answer).
  [[nodiscard]] bool is_constant() const;
  /// The single quantity this expression names, when it is just a name (for units).
  [[nodiscard]] const QuantityInfo* single_quantity() const;

  enum class Op { number, quantity, negate, add, subtract, multiply, divide, power, call };
  struct Node {
    Op op = Op::number;
    double number = 0;
    std::size_t index = 0;  // quantity index, or function index for calls
    int args = 0;           // operands taken from the evaluation stack
  };

 private:
  std::string text_;
  std::vector<Node> program_;  // postfix: operands before their operator
};

}  // namespace linkage::lesson
