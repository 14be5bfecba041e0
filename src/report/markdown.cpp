#include "report/markdown.hpp"

#include <md4c.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <exception>
#include <functional>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/markup_escape.hpp"
#include "report/latex_math.hpp"
#include "report/latex_mathml.hpp"
#include "report/notation.hpp"
#include "report/text_layout.hpp"
#include "report/unicode_tex.hpp"

namespace linkage {

std::string text_position(std::string_view markdown, const char* at) {
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

namespace {

// The characters an entity (&amp;, &#233;, &#x3B8;) stands for; the few named ones
// lessons would write, else the entity as written.
std::string entity(std::string_view e) {
  if (e.starts_with("&#")) {
    const bool hex = e.size() > 2 && (e[2] == 'x' || e[2] == 'X');
    const std::string digits(e.substr(hex ? 3 : 2, e.size() - (hex ? 4 : 3)));
    const unsigned long c = std::strtoul(digits.c_str(), nullptr, hex ? 16 : 10);
    return c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF) ? "\uFFFD" : encode_utf8(static_cast<char32_t>(c));
  }
  for (const auto& [name, text] : {std::pair<std::string_view, std::string_view>{"&amp;", "&"},
                                   {"&lt;", "<"},
                                   {"&gt;", ">"},
                                   {"&quot;", "\""},
                                   {"&nbsp;", " "}})
    if (e == name) return std::string(text);
  return std::string(e);
}

std::string trim_spaces(std::string_view s) {
  const std::size_t start = s.find_first_not_of(" \n");
  return start == std::string_view::npos ? "" : std::string(s.substr(start, s.find_last_not_of(" \n") - start + 1));
}

// Math text as LaTeX reads it: md4c's line breaks (its own " ") become new lines in
// display math, and each piece remembers where it came from for error messages.
struct Math {
  std::string text;
  std::vector<std::pair<std::size_t, const char*>> from;  // (offset in text, source)
  bool display = false;
  const char* begin = nullptr;  // the Markdown's start

  void add(std::string_view piece, bool source) {
    if (source && display && text.ends_with('\n')) {  // md4c drops a line's indentation: keep it
      const char* indent = piece.data();
      while (indent > begin && (indent[-1] == ' ' || indent[-1] == '\t')) --indent;
      piece = std::string_view(indent, static_cast<std::size_t>(piece.data() + piece.size() - indent));
    }
    if (source) from.emplace_back(text.size(), piece.data());
    text += !source && display ? std::string_view("\n") : piece;
  }
  [[nodiscard]] std::string trimmed() const { return trim_spaces(text); }
  // Where the character `at` of `converted` (a copy of trimmed()) came from.
  [[nodiscard]] const char* source_of(const std::string& converted, const char* at) const {
    const auto offset = static_cast<std::size_t>(at - converted.data()) + text.find_first_not_of(" \n");
    const char* source = nullptr;
    for (const auto& [in_text, in_source] : from)
      if (in_text <= offset) source = in_source + (offset - in_text);
    return source;
  }
};

// A table column's alignment as LaTeX writes it: l, c or r.
char alignment(void* td_detail) {
  const MD_ALIGN a = static_cast<MD_BLOCK_TD_DETAIL*>(td_detail)->align;
  return a == MD_ALIGN_CENTER ? 'c' : a == MD_ALIGN_RIGHT ? 'r' : 'l';
}

// A table's cells as both renderers collect them: rows of cells and one alignment
// letter per column, from the header row.
struct TableCells {
  std::vector<std::vector<std::string>> rows;
  std::string align;

  // Starts a table, a row or a header cell; other blocks are not the table's.
  void start(MD_BLOCKTYPE type, void* detail) {
    if (type == MD_BLOCK_TABLE) {
      rows.clear();
      align.clear();
    } else if (type == MD_BLOCK_TR) {
      rows.emplace_back();
    } else if (type == MD_BLOCK_TH) {
      align += alignment(detail);
    }
  }
};

// --- md4c's events, bounded -----------------------------------------------------------

// A renderer of md4c's events and the state both keep. md4c nests as deep as the text
// does, so parse() forwards only kMaxNesting levels of containers (quotes, list items)
// and of spans, and refuses the text at the first character past the bound.
class Renderer {
 public:
  explicit Renderer(std::string_view markdown) : markdown_(markdown) {}
  virtual ~Renderer() = default;
  virtual void enter_block(MD_BLOCKTYPE type, void* detail) = 0;
  virtual void leave_block(MD_BLOCKTYPE type) = 0;
  virtual void enter_span(MD_SPANTYPE type, void* detail) = 0;
  virtual void leave_span(MD_SPANTYPE type) = 0;
  // `source` is true when `text` points into the Markdown (md4c hands its own strings
  // for line breaks inside code and math, and for NUL characters).
  virtual void text(MD_TEXTTYPE type, std::string_view text, bool source) = 0;
  [[nodiscard]] std::string take() { return std::move(out_); }

 protected:
  static std::string url(MD_SPANTYPE type, void* detail) {
    const MD_ATTRIBUTE& a = type == MD_SPAN_A ? static_cast<MD_SPAN_A_DETAIL*>(detail)->href
                                              : static_cast<MD_SPAN_IMG_DETAIL*>(detail)->src;
    return {a.text, a.size};
  }
  void start_math(MD_SPANTYPE type) { math_ = Math{"", {}, type == MD_SPAN_LATEXMATH_DISPLAY, markdown_.data()}; }
  // The math span just read, converted by `convert`; math nested too deep is refused
  // naming where in the Markdown.
  template <class Convert>
  std::string converted_math(const Convert& convert) const {
    const std::string latex = math_.trimmed();
    try {
      return convert(latex);
    } catch (const LatexNestingError& e) {
      const char* at = math_.source_of(latex, e.at());
      throw Error::input((at != nullptr ? text_position(markdown_, at) : "line 1, column 1") + ": " + e.what());
    }
  }

  std::string_view markdown_;
  std::string out_, inline_, code_;
  TableCells table_;
  Math math_;
};

bool in_source(std::string_view markdown, const char* at) {
  return !std::less<const char*>()(at, markdown.data()) &&
         std::less<const char*>()(at, markdown.data() + markdown.size());
}

// A level of nesting: a quote, or a list item (its list is the same level).
bool is_container(MD_BLOCKTYPE type) { return type == MD_BLOCK_QUOTE || type == MD_BLOCK_LI; }

struct Parse {
  std::string_view markdown;
  Renderer& renderer;
  int containers = 0, spans = 0;  // open levels, counted past the bound too
  std::string too_deep;           // what is nested too deep, until a character says where
  std::exception_ptr error;

  // Runs `f` unless the text is refused already; md4c stops when this returns non-zero.
  int call(const std::function<void()>& f) {
    if (error) return 1;
    try {
      f();
    } catch (...) {  // never through md4c's C frames
      error = std::current_exception();
      return 1;
    }
    return 0;
  }
  [[nodiscard]] bool forwarding() const { return containers <= kMaxNesting && spans <= kMaxNesting; }
};

// Counts a level in or out; the first level past the bound names what is too deep.
void count(Parse& p, int& level, int delta, const char* what) {
  level += delta;
  if (delta > 0 && level == kMaxNesting + 1 && p.too_deep.empty()) p.too_deep = what;
}

Error too_deep(std::string_view markdown, const char* at, const std::string& what) {
  return Error::input(concat(
      {text_position(markdown, at), ": ", what, " nested more than ", std::to_string(kMaxNesting), " levels deep"}));
}

void parse(std::string_view markdown, Renderer& renderer) {
  Parse state{markdown, renderer, 0, 0, {}, {}};
  MD_PARSER parser{};
  parser.flags = MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH | MD_FLAG_LATEXMATHSPANS | MD_FLAG_NOHTML;
  parser.enter_block = [](MD_BLOCKTYPE type, void* detail, void* data) {
    auto& p = *static_cast<Parse*>(data);
    if (is_container(type)) count(p, p.containers, 1, "lists and quotes are");
    return p.forwarding() ? p.call([&] { p.renderer.enter_block(type, detail); }) : 0;
  };
  parser.leave_block = [](MD_BLOCKTYPE type, void*, void* data) {
    auto& p = *static_cast<Parse*>(data);
    const int result = p.forwarding() ? p.call([&] { p.renderer.leave_block(type); }) : 0;
    if (is_container(type)) count(p, p.containers, -1, "");
    return result;
  };
  parser.enter_span = [](MD_SPANTYPE type, void* detail, void* data) {
    auto& p = *static_cast<Parse*>(data);
    count(p, p.spans, 1, "emphasis, links and math spans are");
    return p.forwarding() ? p.call([&] { p.renderer.enter_span(type, detail); }) : 0;
  };
  parser.leave_span = [](MD_SPANTYPE type, void*, void* data) {
    auto& p = *static_cast<Parse*>(data);
    const int result = p.forwarding() ? p.call([&] { p.renderer.leave_span(type); }) : 0;
    count(p, p.spans, -1, "");
    return result;
  };
  parser.text = [](MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* data) {
    auto& p = *static_cast<Parse*>(data);
    const bool source = in_source(p.markdown, text);
    if (!p.too_deep.empty() && source) {
      p.error = std::make_exception_ptr(too_deep(p.markdown, text, p.too_deep));
      return 1;
    }
    return p.forwarding() ? p.call([&] { p.renderer.text(type, std::string_view(text, size), source); }) : 0;
  };
  const int result = md_parse(markdown.data(), static_cast<MD_SIZE>(markdown.size()), &parser, &state);
  if (state.error) std::rethrow_exception(state.error);
  if (!state.too_deep.empty())  // nothing written past the bound: say where the text ends
    throw too_deep(markdown, markdown.data() + markdown.size(), state.too_deep);
  if (result != 0) throw Error::failure("the Markdown parser md4c failed (out of memory?)");
}

// --- the terminal -----------------------------------------------------------------

// A pipe table with its columns lined up (`align`: 'r' for right) and a rule under
// the header.
std::vector<std::string> text_table(const std::vector<std::vector<std::string>>& rows, const std::string& align) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], display_width(row[c]));
    }
  std::vector<std::string> lines;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = " ";
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      line += c < align.size() && align[c] == 'r' ? concat({" ", pad_left(rows[r][c], widths[c]), " "})
                                                  : concat({" ", pad_right(rows[r][c], widths[c] + 1)});
    while (!line.empty() && line.back() == ' ') line.pop_back();
    lines.push_back(line);
    if (r == 0) {
      std::size_t total = 2 * (widths.size() - 1);
      for (std::size_t w : widths) total += w;
      lines.push_back(concat({"  ", std::string(total, '-')}));
    }
  }
  return lines;
}

