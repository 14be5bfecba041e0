#include "core/content_hash.hpp"

#include <array>
#include <cstdint>
#include <cstdio>

namespace linkage {

std::string content_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  std::array<char, 17> hex{};
  std::snprintf(hex.data(), hex.size(), "%016llx", static_cast<unsigned long long>(h));
  return {hex.data(), 16};
}

}  // namespace linkage
