#pragma once
// Laying text out for a terminal of a given width: display width of UTF-8 (combining
// marks such as the dots of θ̇ take no column), padding, wrapping a formula at its
// break marks, and tables that split into column blocks when too wide.
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

/// One UTF-8 character of `text` at byte `i`: its code point and length in bytes; a
/// byte that starts no whole sequence reads as itself, one byte long.
struct Utf8Char {
  char32_t cp = 0;
  std::size_t size = 1;
};
[[nodiscard]] Utf8Char decode_utf8(std::string_view text, std::size_t i);

/// The UTF-8 bytes of a code point.
[[nodiscard]] std::string encode_utf8(char32_t cp);

/// Columns `text` takes on a terminal: one per code point, none for combining marks
/// (U+0300-036F, U+1AB0-1AFF, U+1DC0-1DFF, U+20D0-20FF, U+FE20-FE2F).
[[nodiscard]] std::size_t display_width(std::string_view text);

/// `text` padded with spaces to `width` display columns, on the right or the left.
[[nodiscard]] std::string pad_right(std::string_view text, std::size_t width);
[[nodiscard]] std::string pad_left(std::string_view text, std::size_t width);

/// Lines of at most `width` columns: `first` + `text`, wrapped at kBreakMark places
/// onto lines starting with `indent`. A piece longer than a line stays whole. Marks are
/// removed; without marks this is just `first` + `text`.
[[nodiscard]] std::vector<std::string> wrap(std::string_view first, std::string_view text, std::string_view indent,
                                            std::size_t width);

/// Plain prose wrapped at spaces into lines of at most `width` columns, each starting
/// with `indent`.
[[nodiscard]] std::vector<std::string> wrap_words(std::string_view text, std::string_view indent, std::size_t width);

/// `text` without kBreakMark characters.
[[nodiscard]] std::string strip_marks(std::string_view text);

/// A table with labelled rows and headed columns. Columns of numbers (digits, '.',
/// 'e', signs) line up at the decimal point; other columns align left.
struct Table {
  std::vector<std::string> headers;             // one per column
  std::vector<std::string> row_labels;          // one per row, may be empty strings
  std::vector<std::vector<std::string>> cells;  // rows x columns
  std::size_t separator_before = 0;             // draw " | " before this column (0: none)
};

/// The table's lines, each at most `width` columns when possible, indented by `indent`:
/// when all columns do not fit, they split into blocks printed one below the other,
/// each with the row labels again. Text cells may carry kBreakMark: a column that alone
/// is too wide wraps its cells there.
[[nodiscard]] std::vector<std::string> layout_table(const Table& table, std::string_view indent, std::size_t width);

}  // namespace linkage