class TextRenderer final : public Renderer {
 public:
  TextRenderer(std::string_view markdown, std::size_t width) : Renderer(markdown), width_(width) {}

  void enter_block(MD_BLOCKTYPE type, void* detail) override {
    if (type != MD_BLOCK_LI && type != MD_BLOCK_DOC) flush_paragraph();  // a tight item's text before its sublist
    switch (type) {
      case MD_BLOCK_CODE:
        code_block_ = true;
        break;
      case MD_BLOCK_P:
        paragraph_ = true;
        break;
      case MD_BLOCK_QUOTE:  // "  | " at the margin, "| " inside another container
        containers_.push_back({containers_.empty() ? "  | " : "| ", false});
        break;
      case MD_BLOCK_UL:
        lists_.push_back(0);
        break;
      case MD_BLOCK_OL:
        lists_.push_back(static_cast<int>(static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start));
        ordered_.push_back(static_cast<MD_BLOCK_OL_DETAIL*>(detail)->mark_delimiter);
        break;
      case MD_BLOCK_LI: {
        // The marker: "-" or the item's number; an outermost item is indented by two.
        std::string marker = lists_.back() == 0 ? "-" : std::to_string(lists_.back()++) + ordered_.back();
        const bool nested = std::any_of(containers_.begin(), containers_.end(), [](const auto& c) { return c.item; });
        containers_.push_back({(nested ? "" : "  ") + marker + " ", true});
        break;
      }
      case MD_BLOCK_H:
        heading_ = static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level);
        break;
      case MD_BLOCK_DOC:
      case MD_BLOCK_HR:
      case MD_BLOCK_HTML:
      case MD_BLOCK_TABLE:
      case MD_BLOCK_THEAD:
      case MD_BLOCK_TBODY:
      case MD_BLOCK_TR:
      case MD_BLOCK_TH:
      case MD_BLOCK_TD:
        table_.start(type, detail);
        break;
    }
  }

  void leave_block(MD_BLOCKTYPE type) override {
    switch (type) {
      case MD_BLOCK_QUOTE:
      case MD_BLOCK_LI:
        flush_paragraph();  // a tight item's text
        containers_.pop_back();
        break;
      case MD_BLOCK_OL:
        ordered_.pop_back();
        [[fallthrough]];
      case MD_BLOCK_UL:
        lists_.pop_back();
        break;
      case MD_BLOCK_P:
        flush_paragraph();
        paragraph_ = false;
        break;
      case MD_BLOCK_H: {
        const std::string title = trim_spaces(inline_);
        inline_.clear();
        emit({title, std::string(display_width(title), heading_ <= 1 ? '=' : '-')});
        break;
      }
      case MD_BLOCK_TH:
      case MD_BLOCK_TD:
        table_.rows.back().push_back(trim_spaces(inline_));
        inline_.clear();
        break;
      case MD_BLOCK_TABLE:
        emit(text_table(table_.rows, table_.align));
        break;
      case MD_BLOCK_CODE: {
        std::vector<std::string> lines;
        for (std::size_t start = 0; start < code_.size();) {
          const std::size_t end = std::min(code_.find('\n', start), code_.size());
          lines.push_back(concat({"    ", std::string_view(code_).substr(start, end - start)}));
          start = end + 1;
        }
        code_.clear();
        code_block_ = false;
        emit(lines);
        break;
      }
      case MD_BLOCK_HR:
        emit({std::string(std::min<std::size_t>(width_, 20), '-')});
        break;
      case MD_BLOCK_DOC:
      case MD_BLOCK_HTML:
      case MD_BLOCK_THEAD:
      case MD_BLOCK_TBODY:
      case MD_BLOCK_TR:
        break;
    }
  }

  void enter_span(MD_SPANTYPE type, void* detail) override {
    if (type == MD_SPAN_A || type == MD_SPAN_IMG) {
      links_.emplace_back(url(type, detail), inline_.size());
    } else if (type == MD_SPAN_LATEXMATH || type == MD_SPAN_LATEXMATH_DISPLAY) {
      start_math(type);
      if (math_.display) flush_paragraph();  // display math stands on its own lines
    } else if (type == MD_SPAN_DEL) {
      inline_ += "~~";
    }
  }

  void leave_span(MD_SPANTYPE type) override {
    if (type == MD_SPAN_A || type == MD_SPAN_IMG) {
      const auto& [url, start] = links_.back();
      if (inline_.compare(start, std::string::npos, url) != 0) inline_ += concat({" (", url, ")"});  // <url> once
      links_.pop_back();
    } else if (type == MD_SPAN_LATEXMATH) {
      inline_ += unicode();
    } else if (type == MD_SPAN_LATEXMATH_DISPLAY) {
      emit(display_math(unicode()));
    } else if (type == MD_SPAN_DEL) {
      inline_ += "~~";
    }
  }

  void text(MD_TEXTTYPE type, std::string_view text, bool source) override {
    if (type == MD_TEXT_LATEXMATH) return math_.add(text, source);
    if (type == MD_TEXT_CODE && code_block_) return void(code_ += text);
    if (type == MD_TEXT_SOFTBR)
      inline_ += ' ';
    else if (type == MD_TEXT_BR)
      inline_ += '\n';
    else if (type == MD_TEXT_ENTITY)
      inline_ += entity(text);
    else if (type == MD_TEXT_NULLCHAR)
      inline_ += "\uFFFD";
    else
      inline_ += text;
  }

 private:
  // A container's share of the lines of a block inside it: a quote's bar on every
  // line, an item's marker on the first line of its first block and spaces after.
  struct Container {
    std::string first;
    bool item = false;
    bool used = false;
  };

  std::string unicode() const {
    return converted_math([](const std::string& latex) { return latex_to_unicode(latex); });
  }

  // Display math indented, continuation lines of an aligned equation ("= ...") under
  // the first "=".
  static std::vector<std::string> display_math(const std::string& unicode) {
    const std::size_t equals = unicode.find(" = ");
    const std::size_t first_end = unicode.find('\n');
    const std::size_t align = equals != std::string::npos && equals < first_end
                                  ? display_width(std::string_view(unicode).substr(0, equals + 1))
                                  : 0;
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= unicode.size();) {
      const std::size_t end = std::min(unicode.find('\n', start), unicode.size());
      const std::string line = unicode.substr(start, end - start);
      lines.push_back(concat({"    ", line.starts_with("= ") ? std::string(align, ' ') : "", line}));
      start = end + 1;
    }
    return lines;
  }

  void flush_paragraph() {
    const std::string text = trim_spaces(inline_);
    inline_.clear();
    if (text.empty()) return;
    const auto [first, rest] = prefixes();
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= text.size();) {  // hard breaks start new lines
      const std::size_t end = std::min(text.find('\n', start), text.size());
      for (std::string& line : wrap_words(text.substr(start, end - start), rest, width_)) lines.push_back(line);
      start = end + 1;
    }
    if (!lines.empty()) lines[0] = first + lines[0].substr(rest.size());
    write(lines, tight_item_text());
  }

  // Lines of a block that are not wrapped (headings, tables, code, math).
  void emit(const std::vector<std::string>& lines) {
    const auto [first, rest] = prefixes();
    std::vector<std::string> prefixed;
    for (const std::string& line : lines) prefixed.push_back((prefixed.empty() ? first : rest) + line);
    write(prefixed, false);
  }

  // The prefixes of a block's first and further lines; uses up the items' markers. Sets
  // blank_, the line before the block: the bars of the quotes it shares with the last.
  std::pair<std::string, std::string> prefixes() {
    std::string first, rest;
    std::size_t quotes = 0;
    blank_.clear();
    for (Container& c : containers_) {
      first += c.used ? std::string(c.first.size(), ' ') : c.first;
      rest += c.item ? std::string(c.first.size(), ' ') : c.first;
      if (c.item) c.used = true;
      if (!c.item && quotes++ < last_quotes_) blank_ = rest;
    }
    last_quotes_ = quotes;
    return {first, rest};
  }

  // Text written straight into a list item (a tight list): items stay together.
  [[nodiscard]] bool tight_item_text() const { return !paragraph_ && !containers_.empty() && containers_.back().item; }

  void write(const std::vector<std::string>& lines, bool tight) {
    // Blocks are separated by a blank line, but the items of tight lists are not.
    auto add = [&](std::string_view line) {
      out_ += line.substr(0, line.find_last_not_of(' ') + 1);  // npos + 1 is 0
      out_ += '\n';
    };
    if (!out_.empty() && !(tight && last_tight_)) add(blank_);
    for (const std::string& line : lines) add(line);
    last_tight_ = tight;
  }

  std::size_t width_;
  std::vector<Container> containers_;
  std::string blank_;
  std::size_t last_quotes_ = 0;
  std::vector<int> lists_;                                  // per open list: the next number, or 0 for bullets
  std::vector<char> ordered_;                               // per open numbered list: its delimiter
  std::vector<std::pair<std::string, std::size_t>> links_;  // open links: URL, where the text starts
  int heading_ = 1;
  bool code_block_ = false, paragraph_ = false, last_tight_ = false;
};

