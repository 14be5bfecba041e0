#include "lesson/markdown.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "lesson/latex_text.hpp"
#include "report/latex_math.hpp"
#include "report/text_layout.hpp"
#include "report/unicode_tex.hpp"

namespace linkage::lesson {
namespace {

// --- blocks ------------------------------------------------------------------------

struct Block {
  enum class Kind { paragraph, heading, item, quote, code, math, table } kind = Kind::paragraph;
  std::string text;    // joined lines (paragraph, heading, item, quote) or raw lines (code, math, table)
  int level = 0;       // heading level, or list nesting (leading spaces / 2)
  std::string marker;  // "-" or "3." for items
  // Where the text came from: (offset in text, offset in the Markdown) at the start of
  // each appended piece, so an error can point into what the author wrote.
  std::vector<std::pair<std::size_t, std::size_t>> from;
};

// "line 3, column 17" of the character `at` points to in `markdown`.
std::string source_position(std::string_view markdown, const char* at) {
  const auto end =
      static_cast<std::size_t>(std::clamp(at, markdown.data(), markdown.data() + markdown.size()) - markdown.data());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (markdown[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(markdown[i]) & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Appends `separator` and `piece` (a view into `source`) to the block's text.
void append(Block& b, std::string_view source, std::string_view separator, std::string_view piece) {
  b.text += separator;
  b.from.emplace_back(b.text.size(), static_cast<std::size_t>(piece.data() - source.data()));
  b.text += piece;
}

Block block(Block::Kind kind, std::string_view source, std::string_view text, int level = 0, std::string marker = "") {
  Block b{kind, "", level, std::move(marker), {}};
  append(b, source, "", text);
  return b;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::size_t leading_spaces(std::string_view line) {
  std::size_t n = 0;
  while (n < line.size() && line[n] == ' ') ++n;
  return n;
}

// "- item", "* item", "12. item": the marker and where the text starts.
bool list_marker(std::string_view line, std::string& marker, std::size_t& text_start) {
  const std::size_t indent = leading_spaces(line);
  std::string_view rest = line.substr(indent);
  if (rest.size() >= 2 && (rest[0] == '-' || rest[0] == '*' || rest[0] == '+') && rest[1] == ' ') {
    marker = "-";
    text_start = indent + 2;
    return true;
  }
  std::size_t digits = 0;
  while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
  if (digits > 0 && digits <= 9 && digits + 1 < rest.size() && rest[digits] == '.' && rest[digits + 1] == ' ') {
    marker = std::string(rest.substr(0, digits + 1));
    text_start = indent + digits + 2;
    return true;
  }
  return false;
}

// The cells of a pipe-table row ("| a | b |"), trimmed; empty for the |---| rule.
std::vector<std::string_view> table_cells(std::string_view line) {
  std::string_view t = trim(line);
  if (t.starts_with('|')) t.remove_prefix(1);
  if (t.ends_with('|')) t.remove_suffix(1);
  if (t.find_first_not_of("-:| ") == std::string_view::npos) return {};
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  for (std::size_t bar = t.find('|');; bar = t.find('|', start)) {
    cells.push_back(trim(t.substr(start, bar == std::string_view::npos ? bar : bar - start)));
    if (bar == std::string_view::npos) break;
    start = bar + 1;
  }
  return cells;
}

std::vector<Block> parse_blocks(std::string_view markdown) {
  std::vector<Block> blocks;
  const std::vector<std::string_view> lines = split_lines(markdown);
  Block* open = nullptr;  // a paragraph, item or quote still taking lines
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    const std::string_view t = trim(line);
    if (t.empty()) {
      open = nullptr;
      continue;
    }
    if (t.starts_with("```") || t.starts_with("$$")) {
      const bool code = t.starts_with("```");
      Block b{code ? Block::Kind::code : Block::Kind::math, "", 0, "", {}};
      const std::string_view fence = code ? "```" : "$$";
      // A one-line math block: $$ ... $$
      if (!code && t.size() > 4 && t.ends_with("$$")) {
        append(b, markdown, "", trim(t.substr(2, t.size() - 4)));
      } else {
        if (!code && t.size() > 2) {
          append(b, markdown, "", trim(t.substr(2)));
          b.text += "\n";
        }
        for (++i; i < lines.size(); ++i) {
          const std::string_view inner = trim(lines[i]);
          if (inner.starts_with(fence) || (!code && inner.ends_with("$$"))) {
            if (!code && inner.size() > 2) {
              append(b, markdown, "", trim(inner.substr(0, inner.size() - 2)));
              b.text += "\n";
            }
            break;
          }
          append(b, markdown, "", lines[i]);
          b.text += "\n";
        }
        while (!b.text.empty() && b.text.back() == '\n') b.text.pop_back();
      }
      blocks.push_back(std::move(b));
      open = nullptr;
      continue;
    }
    if (t.front() == '#') {
      std::size_t level = 0;
      while (level < t.size() && t[level] == '#') ++level;
      blocks.push_back(block(Block::Kind::heading, markdown, trim(t.substr(level)), static_cast<int>(level)));
      open = nullptr;
      continue;
    }
    if (t.front() == '|') {
      if (!blocks.empty() && blocks.back().kind == Block::Kind::table && open == &blocks.back())
        append(blocks.back(), markdown, "\n", t);
      else
        blocks.push_back(block(Block::Kind::table, markdown, t));
      open = &blocks.back();
      continue;
    }
    if (t.front() == '>') {
      const std::string_view content = trim(t.substr(1));
      if (open != nullptr && open->kind == Block::Kind::quote) {
        if (content.empty())
          open->text += "\n";
        else
          append(*open, markdown, open->text.empty() || open->text.back() == '\n' ? "" : " ", content);
      } else {
        blocks.push_back(block(Block::Kind::quote, markdown, content));
        open = &blocks.back();
      }
      continue;
    }
    std::string marker;
    std::size_t text_start = 0;
    // As in CommonMark, a numbered item interrupts a paragraph only when it counts from 1
    // ("240000. The ..." in the middle of a paragraph is a number, not a list).
    const bool continues = open != nullptr && open->kind == Block::Kind::paragraph;
    if (list_marker(line, marker, text_start) && !(continues && marker != "-" && marker != "1.")) {
      // Each level indents the item's lines further: a bound keeps the output in proportion.
      if (leading_spaces(line) / 2 > static_cast<std::size_t>(kMaxNesting))
        throw Error::input(source_position(markdown, line.data()) + ": a list item indented " +
                           std::to_string(leading_spaces(line)) + " spaces is nested more than " +
                           std::to_string(kMaxNesting) + " levels deep (each 2 spaces are a level)");
      blocks.push_back(block(Block::Kind::item, markdown, trim(line.substr(text_start)),
                             static_cast<int>(leading_spaces(line) / 2), marker));
      open = &blocks.back();
      continue;
    }
    if (open != nullptr && open->kind != Block::Kind::table) {
      append(*open, markdown, " ", t);
      continue;
    }
    blocks.push_back(block(Block::Kind::paragraph, markdown, t));
    open = &blocks.back();
  }
  return blocks;
}

// --- inline markup for a terminal ---------------------------------------------------

std::string inline_text(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      ++i;
      continue;
    }
    if (c == '_' && i + 1 < s.size() && s[i + 1] == '_') {
      ++i;
      continue;
    }
    if (c == '`') continue;
    // *emphasis*: drop the stars when they hug a word ("m * D" is multiplication).
    if (c == '*' && i + 1 < s.size() && s[i + 1] != ' ') {
      const std::size_t end = s.find('*', i + 1);
      if (end != std::string_view::npos && s[end - 1] != ' ') {
        out += inline_text(s.substr(i + 1, end - i - 1));
        i = end;
        continue;
      }
    }
    if (c == '$') {  // inline math, as Unicode
      const std::size_t end = s.find('$', i + 1);
      if (end != std::string_view::npos) {
        out += latex_to_unicode(s.substr(i + 1, end - i - 1));
        i = end;
      }
      continue;
    }
    if (c == '!' && i + 1 < s.size() && s[i + 1] == '[') continue;  // an image reads like a link
    if (c == '[') {
      const std::size_t close = s.find("](", i);
      const std::size_t end = close == std::string_view::npos ? close : s.find(')', close);
      if (end != std::string_view::npos) {
        out += inline_text(s.substr(i + 1, close - i - 1)) + " (" + std::string(s.substr(close + 2, end - close - 2)) +
               ")";
        i = end;
        continue;
      }
    }
    out += c;
  }
  return out;
}

void append_lines(std::string& out, const std::vector<std::string>& lines) {
  for (const std::string& l : lines) out += l + "\n";
}

// A pipe table with its columns lined up and a rule under the header.
std::string text_table(std::string_view text) {
  std::vector<std::vector<std::string>> rows;
  for (std::string_view line : split_lines(text)) {
    std::vector<std::string> row;
    for (std::string_view cell : table_cells(line)) row.push_back(inline_text(cell));
    if (!row.empty()) rows.push_back(std::move(row));
  }
  std::vector<std::size_t> widths;
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], display_width(row[c]));
    }
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = " ";
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      line += ' ';
      line += pad_right(rows[r][c], widths[c] + 1);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
    if (r == 0) {
      std::size_t total = 2 * (widths.size() - 1);
      for (std::size_t w : widths) total += w;
      out += "  ";
      out += std::string(total, '-');
      out += '\n';
    }
  }
  return out;
}

