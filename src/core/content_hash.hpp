#pragma once
// A short fingerprint of text for caches (equal text, equal hash; not cryptographic).
#include <string>
#include <string_view>

namespace linkage {

/// 64-bit FNV-1a of `text`, as 16 lowercase hex digits.
[[nodiscard]] std::string content_hash(std::string_view text);

}  // namespace linkage