// --- LaTeX ------------------------------------------------------------------------

// Plain characters (no markup) as text-mode LaTeX: special characters escaped, and
// Greek letters, dotted symbols (θ̇₁), sub/superscripts (10⁻¹²) and operators (× −) as
// inline math, so pdflatex compiles it.
std::string latex_chars(std::string_view s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const Utf8Char c = decode_utf8(s, i);
    const std::string_view symbol = tex_symbol(c.cp);
    std::string base(symbol);
    if (base.empty() && c.cp < 0x80 && std::isalpha(static_cast<int>(c.cp))) base = s.substr(i, 1);
    // Accents and scripts that follow the base.
    std::size_t j = i + c.size;
    std::string math = base;
    for (Utf8Char next; !base.empty() && j < s.size() && ((next = decode_utf8(s, j)).cp == 0x307 || next.cp == 0x308);
         j += next.size)
      math = concat({next.cp == 0x307 ? "\\dot{" : "\\ddot{", math, "}"});
    // Scripts, each run in one group (10⁻¹² is 10^{-12}): after a letter, or starting at
    // c itself; a digit's scripts (10²) start after it, with the digit kept as text.
    const bool c_is_script = script_char(c.cp).has_value();
    if (base.empty() && c_is_script) j = i;
    std::string sub, sup;
    while ((!base.empty() || c_is_script) && j < s.size()) {
      const Utf8Char next = decode_utf8(s, j);
      const auto script = script_char(next.cp);
      if (!script) break;
      (script->superscript ? sup : sub) += script->ascii;
      j += next.size;
    }
    std::string scripts;
    if (!sub.empty()) scripts += concat({"_{", sub, "}"});
    if (!sup.empty()) scripts += concat({"^{", sup, "}"});
    if (!symbol.empty() || math != base || !scripts.empty()) {
      out += concat({"$", math.empty() ? "{}" : math, scripts, "$"});  // {} for a script alone
      i = j;
      continue;
    }
    out += c.cp < 0x80 ? latex_escape(s.substr(i, 1)) : std::string(s.substr(i, c.size));
    i += c.size;
  }
  return out;
}

