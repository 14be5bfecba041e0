#pragma once
// `linkage lesson --only RANGE`: which steps to run.
#include <string>
#include <vector>

namespace linkage::cli {

/// Parses "3", "2-5", "4-", "-3" or a comma list of these over steps 1..count; one
/// flag per step. Throws Error::input naming --only for a malformed or out-of-range part.
[[nodiscard]] std::vector<bool> parse_step_range(const std::string& text, std::size_t count);

}  // namespace linkage::cli
