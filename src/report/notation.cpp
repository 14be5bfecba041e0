#include "report/notation.hpp"

#include "core/number_format.hpp"

namespace linkage {

std::string format_number(double value, Style style, int digits) {
  std::string text = digits > 0 ? format_significant(value, digits) : format_roundtrip(value);
  if (text == "-0") text = "0";
  const auto e = text.find('e');
  if (style != Style::latex || e == std::string::npos) return text;
  const std::string mantissa = text.substr(0, e);
  const int exponent = std::stoi(text.substr(e + 1));
  const std::string power = "10^{" + std::to_string(exponent) + "}";
  return mantissa == "1" ? power : mantissa == "-1" ? "-" + power : mantissa + " \\times " + power;
}

std::string unit_text(std::string_view ascii_unit, Style style) {
  std::string out;
  for (std::size_t i = 0; i < ascii_unit.size(); ++i) {
    const char c = ascii_unit[i];
    if (style == Style::unicode && c == '^' && i + 1 < ascii_unit.size() && ascii_unit[i + 1] == '2') {
      out += "²";
      ++i;
    } else if (style == Style::latex && c == ' ') {
      out += "\\,";
    } else {
      out += c;
    }
  }
  return style == Style::latex ? "\\mathrm{" + out + "}" : out;
}

std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (std::string_view piece : pieces) out += piece;
  return out;
}

std::string parenthesized(std::string_view label) { return concat({"(", label, ")"}); }

}  // namespace linkage