class LatexRenderer final : public Renderer {
 public:
  using Renderer::Renderer;

  void enter_block(MD_BLOCKTYPE type, void* detail) override {
    if (type != MD_BLOCK_LI && type != MD_BLOCK_DOC) flush_item_text();
    switch (type) {
      case MD_BLOCK_UL:
      case MD_BLOCK_OL:
        out_ += type == MD_BLOCK_UL ? "\\begin{itemize}\n" : "\\begin{enumerate}\n";
        open_.push_back(type);
        break;
      case MD_BLOCK_QUOTE:
        out_ += "\\begin{quote}\n";
        open_.push_back(type);
        break;
      case MD_BLOCK_LI:
        out_ += "  \\item ";
        open_.push_back(type);
        item_paragraphs_.push_back(0);
        break;
      case MD_BLOCK_H:
        out_ += static_cast<MD_BLOCK_H_DETAIL*>(detail)->level <= 1 ? "\\subsection*{" : "\\subsubsection*{";
        break;
      case MD_BLOCK_DOC:
      case MD_BLOCK_HR:
      case MD_BLOCK_CODE:
      case MD_BLOCK_HTML:
      case MD_BLOCK_P:
      case MD_BLOCK_TABLE:
      case MD_BLOCK_THEAD:
      case MD_BLOCK_TBODY:
      case MD_BLOCK_TR:
      case MD_BLOCK_TH:
      case MD_BLOCK_TD:
        table_.start(type, detail);
        break;
    }
  }

