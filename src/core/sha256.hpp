#pragma once
// SHA-256 (FIPS 180-4), for a page's Content-Security-Policy: the hash of each inline
// script and style it allows.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace linkage {

/// The 32-byte SHA-256 digest of `data`.
[[nodiscard]] std::array<std::uint8_t, 32> sha256(std::string_view data);

/// `bytes` in base64 (RFC 4648, with padding).
[[nodiscard]] std::string base64(std::string_view bytes);

}  // namespace linkage
