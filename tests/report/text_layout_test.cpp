#include "report/text_layout.hpp"

#include <gtest/gtest.h>

#include "report/notation.hpp"

namespace linkage {
namespace {

TEST(TextLayout, Utf8DecodesAndEncodesEachLength) {
  for (const char32_t cp : {U'A', U'θ', U'€', U'𝜃'}) {
    const std::string bytes = encode_utf8(cp);
    const Utf8Char c = decode_utf8(bytes, 0);
    EXPECT_EQ(c.cp, cp);
    EXPECT_EQ(c.size, bytes.size());
  }
  EXPECT_EQ(encode_utf8(U'€'), "\xE2\x82\xAC");
  // A byte that starts no whole sequence reads as itself, one byte long.
  for (const std::string bad : {"\x80", "\xE2\x82", "\xE2(x"}) {
    const Utf8Char c = decode_utf8(bad, 0);
    EXPECT_EQ(c.cp, static_cast<unsigned char>(bad[0]));
    EXPECT_EQ(c.size, 1u);
  }
}

TEST(TextLayout, DisplayWidthCountsCombiningMarksAsZero) {
  EXPECT_EQ(display_width("abc"), 3u);
  EXPECT_EQ(display_width("θ₁"), 2u);
  EXPECT_EQ(display_width("θ̇₁"), 2u);  // θ + U+0307 + ₁
  EXPECT_EQ(display_width("θ̈₂"), 2u);  // θ + U+0308 + ₂
  EXPECT_EQ(display_width("ẍ₁"), 2u);  // precomposed U+1E8D
  EXPECT_EQ(display_width("‖A q - B‖₂"), 10u);
  EXPECT_EQ(display_width(std::string("a") + kBreakMark + " + b"), 5u);
  EXPECT_EQ(pad_right("θ̇₁", 4), "θ̇₁  ");
  EXPECT_EQ(pad_left("θ̇₁", 4), "  θ̇₁");
}

TEST(TextLayout, WrapPrefersTheOutermostSum) {
  const std::string m(1, kBreakMark);
  const std::string text = "a (bbbbbbbbbb" + m + " + cccccccccc)" + m + " + dddddddddd" + m + " + e";
  // Everything fits: one line, marks removed.
  EXPECT_EQ(wrap("x = ", text, "      ", 80),
            std::vector<std::string>{"x = a (bbbbbbbbbb + cccccccccc) + dddddddddd + e"});
  // 30 columns: the inner break would fit more, but the outer one is taken.
  const auto lines = wrap("x = ", text, "      ", 30);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "x = a (bbbbbbbbbb");
  EXPECT_EQ(lines[1], "      + cccccccccc)");
  EXPECT_EQ(lines[2], "      + dddddddddd + e");
  for (const auto& line : wrap("x = ", text, "  ", 12)) EXPECT_LE(display_width(line), 18u) << line;
}

TEST(TextLayout, WrapWordsFillsLines) {
  const auto lines = wrap_words("one two three four five six", "  ", 14);
  EXPECT_EQ(lines, (std::vector<std::string>{"  one two", "  three four", "  five six"}));
}

TEST(TextLayout, TablesAlignDecimalPointsAndSplitIntoBlocks) {
  Table table;
  table.headers = {"a", "b", "B"};
  table.row_labels = {"(1)", "(2)"};
  table.cells = {{"-9.80725", "x y", "0.5"}, {"0.017575", "z", "-12"}};
  table.separator_before = 2;
  const auto lines = layout_table(table, "  ", 80);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "        a         b    |   B");
  EXPECT_EQ(lines[1], "  (1)  -9.80725   x y  |    0.5");
  EXPECT_EQ(lines[2], "  (2)   0.017575  z    |  -12");

  // Too narrow for all three columns: blocks of columns, row labels repeated.
  const auto blocks = layout_table(table, "  ", 20);
  ASSERT_EQ(blocks.size(), 7u);
  EXPECT_EQ(blocks[3], "");
  EXPECT_EQ(blocks[0], "        a");
  EXPECT_EQ(blocks[4], "       b    |   B");
  EXPECT_EQ(blocks[6], "  (2)  z    |  -12");
  for (const auto& line : blocks) EXPECT_LE(display_width(line), 20u) << line;
}

}  // namespace
}  // namespace linkage