  void leave_block(MD_BLOCKTYPE type) override {
    switch (type) {
      case MD_BLOCK_UL:
      case MD_BLOCK_OL:
      case MD_BLOCK_QUOTE:
        open_.pop_back();
        out_ += type == MD_BLOCK_UL   ? "\\end{itemize}\n"
                : type == MD_BLOCK_OL ? "\\end{enumerate}\n"
                                      : "\\end{quote}\n";
        if (!in_item()) out_ += "\n";
        break;
      case MD_BLOCK_LI:
        if (item_paragraphs_.back() == 0 && inline_.empty()) inline_ = " ";  // an empty item ends its line too
        flush_item_text();
        open_.pop_back();
        item_paragraphs_.pop_back();
        break;
      case MD_BLOCK_P:
        if (in_item()) {
          flush_item_text();
        } else {
          out_ += take_inline() + "\n\n";
        }
        break;
      case MD_BLOCK_H:
        out_ += take_inline() + "}\n\n";
        break;
      case MD_BLOCK_CODE:
        if (!code_.empty() && code_.back() == '\n') code_.pop_back();
        out_ += concat({"\\begin{verbatim}\n", code_, "\n\\end{verbatim}\n\n"});
        code_.clear();
        break;
      case MD_BLOCK_TH:
      case MD_BLOCK_TD:
        table_.rows.back().push_back(take_inline());
        break;
      case MD_BLOCK_TABLE:
        out_ += concat({"\\begin{tabular}{", table_.align, "}\n"});
        for (std::size_t r = 0; r < table_.rows.size(); ++r) {
          for (std::size_t c = 0; c < table_.rows[r].size(); ++c) out_ += (c > 0 ? " & " : "  ") + table_.rows[r][c];
          out_ += " \\\\\n";
          if (r == 0) out_ += "  \\hline\n";
        }
        out_ += "\\end{tabular}\n\n";
        break;
      case MD_BLOCK_HR:
        out_ += "\\noindent\\rule{\\linewidth}{0.4pt}\n\n";
        break;
      case MD_BLOCK_DOC:
      case MD_BLOCK_HTML:
      case MD_BLOCK_THEAD:
      case MD_BLOCK_TBODY:
      case MD_BLOCK_TR:
        break;
    }
  }