// --- inline markup for LaTeX --------------------------------------------------------

// One code point of UTF-8 at s[i]; sets `length`.
char32_t decode(std::string_view s, std::size_t i, std::size_t& length) {
  const auto lead = static_cast<unsigned char>(s[i]);
  length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
  if (i + length > s.size()) {
    length = 1;
    return lead;
  }
  char32_t c = length == 1 ? lead : length == 2 ? (lead & 0x1Fu) : length == 3 ? (lead & 0x0Fu) : (lead & 0x07u);
  for (std::size_t k = 1; k < length; ++k) c = (c << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3Fu);
  return c;
}

// Greek letters, dotted x and y, and operators: report/unicode_tex's one table.
std::string_view greek(char32_t c) { return tex_symbol(c); }

// Subscript (₀..₉) or superscript (⁰ ¹ ² ³ ⁴..⁹) digit, or -1.
int script_digit(char32_t c, bool& superscript) {
  superscript = false;
  if (c >= U'₀' && c <= U'₉') return static_cast<int>(c - U'₀');
  superscript = true;
  if (c == U'⁰') return 0;
  if (c == U'¹') return 1;
  if (c == U'²') return 2;
  if (c == U'³') return 3;
  if (c >= U'⁴' && c <= U'⁹') return static_cast<int>(c - U'⁴') + 4;
  return -1;
}

