#include "cli/step_range.hpp"

#include <charconv>
#include <string_view>

#include "core/error.hpp"

namespace linkage::cli {

std::vector<bool> parse_step_range(const std::string& text, std::size_t count) {
  std::vector<bool> selected(count, false);
  const std::string valid = "; write N, N-M, N-, -M or a comma list of these, with steps 1 to " + std::to_string(count);
  auto number = [&](std::string_view s, std::size_t fallback) -> std::size_t {
    if (s.empty()) return fallback;
    std::size_t n = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc() || ptr != s.data() + s.size())
      throw Error::invalid("only", "'" + std::string(s) + "' is not a step number" + valid);
    if (n < 1 || n > count)
      throw Error::invalid(
          "only", "step " + std::to_string(n) + " does not exist; the lesson has steps 1 to " + std::to_string(count));
    return n;
  };
  if (text.empty()) throw Error::invalid("only", "the range is empty" + valid);
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    const std::string_view part(text.data() + start, comma - start);
    if (part.empty()) throw Error::invalid("only", "'" + text + "' has an empty part" + valid);
    const std::size_t dash = part.find('-');
    const std::size_t first = dash == std::string_view::npos ? number(part, 1) : number(part.substr(0, dash), 1);
    const std::size_t last = dash == std::string_view::npos ? first : number(part.substr(dash + 1), count);
    if (first > last) throw Error::invalid("only", "'" + std::string(part) + "' runs backwards" + valid);
    for (std::size_t i = first; i <= last; ++i) selected[i - 1] = true;
    start = comma + 1;
  }
  return selected;
}

}  // namespace linkage::cli