  void enter_span(MD_SPANTYPE type, void* detail) override {
    flush_text();
    switch (type) {
      case MD_SPAN_EM:
        inline_ += "\\emph{";
        break;
      case MD_SPAN_STRONG:
        inline_ += "\\textbf{";
        break;
      case MD_SPAN_A:
      case MD_SPAN_IMG:
        inline_ += concat({"\\href{", url(type, detail), "}{"});
        break;
      case MD_SPAN_LATEXMATH:
      case MD_SPAN_LATEXMATH_DISPLAY:
        start_math(type);
        break;
      case MD_SPAN_CODE:
      case MD_SPAN_DEL:
      case MD_SPAN_WIKILINK:
      case MD_SPAN_U:
        break;
    }
  }

  void leave_span(MD_SPANTYPE type) override {
    flush_text();
    switch (type) {
      case MD_SPAN_EM:
      case MD_SPAN_STRONG:
      case MD_SPAN_A:
      case MD_SPAN_IMG:
        inline_ += "}";
        break;
      case MD_SPAN_CODE:
        inline_ += concat({"\\texttt{", latex_escape(code_), "}"});
        code_.clear();
        break;
      case MD_SPAN_LATEXMATH:
        inline_ += concat({"$", math_.text, "$"});
        break;
      case MD_SPAN_LATEXMATH_DISPLAY:
        inline_ += concat({"\\[\n", math_.trimmed(), "\n\\]"});
        break;
      case MD_SPAN_DEL:
      case MD_SPAN_WIKILINK:
      case MD_SPAN_U:
        break;
    }
  }

  void text(MD_TEXTTYPE type, std::string_view text, bool source) override {
    if (type == MD_TEXT_LATEXMATH) return math_.add(text, source);
    if (type == MD_TEXT_CODE) return void(code_ += text);
    if (type == MD_TEXT_BR) {
      flush_text();
      inline_ += "\\\\\n";
    } else if (type == MD_TEXT_SOFTBR) {
      text_ += ' ';
    } else if (type == MD_TEXT_ENTITY) {
      text_ += entity(text);
    } else if (type != MD_TEXT_NULLCHAR) {
      text_ += text;
    }
  }

 private:
  [[nodiscard]] bool in_item() const { return !open_.empty() && open_.back() == MD_BLOCK_LI; }

