#pragma once
// "Did you mean ...?" for misspelt keys, kinds and names in a lesson.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkage::lesson {

/// The candidate closest to `word` by optimal-string-alignment distance (a swap of two
/// neighbouring letters counts as one edit; case is ignored), if it is close enough to
/// be a plausible typo: at most max(2, |word| / 3) edits.
[[nodiscard]] std::optional<std::string_view> closest_match(std::string_view word,
                                                            const std::vector<std::string_view>& candidates);

/// "a, b, c".
[[nodiscard]] std::string join(const std::vector<std::string_view>& words, std::string_view separator = ", ");

/// `text` fit to quote in a one-line message: whole when short, else the 40 or so
/// characters up to and including `at`, cut marks "…" where text is left out; line
/// breaks and other control characters read as spaces.
[[nodiscard]] std::string excerpt(std::string_view text, std::size_t at = std::string_view::npos);

}  // namespace linkage::lesson
