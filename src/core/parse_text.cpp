#include "core/parse_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/character_text.hpp"
#include "core/error.hpp"

namespace linkage {

double parse_number(const std::string& text, const std::string& setting, const std::string& unit) {
  double value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last)
    throw Error::invalid(setting, "'" + text + "' is outside the range of double precision (about 1e-308 to 1e308)");
  if (text.empty() || ec != std::errc() || ptr != last)
    throw Error::invalid(
        setting, "'" + text + "' is not a number" + (unit.empty() ? "" : " (" + unit + ")") + lookalike_advice(text));
  if (!std::isfinite(value))
    throw Error::invalid(
        setting, "'" + text + "' is not a finite number; give a finite value" + (unit.empty() ? "" : " in " + unit));
  return value;
}

std::vector<std::string> split_commas(const std::string& list) {
  std::vector<std::string> items;
  if (list.empty()) return items;
  int depth = 0;  // a comma inside parentheses is an expression's: atan2(y, x)
  std::size_t start = 0;
  for (std::size_t at = 0; at <= list.size(); ++at) {
    if (at < list.size() && list[at] == '(') ++depth;
    if (at < list.size() && list[at] == ')') depth = std::max(0, depth - 1);
    if (at == list.size() || (list[at] == ',' && depth == 0)) {
      items.push_back(list.substr(start, at - start));
      start = at + 1;
    }
  }
  return items;
}

}  // namespace linkage
