#include "lesson/text_template.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "report/markdown.hpp"

namespace linkage::lesson {

TextTemplate TextTemplate::parse(std::string_view text, const std::string& origin, const QuotableValues* names) {
  TextTemplate t;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t open = text.find("{{", pos);
    Part part;
    if (open == std::string_view::npos) {
      part.literal = std::string(text.substr(pos));
      t.parts_.push_back(std::move(part));
      break;
    }
    part.literal = std::string(text.substr(pos, open - pos));
    const std::size_t close = text.find("}}", open + 2);
    if (close == std::string_view::npos)
      throw Error::input(origin + ": '{{' at character " + std::to_string(open + 1) +
                         " is not closed by '}}'; write {{NAME}} or {{EXPRESSION : DIGITS}}");
    std::string_view inside = text.substr(open + 2, close - open - 2);
    const std::size_t colon = inside.rfind(':');
    if (colon != std::string_view::npos) {
      std::string_view digits = inside.substr(colon + 1);
      while (!digits.empty() && digits.front() == ' ') digits.remove_prefix(1);
      while (!digits.empty() && digits.back() == ' ') digits.remove_suffix(1);
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), part.digits);
      if (ec != std::errc() || ptr != digits.data() + digits.size() || part.digits < 1 || part.digits > 17)
        throw Error::input(origin + ": '{{" + excerpt(inside) +
                           "}}': the digits after ':' must be a whole number from 1 to 17");
      inside = inside.substr(0, colon);
    }
    part.value.push_back(Expression::parse(inside, origin + ": {{" + excerpt(inside) + "}}", names));
    part.where = text_position(text, text.data() + open);
    t.parts_.push_back(std::move(part));
    pos = close + 2;
  }
  // The text as it will be shown, each placeholder standing in as digits of the same
  // length (values are numbers), so errors point at the right line and column.
  std::string shown(text);
  for (std::size_t at = shown.find("{{"); at != std::string::npos; at = shown.find("{{", at)) {
    const std::size_t end = shown.find("}}", at + 2) + 2;
    std::fill(shown.begin() + static_cast<std::ptrdiff_t>(at), shown.begin() + static_cast<std::ptrdiff_t>(end), '0');
  }
  check_markdown(shown, origin);
  return t;
}

void TextTemplate::require_finite(const std::string& origin) const {
  for (const Part& part : parts_)
    for (const Expression& e : part.value)
      if (const double value = e.evaluate(); !std::isfinite(value))
        throw Error::input(origin + ": " + part.where + ": {{" + excerpt(e.text()) + "}} is " +
                           (std::isnan(value) ? std::string("nan") : format_roundtrip(value)) +
                           " at these inputs; text can show only finite numbers");
}

std::string TextTemplate::render() const {
  std::string out;
  for (const Part& part : parts_) {
    out += part.literal;
    for (const Expression& e : part.value) out += format_significant(e.evaluate(), part.digits);
  }
  return out;
}

}  // namespace linkage::lesson