  void flush_text() {
    inline_ += latex_chars(text_);
    text_.clear();
  }
  std::string take_inline() {
    flush_text();
    return trim_spaces(std::exchange(inline_, {}));
  }
  // An item's text, after "\item " or as a further paragraph of the item.
  void flush_item_text() {
    flush_text();
    if (!in_item() || inline_.empty()) return;
    if (item_paragraphs_.back()++ > 0) out_ += "\n  ";
    out_ += take_inline() + "\n";
  }

  std::string text_;                // plain text not yet converted by latex_chars
  std::vector<MD_BLOCKTYPE> open_;  // the open lists, quotes and items
  std::vector<int> item_paragraphs_;
};

// --- HTML -------------------------------------------------------------------------

// A link's target kept only when it cannot run anything: http(s), mailto, or relative.
bool safe_url(std::string_view url) {
  const std::size_t colon = url.find(':');
  if (colon == std::string_view::npos || url.find_first_of("/?#") < colon) return true;
  std::string scheme(url.substr(0, colon));
  for (char& c : scheme) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return scheme == "http" || scheme == "https" || scheme == "mailto";
}

class HtmlRenderer final : public Renderer {
 public:
  HtmlRenderer(std::string_view markdown, std::vector<std::string>* unknown) : Renderer(markdown), unknown_(unknown) {}

  void enter_block(MD_BLOCKTYPE type, void* detail) override {
    switch (type) {
      case MD_BLOCK_QUOTE:
        out_ += "<blockquote>\n";
        break;
      case MD_BLOCK_UL:
        out_ += "<ul>\n";
        break;
      case MD_BLOCK_OL: {
        const unsigned start = static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start;
        out_ += start == 1 ? "<ol>\n" : concat({"<ol start=\"", std::to_string(start), "\">\n"});
        break;
      }
      case MD_BLOCK_LI:
        out_ += "<li>";
        break;
      case MD_BLOCK_HR:
        out_ += "<hr>\n";
        break;
      case MD_BLOCK_H:
        heading_ = static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level);
        out_ += concat({"<h", std::to_string(heading_), ">"});
        break;
      case MD_BLOCK_CODE:
        out_ += "<pre><code>";
        break;
      case MD_BLOCK_P:
        out_ += "<p>";
        break;
      case MD_BLOCK_TABLE:
        out_ += "<table>\n";
        break;
      case MD_BLOCK_THEAD:
        out_ += "<thead>\n";
        break;
      case MD_BLOCK_TBODY:
        out_ += "<tbody>\n";
        break;
      case MD_BLOCK_TR:
        out_ += "<tr>";
        break;
      case MD_BLOCK_TH:
      case MD_BLOCK_TD: {
        const char a = alignment(detail);
        out_ += concat({type == MD_BLOCK_TH ? "<th" : "<td",
                        a == 'r'   ? " align=\"right\""
                        : a == 'c' ? " align=\"center\""
                                   : "",
                        ">"});
        break;
      }
      case MD_BLOCK_DOC:
      case MD_BLOCK_HTML:
        break;
    }
  }

  void leave_block(MD_BLOCKTYPE type) override {
    switch (type) {
      case MD_BLOCK_QUOTE:
        out_ += "</blockquote>\n";
        break;
      case MD_BLOCK_UL:
        out_ += "</ul>\n";
        break;
      case MD_BLOCK_OL:
        out_ += "</ol>\n";
        break;
      case MD_BLOCK_LI:
        out_ += "</li>\n";
        break;
      case MD_BLOCK_H:
        out_ += concat({"</h", std::to_string(heading_), ">\n"});
        break;
      case MD_BLOCK_CODE:
        out_ += "</code></pre>\n";
        break;
      case MD_BLOCK_P:
        out_ += "</p>\n";
        break;
      case MD_BLOCK_TABLE:
        out_ += "</table>\n";
        break;
      case MD_BLOCK_THEAD:
        out_ += "</thead>\n";
        break;
      case MD_BLOCK_TBODY:
        out_ += "</tbody>\n";
        break;
      case MD_BLOCK_TR:
        out_ += "</tr>\n";
        break;
      case MD_BLOCK_TH:
        out_ += "</th>";
        break;
      case MD_BLOCK_TD:
        out_ += "</td>";
        break;
      case MD_BLOCK_DOC:
      case MD_BLOCK_HR:
      case MD_BLOCK_HTML:
        break;
    }
  }

  void enter_span(MD_SPANTYPE type, void* detail) override {
    switch (type) {
      case MD_SPAN_EM:
        out_ += "<em>";
        break;
      case MD_SPAN_STRONG:
        out_ += "<strong>";
        break;
      case MD_SPAN_CODE:
        out_ += "<code>";
        break;
      case MD_SPAN_DEL:
        out_ += "<del>";
        break;
      case MD_SPAN_U:
        out_ += "<u>";
        break;
      case MD_SPAN_A: {  // an unsafe target is dropped, its text kept
        const std::string target = url(type, detail);
        links_.push_back(safe_url(target));
        out_ += links_.back() ? concat({"<a href=\"", escape_markup(target), "\">"}) : "<span>";
        break;
      }
      case MD_SPAN_IMG:  // nothing is fetched: the image's text stands for it
        out_ += "<span>";
        break;
      case MD_SPAN_LATEXMATH:
      case MD_SPAN_LATEXMATH_DISPLAY:
        start_math(type);
        break;
      case MD_SPAN_WIKILINK:
        break;
    }
  }

  void leave_span(MD_SPANTYPE type) override {
    switch (type) {
      case MD_SPAN_EM:
        out_ += "</em>";
        break;
      case MD_SPAN_STRONG:
        out_ += "</strong>";
        break;
      case MD_SPAN_CODE:
        out_ += "</code>";
        break;
      case MD_SPAN_DEL:
        out_ += "</del>";
        break;
      case MD_SPAN_U:
        out_ += "</u>";
        break;
      case MD_SPAN_A:
        out_ += links_.back() ? "</a>" : "</span>";
        links_.pop_back();
        break;
      case MD_SPAN_IMG:
        out_ += "</span>";
        break;
      case MD_SPAN_LATEXMATH:
      case MD_SPAN_LATEXMATH_DISPLAY: {
        const bool display = type == MD_SPAN_LATEXMATH_DISPLAY;
        out_ += converted_math([&](const std::string& latex) { return latex_to_mathml(latex, display, unknown_); });
        break;
      }
      case MD_SPAN_WIKILINK:
        break;
    }
  }

  void text(MD_TEXTTYPE type, std::string_view text, bool source) override {
    switch (type) {
      case MD_TEXT_LATEXMATH:
        math_.add(text, source);
        break;
      case MD_TEXT_BR:
        out_ += "<br>\n";
        break;
      case MD_TEXT_SOFTBR:
        out_ += "\n";
        break;
      case MD_TEXT_ENTITY:
        out_ += escape_markup(entity(text));
        break;
      case MD_TEXT_NULLCHAR:
        out_ += "\uFFFD";
        break;
      case MD_TEXT_NORMAL:
      case MD_TEXT_CODE:
      case MD_TEXT_HTML:
        out_ += escape_markup(text);
        break;
    }
  }

 private:
  std::vector<std::string>* unknown_;
  int heading_ = 1;
  std::vector<bool> links_;  // per open link: its target was kept
};

