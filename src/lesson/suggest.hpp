#pragma once
// "Did you mean ...?" for misspelt keys, kinds and names in a lesson.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/name_match.hpp"  // excerpt

namespace linkage::lesson {

/// The candidate closest to `word` by optimal-string-alignment distance (a swap of two
/// neighbouring letters counts as one edit; case is ignored), if it is close enough to
/// be a plausible typo: at most max(2, |word| / 3) edits.
[[nodiscard]] std::optional<std::string_view> closest_match(std::string_view word,
                                                            const std::vector<std::string_view>& candidates);

/// "a, b, c".
[[nodiscard]] std::string join(const std::vector<std::string_view>& words, std::string_view separator = ", ");

}  // namespace linkage::lesson