// A subscript or superscript digit or sign as its ASCII character, or 0.
char script_char(char32_t c, bool& superscript) {
  const int digit = script_digit(c, superscript);
  if (digit >= 0) return static_cast<char>('0' + digit);
  superscript = c == U'⁻' || c == U'⁺';
  if (c == U'⁻' || c == U'₋') return '-';
  if (c == U'⁺' || c == U'₊') return '+';
  return 0;
}

// Converts plain characters (no markup) to text-mode LaTeX.
std::string latex_chars(std::string_view s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t length = 0;
    const char32_t c = decode(s, i, length);
    std::string base;
    if (const std::string_view g = greek(c); !g.empty())
      base = std::string(g);
    else if (c < 0x80 && std::isalpha(static_cast<int>(c)))
      base = std::string(1, static_cast<char>(c));
    // Accents and scripts that follow the base.
    std::size_t j = i + length;
    std::string math = base;
    bool symbol = !base.empty();
    while (symbol && j < s.size()) {
      std::size_t n = 0;
      const char32_t next = decode(s, j, n);
      if (next == 0x307)
        math = "\\dot{" + math + "}";
      else if (next == 0x308)
        math = "\\ddot{" + math + "}";
      else
        break;
      j += n;
    }
    // Scripts, each run in one group (10⁻¹² is 10^{-12}): after a letter, or starting at
    // c itself; a digit's scripts (10²) start after it, with the digit kept as text.
    bool c_superscript = false;
    const bool c_is_script = script_char(c, c_superscript) != 0;
    if (base.empty() && c_is_script) j = i;
    std::string sub, sup;
    while ((!base.empty() || c_is_script) && j < s.size()) {
      std::size_t n = 0;
      bool superscript = false;
      const char script = script_char(decode(s, j, n), superscript);
      if (script == 0) break;
      (superscript ? sup : sub) += script;
      j += n;
    }
    std::string scripts;
    if (!sub.empty()) scripts += "_{" + sub + "}";
    if (!sup.empty()) scripts += "^{" + sup + "}";
    const bool needs_math = !greek(c).empty() || math != base || !scripts.empty();
    if (needs_math) {
      if (base.empty()) base = "{}";  // a script with nothing before it
      out += "$" + (math.empty() ? base : math) + scripts + "$";
      i = j;
      continue;
    }
    if (c < 0x80)
      out += latex_escape(std::string_view(&s[i], 1));
    else
      out += std::string(s.substr(i, length));  // passes through (needs a Unicode engine)
    i += length;
  }
  return out;
}

}  // namespace

