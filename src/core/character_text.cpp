#include "core/character_text.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace linkage {
namespace {

struct Lookalike {
  char32_t code;
  char ascii;
};
// Pasted from word processors and PDFs: dashes and the minus sign, multiplication and
// division signs.
constexpr std::array<Lookalike, 10> kLookalikes{{{U'\u2212', '-'},
                                                 {U'\u2010', '-'},
                                                 {U'\u2011', '-'},
                                                 {U'\u2012', '-'},
                                                 {U'\u2013', '-'},
                                                 {U'\uFE63', '-'},
                                                 {U'\u00D7', '*'},
                                                 {U'\u22C5', '*'},
                                                 {U'\u00F7', '/'},
                                                 {U'\u2215', '/'}}};

struct Decoded {
  char32_t code = 0;
  std::size_t size = 0;  // 0: not a valid UTF-8 sequence
};

Decoded decode(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) return {lead, 1};
  const std::size_t size = lead >= 0xF0 && lead < 0xF8 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (size == 0 || at + size > text.size()) return {};
  char32_t code = lead & (0x7F >> size);
  for (std::size_t i = 1; i < size; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return {};
    code = (code << 6) | (byte(at + i) & 0x3F);
  }
  return {code, size};
}

std::string code_point(char32_t code) {
  std::array<char, 16> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "U+%04X", static_cast<unsigned>(code));
  return buffer.data();
}

}  // namespace

std::string describe_character(std::string_view text, std::size_t at) {
  if (at >= text.size()) return "the end";
  const Decoded d = decode(text, at);
  if (d.size == 0) {
    std::array<char, 32> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "byte 0x%02X (not UTF-8)", static_cast<unsigned char>(text[at]));
    return buffer.data();
  }
  if (d.code == 0) return "'\\0' (U+0000)";
  // Appended piece by piece: GCC 12's -Wrestrict misfires on "'" + std::string.
  std::string out(1, '\'');
  out.append(text.substr(at, d.size)).append("'");
  if (d.code < 0x80) return out;
  out.append(" (").append(code_point(d.code)).append(")");
  for (const Lookalike& l : kLookalikes)
    if (l.code == d.code) out.append(": use '").append(1, l.ascii).append("'");
  return out;
}

std::string lookalike_advice(std::string_view text, std::size_t at) {
  const std::size_t first = at == std::string_view::npos ? 0 : at;
  const std::size_t last = at == std::string_view::npos ? text.size() : std::min(at + 1, text.size());
  for (std::size_t i = first; i < last; ++i) {
    const Decoded d = decode(text, i);
    for (const Lookalike& l : kLookalikes)
      if (d.size > 0 && l.code == d.code) return std::string("; ").append(describe_character(text, i));
  }
  return {};
}

std::string visible_nul(std::string_view text) {
  std::string out(text);
  for (std::size_t at = out.find('\0'); at != std::string::npos; at = out.find('\0', at + 2)) out.replace(at, 1, "\\0");
  return out;
}

}  // namespace linkage
