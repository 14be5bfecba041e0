#pragma once
// "Did you mean ...?" and name lists for messages: the TOML readers, the value parsers of
// flags and keys (camera, quality, angles, integrator, ...), lessons.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

/// Edits between two words, ignoring case, a swap of neighbours counting as one (optimal
/// string alignment).
[[nodiscard]] std::size_t typo_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` (edits ignoring case, a swap of neighbours counting as
/// one), if it is close enough to be a typo: at most max(2, |word| / 3) edits, and not
/// every letter.
[[nodiscard]] std::optional<std::string> closest_name(std::string_view word,
                                                      const std::vector<std::string>& candidates);

/// "a, b, c", or `none` when the list is empty.
[[nodiscard]] std::string join_names(const std::vector<std::string>& names, std::string_view none = "none");

/// " (did you mean 'x'?)" when a candidate is close, else "".
[[nodiscard]] std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

/// `text` fit to quote in a one-line message: whole when short, else the 40 or so
/// characters up to and including `at`, cut marks "…" where text is left out; line
/// breaks and other control characters read as spaces.
[[nodiscard]] std::string excerpt(std::string_view text, std::size_t at = std::string_view::npos);

}  // namespace linkage