namespace {

// Inline spans that wrap their content: the delimiter, the LaTeX around the content, and
// whether the content is itself markup (else it is escaped verbatim, or kept as math).
struct InlineSpan {
  std::string_view delimiter;
  std::string_view before, after;
  enum class Content { math, verbatim, markup } content;
};
constexpr std::array<InlineSpan, 4> kSpans{{
    {"$", "$", "$", InlineSpan::Content::math},
    {"`", "\\texttt{", "}", InlineSpan::Content::verbatim},
    {"**", "\\textbf{", "}", InlineSpan::Content::markup},
    {"*", "\\emph{", "}", InlineSpan::Content::markup},  // only hugging a word: "m * D" is a product
}};

}  // namespace

std::string inline_latex(std::string_view s) {
  std::string out;
  std::size_t plain_start = 0;
  auto take = [&](std::size_t i, std::size_t next, const std::string& latex) {
    out += latex_chars(s.substr(plain_start, i - plain_start));
    out += latex;
    plain_start = next;
  };
  for (std::size_t i = 0; i < s.size();) {
    bool matched = false;
    for (const InlineSpan& span : kSpans) {
      if (s.substr(i, span.delimiter.size()) != span.delimiter) continue;
      const std::size_t from = i + span.delimiter.size();
      const std::size_t end = s.find(span.delimiter, from);
      if (end == std::string_view::npos) break;
      const std::string_view inner = s.substr(from, end - from);
      if (span.delimiter == "*" && (inner.empty() || inner.front() == ' ' || inner.back() == ' ')) break;
      const std::string content = span.content == InlineSpan::Content::math       ? std::string(inner)
                                  : span.content == InlineSpan::Content::verbatim ? latex_escape(inner)
                                                                                  : inline_latex(inner);
      take(i, end + span.delimiter.size(), std::string(span.before) + content + std::string(span.after));
      i = plain_start;
      matched = true;
      break;
    }
    if (matched) continue;
    // [text](url) and ![alt](image) become links.
    if (s[i] == '[' || (s[i] == '!' && i + 1 < s.size() && s[i + 1] == '[')) {
      const std::size_t open = s[i] == '!' ? i + 1 : i;
      const std::size_t mid = s.find("](", open);
      const std::size_t end = mid == std::string_view::npos ? mid : s.find(')', mid);
      if (end != std::string_view::npos) {
        take(i, end + 1,
             "\\href{" + std::string(s.substr(mid + 2, end - mid - 2)) + "}{" +
                 inline_latex(s.substr(open + 1, mid - open - 1)) + "}");
        i = plain_start;
        continue;
      }
    }
    ++i;
  }
  out += latex_chars(s.substr(plain_start));
  return out;
}

namespace {

// Where in `markdown` the character `at` of a block's text came from.
const char* source_of(std::string_view markdown, const std::vector<Block>& blocks, const char* at) {
  for (const Block& b : blocks) {
    const char* text = b.text.data();
    if (std::less<const char*>()(at, text) || std::less<const char*>()(text + b.text.size(), at)) continue;
    const auto offset = static_cast<std::size_t>(at - text);
    std::size_t source = 0;
    for (const auto& [in_text, in_source] : b.from)
      if (in_text <= offset) source = in_source + (offset - in_text);
    return markdown.data() + std::min(source, markdown.size());
  }
  return markdown.data();
}

std::string blocks_to_text(const std::vector<Block>& blocks, std::size_t width) {
  std::string out;
  bool first = true;
  Block::Kind previous = Block::Kind::paragraph;
  for (const Block& b : blocks) {
    // Items of one list stay together; everything else is separated by a blank line.
    if (!first && !(b.kind == Block::Kind::item && previous == Block::Kind::item)) out += "\n";
    first = false;
    previous = b.kind;
    switch (b.kind) {
      case Block::Kind::paragraph:
        append_lines(out, wrap_words(inline_text(b.text), "", width));
        break;
      case Block::Kind::heading: {
        const std::string title = inline_text(b.text);
        out += title + "\n" + std::string(display_width(title), b.level <= 1 ? '=' : '-') + "\n";
        break;
      }
      case Block::Kind::item: {
        const std::string indent(static_cast<std::size_t>(2 * b.level) + b.marker.size() + 3, ' ');
        std::vector<std::string> lines = wrap_words(inline_text(b.text), indent, width);
        if (!lines.empty())
          lines[0] = std::string(static_cast<std::size_t>(2 * b.level) + 2, ' ') + b.marker + " " +
                     lines[0].substr(indent.size());
        append_lines(out, lines);
        break;
      }
      case Block::Kind::quote: {
        for (std::string_view paragraph : split_lines(b.text))
          append_lines(out, wrap_words(inline_text(paragraph), "  | ", width));
        break;
      }
      case Block::Kind::code:
        for (std::string_view line : split_lines(b.text)) out += "    " + std::string(line) + "\n";
        break;
      case Block::Kind::math: {
        const std::string unicode = latex_to_unicode(b.text);
        // Continuation lines of an aligned equation ("= ...") line up under the first "=".
        const std::size_t equals = unicode.find(" = ");
        const std::size_t first_end = unicode.find('\n');
        const std::size_t align = equals != std::string::npos && equals < first_end
                                      ? display_width(std::string_view(unicode).substr(0, equals + 1))
                                      : 0;
        for (std::string_view line : split_lines(unicode)) {
          out += "    ";
          if (line.starts_with("= ")) out += std::string(align, ' ');
          out += std::string(line);
          out += "\n";
        }
        break;
      }
      case Block::Kind::table:
        out += text_table(b.text);
        break;
    }
  }
  return out;
}

}  // namespace

