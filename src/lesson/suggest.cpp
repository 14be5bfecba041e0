#include "lesson/suggest.hpp"

#include <algorithm>
#include <cctype>

#include "model/name_match.hpp"

namespace linkage::lesson {

std::optional<std::string_view> closest_match(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::optional<std::string_view> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (std::string_view c : candidates) {
    const std::size_t distance = typo_distance(word, c);
    if (distance < best_distance) {
      best_distance = distance;
      best = c;
    }
  }
  return best;
}

std::string join(const std::vector<std::string_view>& words, std::string_view separator) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += separator;
    out += w;
  }
  return out;
}

std::string excerpt(std::string_view text, std::size_t at) {
  constexpr std::size_t kShort = 60, kWindow = 40;
  std::size_t begin = 0, end = text.size();
  if (text.size() > kShort) {
    end = at < text.size() ? at + 1 : text.size();
    begin = end > kWindow ? end - kWindow : 0;
    end = std::max(end, std::min(text.size(), begin + kWindow));
    // Whole UTF-8 characters only.
    const auto continuation = [&](std::size_t i) {
      return i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
    };
    while (continuation(begin)) ++begin;
    while (continuation(end)) ++end;
  }
  std::string out = begin > 0 ? "…" : "";
  for (char c : text.substr(begin, end - begin)) out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  if (end < text.size()) out += "…";
  return out;
}

}  // namespace linkage::lesson
