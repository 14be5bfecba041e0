#pragma once
// Exercise answers and {{...}} in lesson text: the mechanism files' expression language
// (symbolic/expression_reader.hpp) over the quotable values of the step's mechanism
// (report/quotable_values.hpp; the homework's are two-blocks.toml's, named by its
// [aliases]), read once (names resolved, errors found at validation) to the number it is.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace GiNaC {
class ex;
}

namespace linkage {
class QuotableValues;
}

namespace linkage::lesson {

class Expression {
 public:
  /// Parses `text` over `names` (none: numbers and pi only); throws Error::input starting
  /// with `origin` (e.g. "file:3:10: answer") naming the problem and where in the text it is.
  static Expression parse(std::string_view text, const std::string& origin, const QuotableValues* names = nullptr);

  [[nodiscard]] double evaluate() const;
  [[nodiscard]] const std::string& text() const { return text_; }
  /// The single name this expression is, when it is just a name (for units).
  [[nodiscard]] const std::optional<std::string>& single_name() const { return single_name_; }

 private:
  std::string text_;
  std::optional<std::string> single_name_;
  struct Value;                         // the expression read and its names' values
  std::shared_ptr<const Value> value_;  // shared: an expression is read once and never changes
};

}  // namespace linkage::lesson