std::string markdown_to_text(std::string_view markdown, std::size_t width) {
  const std::vector<Block> blocks = parse_blocks(markdown);
  try {
    return blocks_to_text(blocks, width);
  } catch (const LatexNestingError& e) {
    throw Error::input(source_position(markdown, source_of(markdown, blocks, e.at())) + ": " + e.what());
  }
}

std::string markdown_to_latex(std::string_view markdown) {
  std::string out;
  const std::vector<Block> blocks = parse_blocks(markdown);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const Block& b = blocks[k];
    switch (b.kind) {
      case Block::Kind::paragraph:
        out += inline_latex(b.text) + "\n\n";
        break;
      case Block::Kind::heading:
        out += std::string(b.level <= 1 ? "\\subsection*{" : "\\subsubsection*{") + inline_latex(b.text) + "}\n\n";
        break;
      case Block::Kind::item: {
        const bool numbered = b.marker != "-";
        const char* env = numbered ? "enumerate" : "itemize";
        out += std::string("\\begin{") + env + "}\n";
        for (; k < blocks.size() && blocks[k].kind == Block::Kind::item && (blocks[k].marker != "-") == numbered; ++k)
          out += "  \\item " + inline_latex(blocks[k].text) + "\n";
        --k;
        out += std::string("\\end{") + env + "}\n\n";
        break;
      }
      case Block::Kind::quote: {
        out += "\\begin{quote}\n";
        for (std::string_view paragraph : split_lines(b.text)) out += inline_latex(paragraph) + "\n\n";
        out += "\\end{quote}\n\n";
        break;
      }
      case Block::Kind::code:
        out += "\\begin{verbatim}\n" + b.text + "\n\\end{verbatim}\n\n";
        break;
      case Block::Kind::math:
        out += "\\[\n" + b.text + "\n\\]\n\n";
        break;
      case Block::Kind::table: {
        std::vector<std::vector<std::string>> rows;
        for (std::string_view line : split_lines(b.text)) {
          std::vector<std::string> cells;
          for (std::string_view cell : table_cells(line)) cells.push_back(inline_latex(cell));
          if (!cells.empty()) rows.push_back(std::move(cells));
        }
        if (rows.empty()) break;
        out += "\\begin{tabular}{" + std::string(rows.front().size(), 'l') + "}\n";
        for (std::size_t r = 0; r < rows.size(); ++r) {
          for (std::size_t c = 0; c < rows[r].size(); ++c) out += (c > 0 ? " & " : "  ") + rows[r][c];
          out += " \\\\\n";
          if (r == 0) out += "  \\hline\n";
        }
        out += "\\end{tabular}\n\n";
        break;
      }
    }
  }
  return out;
}

void check_markdown(std::string_view markdown, const std::string& origin) {
  try {
    (void)markdown_to_text(markdown, 80);  // markdown_to_latex has no recursion to bound
  } catch (const Error& e) {
    throw Error(e.code(), origin + ": " + e.what());
  }
}

}  // namespace linkage::lesson