// `text` as one paragraph: on one line, and a start that would open a block (a
// heading's #, a quote's >, a list's marker, a fence) escaped.
std::string one_paragraph(std::string_view text) {
  std::string s;
  for (char c : text) s += c == '\n' || c == '\r' ? ' ' : c;
  s.erase(0, std::min(s.find_first_not_of(' '), s.size()));
  if (s.empty()) return s;
  const char c = s.front();
  const bool rule = s.find_first_not_of(std::string(1, c) + " ") == std::string::npos;
  if (c == '#' || c == '>' || s.starts_with("```") || s.starts_with("~~~") ||
      ((c == '-' || c == '+' || c == '*' || c == '_') && (s.size() == 1 || s[1] == ' ' || rule)))
    return concat({"\\", s});
  const std::size_t digits = s.find_first_not_of("0123456789");
  if (digits > 0 && digits != std::string::npos && (s[digits] == '.' || s[digits] == ')') &&
      (digits + 1 == s.size() || s[digits + 1] == ' '))
    s.insert(digits, "\\");
  return s;
}

}  // namespace

std::string markdown_to_text(std::string_view markdown, std::size_t width) {
  TextRenderer renderer(markdown, width);
  parse(markdown, renderer);
  return renderer.take();
}

std::string markdown_to_latex(std::string_view markdown) {
  LatexRenderer renderer(markdown);
  parse(markdown, renderer);
  return renderer.take();
}

std::string markdown_to_html(std::string_view markdown, std::vector<std::string>* unknown) {
  HtmlRenderer renderer(markdown, unknown);
  parse(markdown, renderer);
  return renderer.take();
}

std::string inline_latex(std::string_view text) {
  const std::string paragraph = one_paragraph(text);
  std::string out = markdown_to_latex(paragraph);
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

void check_markdown(std::string_view markdown, const std::string& origin) {
  try {
    (void)markdown_to_text(markdown, 80);  // the nesting of blocks, spans and math
  } catch (const Error& e) {
    throw Error(e.code(), origin + ": " + e.what());
  }
}

}  // namespace linkage
