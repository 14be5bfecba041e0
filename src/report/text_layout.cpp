#include "report/text_layout.hpp"

#include <algorithm>

#include "report/notation.hpp"

namespace linkage {

namespace {

bool is_combining(char32_t c) {
  return (c >= 0x300 && c <= 0x36F) || (c >= 0x1AB0 && c <= 0x1AFF) || (c >= 0x1DC0 && c <= 0x1DFF) ||
         (c >= 0x20D0 && c <= 0x20FF) || (c >= 0xFE20 && c <= 0xFE2F);
}

std::string rstrip(std::string line) {
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

// A number, optionally marked with a trailing '*' (see the agreement table).
bool is_number(std::string_view cell) {
  if (cell.ends_with('*')) cell.remove_suffix(1);
  if (cell.empty()) return false;
  bool digit = false;
  for (char c : cell) {
    if (c >= '0' && c <= '9')
      digit = true;
    else if (c != '.' && c != 'e' && c != '-' && c != '+')
      return false;
  }
  return digit;
}

// A number split at its decimal point: "-9.80725" -> "-9", ".80725"; "1e-05" -> "1", "e-05".
std::pair<std::string_view, std::string_view> split_number(std::string_view cell) {
  std::size_t at = cell.find('.');
  if (at == std::string_view::npos) at = cell.find('e');
  if (at == std::string_view::npos) at = cell.size();
  return {cell.substr(0, at), cell.substr(at)};
}

// A column formatted to one width: every cell and the header.
struct Column {
  std::string header;
  std::vector<std::string> cells;
  std::size_t width = 0;
};

Column format_column(const Table& table, std::size_t c) {
  Column col;
  const std::size_t header_width = display_width(table.headers[c]);
  const bool numeric = std::all_of(table.cells.begin(), table.cells.end(),
                                   [&](const std::vector<std::string>& row) { return is_number(row[c]); });
  if (numeric) {
    std::size_t int_width = 0, frac_width = 0;
    for (const auto& row : table.cells) {
      const auto [integer, fraction] = split_number(row[c]);
      int_width = std::max(int_width, integer.size());
      frac_width = std::max(frac_width, fraction.size());
    }
    for (const auto& row : table.cells) {
      const auto [integer, fraction] = split_number(row[c]);
      col.cells.push_back(pad_left(integer, int_width) + pad_right(fraction, frac_width));
    }
    // The header starts over the first digit: one column in when some cell is negative.
    const bool signs = std::any_of(table.cells.begin(), table.cells.end(),
                                   [&](const std::vector<std::string>& row) { return row[c].starts_with('-'); });
    col.header = std::string(signs ? 1 : 0, ' ') + table.headers[c];
    col.width = std::max(int_width + frac_width, display_width(col.header));
  } else {
    col.width = header_width;
    for (const auto& row : table.cells) col.width = std::max(col.width, display_width(strip_marks(row[c])));
    for (const auto& row : table.cells) col.cells.push_back(row[c]);  // marks kept for wrapping
    col.header = table.headers[c];
  }
  return col;
}

}  // namespace

Utf8Char decode_utf8(std::string_view text, std::size_t i) {
  const auto lead = static_cast<unsigned char>(text[i]);
  const std::size_t more = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
  char32_t cp = lead & (more == 1 ? 0x1Fu : more == 2 ? 0x0Fu : 0x07u);
  for (std::size_t k = 1; k <= more; ++k) {
    const auto c = i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u;
    if ((c & 0xC0u) != 0x80u) return {lead, 1};
    cp = (cp << 6) | (c & 0x3Fu);
  }
  return more == 0 ? Utf8Char{lead, 1} : Utf8Char{cp, more + 1};
}

std::string encode_utf8(char32_t cp) {
  if (cp < 0x80) return std::string(1, static_cast<char>(cp));
  const std::size_t more = cp < 0x800 ? 1 : cp < 0x10000 ? 2 : 3;
  std::string out(1, static_cast<char>(((0xFF00u >> (more + 1)) & 0xFFu) | (cp >> (6 * more))));
  for (std::size_t k = more; k-- > 0;) out += static_cast<char>(0x80u | ((cp >> (6 * k)) & 0x3Fu));
  return out;
}

std::size_t display_width(std::string_view text) {
  std::size_t width = 0;
  for (std::size_t i = 0; i < text.size();) {
    const Utf8Char c = decode_utf8(text, i);
    if (c.cp != static_cast<char32_t>(kBreakMark) && !is_combining(c.cp)) ++width;
    i += c.size;
  }
  return width;
}

std::string pad_right(std::string_view text, std::size_t width) {
  const std::size_t w = display_width(text);
  return std::string(text) + std::string(w < width ? width - w : 0, ' ');
}

std::string pad_left(std::string_view text, std::size_t width) {
  const std::size_t w = display_width(text);
  return std::string(w < width ? width - w : 0, ' ') + std::string(text);
}

std::string strip_marks(std::string_view text) {
  std::string out;
  for (char c : text)
    if (c != kBreakMark) out += c;
  return out;
}

std::vector<std::string> wrap(std::string_view first, std::string_view text, std::string_view indent,
                              std::size_t width) {
  // Pieces between marks, each with the parenthesis depth at its mark.
  struct Piece {
    std::string text;
    int depth = 0;
  };
  std::vector<Piece> pieces(1);
  int depth = 0;
  for (char c : text) {
    if (c == kBreakMark) {
      pieces.push_back({"", depth});
      continue;
    }
    if (c == '(') ++depth;
    if (c == ')') --depth;
    pieces.back().text += c;
  }

  // Each line takes everything left if it fits; otherwise it breaks before the piece of
  // lowest depth (the outermost sum) among those that keep it within `width`, the last
  // such piece on ties.
  std::vector<std::string> lines;
  std::string line = std::string(first) + pieces.front().text;
  std::size_t next = 1;
  while (next < pieces.size()) {
    std::size_t used = display_width(line), fit = next;
    while (fit < pieces.size() && used + display_width(pieces[fit].text) <= width)
      used += display_width(pieces[fit++].text);
    std::size_t take = fit;  // pieces [next, take) join this line
    if (fit < pieces.size())
      for (std::size_t k = fit; k > next; --k)
        if (pieces[k].depth < pieces[take].depth) take = k;
    for (; next < take; ++next) line += pieces[next].text;
    if (next == pieces.size()) break;
    lines.push_back(rstrip(line));
    std::string_view piece = pieces[next].text;
    while (piece.starts_with(' ')) piece.remove_prefix(1);
    line = std::string(indent) + std::string(piece);
    ++next;
  }
  lines.push_back(rstrip(line));
  return lines;
}

std::vector<std::string> wrap_words(std::string_view text, std::string_view indent, std::size_t width) {
  std::vector<std::string> lines;
  std::string line(indent);
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    const bool empty = line.size() == indent.size();
    if (!empty && display_width(line) + 1 + display_width(word) > width) {
      lines.push_back(line);
      line = std::string(indent);
    }
    if (line.size() != indent.size()) line += ' ';
    line += word;
    start = end + 1;
  }
  if (line.size() != indent.size()) lines.push_back(line);
  return lines;
}

std::vector<std::string> layout_table(const Table& table, std::string_view indent, std::size_t width) {
  constexpr std::size_t gap = 2;
  constexpr std::string_view separator = "  |  ";
  std::vector<Column> columns;
  for (std::size_t c = 0; c < table.headers.size(); ++c) columns.push_back(format_column(table, c));
  std::size_t label_width = 0;
  for (const auto& label : table.row_labels) label_width = std::max(label_width, display_width(label));

  std::vector<std::string> lines;
  const std::size_t base = display_width(indent) + label_width;
  for (std::size_t begin = 0; begin < columns.size();) {
    // As many columns as fit, and always at least one.
    std::size_t end = begin, used = base;
    while (end < columns.size()) {
      const std::size_t lead = (end == table.separator_before && end != begin && end != 0) ? separator.size() : gap;
      if (end > begin && used + lead + columns[end].width > width) break;
      used += lead + columns[end].width;
      ++end;
    }
    if (!lines.empty()) lines.emplace_back();
    auto row_line = [&](std::string_view label, auto&& cell) {
      std::string line = std::string(indent) + pad_right(label, label_width);
      for (std::size_t c = begin; c < end; ++c) {
        const bool sep = c == table.separator_before && c != begin && c != 0;
        line += sep ? std::string(separator) : std::string(gap, ' ');
        line += pad_right(strip_marks(cell(c)), columns[c].width);
      }
      return rstrip(line);
    };
    lines.push_back(row_line("", [&](std::size_t c) -> const std::string& { return columns[c].header; }));
    // A column alone that is still too wide wraps its cells at their break marks.
    const bool wrapped = end == begin + 1 && used > width;
    const std::string continuation = std::string(base + gap + 4, ' ');
    for (std::size_t r = 0; r < table.cells.size(); ++r) {
      const std::string label = r < table.row_labels.size() ? table.row_labels[r] : std::string();
      if (wrapped) {
        const std::string first = std::string(indent) + pad_right(label, label_width) + std::string(gap, ' ');
        for (std::string& l : wrap(first, columns[begin].cells[r], continuation, width)) lines.push_back(std::move(l));
        continue;
      }
      lines.push_back(row_line(label, [&](std::size_t c) -> const std::string& { return columns[c].cells[r]; }));
    }
    begin = end;
  }
  return lines;
}

}  // namespace linkage
