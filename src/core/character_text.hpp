#pragma once
// Characters in messages: a stray character named whole with its code point ("'−'
// (U+2212)", not a lone byte), advice for the look-alikes people paste from documents
// (the minus sign U+2212 for '-'), and NUL bytes made visible (a C string ends at them).
#include <cstddef>
#include <string>
#include <string_view>

namespace linkage {

/// The character that starts at byte `at` of `text` (UTF-8) as a message shows it:
/// "'−' (U+2212): use '-'" for a look-alike of an ASCII operator, "'é' (U+00E9)" for
/// another non-ASCII character, "'#'" for ASCII, "byte 0xE2 (not UTF-8)" for a stray byte.
[[nodiscard]] std::string describe_character(std::string_view text, std::size_t at);

/// "; '−' (U+2212): use '-'" for the first look-alike in `text` (or for the character at
/// byte `at` only, when given), else "": for the end of "'−1' is not a number".
[[nodiscard]] std::string lookalike_advice(std::string_view text, std::size_t at = std::string_view::npos);

/// `text` with each NUL byte written \0.
[[nodiscard]] std::string visible_nul(std::string_view text);

}  // namespace linkage
