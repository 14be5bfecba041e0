#include "core/name_match.hpp"

#include <algorithm>
#include <cctype>

namespace linkage {
namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

}  // namespace

// Optimal string alignment: Levenshtein plus swaps of neighbours ("lenght" -> "length").
std::size_t typo_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
    }
  return at(n, m);
}

std::optional<std::string> closest_name(std::string_view word, const std::vector<std::string>& candidates) {
  // A long word against many names would cost |word| * |name| each: a typo is short.
  constexpr std::size_t kLongest = 200;
  if (word.size() > kLongest) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    if (c.size() > kLongest) continue;
    const std::size_t distance = typo_distance(word, c);
    // Not when every letter differs ('2' for '1'): that is no typo.
    if (distance < best_distance && distance < std::max(word.size(), c.size())) {
      best_distance = distance;
      best = c;
    }
  }
  return best;
}

std::string join_names(const std::vector<std::string>& names, std::string_view none) {
  if (names.empty()) return std::string(none);
  std::string out;
  for (const std::string& name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const auto close = closest_name(word, candidates);
  if (!close) return {};
  std::string out = " (did you mean '";
  out += *close;
  out += "'?)";
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

}  // namespace linkage
