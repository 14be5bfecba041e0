// A stray character is named whole, with its code point, and look-alikes of ASCII
// operators say what to type instead; NUL bytes become visible.
#include "core/character_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace linkage {
namespace {

TEST(CharacterText, NamesTheWholeCharacterAndItsCodePoint) {
  EXPECT_EQ(describe_character("\u2212r/2", 0), "'\u2212' (U+2212): use '-'");
  EXPECT_EQ(describe_character("2 \u00d7 a", 2), "'\u00d7' (U+00D7): use '*'");
  EXPECT_EQ(describe_character("caf\u00e9", 3), "'\u00e9' (U+00E9)");
  EXPECT_EQ(describe_character("a#b", 1), "'#'");
  EXPECT_EQ(describe_character("\xe2\x88", 0), "byte 0xE2 (not UTF-8)");  // cut short
  EXPECT_EQ(describe_character(std::string("a\0b", 3), 1), "'\\0' (U+0000)");
  EXPECT_EQ(describe_character("ab", 2), "the end");
}

TEST(CharacterText, AdvisesOnTheFirstLookalike) {
  EXPECT_EQ(lookalike_advice("\u22121.5e\u22123"), "; '\u2212' (U+2212): use '-'");
  EXPECT_EQ(lookalike_advice("1\u20132"), "; '\u2013' (U+2013): use '-'");
  EXPECT_EQ(lookalike_advice("-1.5"), "");
  EXPECT_EQ(lookalike_advice("\u00e9\u2212", 0), "");  // only the character at byte 0
  EXPECT_EQ(lookalike_advice("\u00e9\u2212", 2), "; '\u2212' (U+2212): use '-'");
}

TEST(CharacterText, WritesNulBytesVisibly) {
  EXPECT_EQ(visible_nul(std::string("a\0b\0", 4)), "a\\0b\\0");
  EXPECT_EQ(visible_nul("plain"), "plain");
}

}  // namespace
}  // namespace linkage
