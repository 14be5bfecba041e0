#pragma once
// Lesson text with computed values: "{{I_zz_P}}" or "{{1000 * I_zz_P : 4}}" is replaced
// by the expression's value at the step's mechanism and settings, to 6 (or the given number of)
// significant digits. Lesson Markdown has no other use for "{{", so there is no escape;
// an unclosed "{{" is an error.
#include <string>
#include <string_view>
#include <vector>

#include "lesson/expression.hpp"

namespace linkage::lesson {

class TextTemplate {
 public:
  TextTemplate() = default;
  /// Parses the placeholders of `text`; throws Error::input starting with `origin`.
  /// `names`: the quotable values of the step's mechanism.
  static TextTemplate parse(std::string_view text, const std::string& origin, const QuotableValues* names = nullptr);
  /// The text with every placeholder replaced by its value.
  [[nodiscard]] std::string render() const;
  /// Throws Error::input, starting with `origin` and naming the placeholder's line and
  /// column in the text, when a placeholder is not a finite number ({{1/0}},
  /// {{sqrt(-1)}}): the text must never show inf or nan.
  void require_finite(const std::string& origin) const;
  [[nodiscard]] bool empty() const { return parts_.empty(); }

 private:
  struct Part {
    std::string literal;            // text before the placeholder
    std::vector<Expression> value;  // zero or one expression
    int digits = 6;
    std::string where;  // "line 2, column 5" of the placeholder's "{{" in the text
  };
  std::vector<Part> parts_;
};

}  // namespace linkage::lesson
