#include "report/latex_mathml.hpp"

#include <array>
#include <cctype>
#include <optional>
#include <utility>

#include "core/limits.hpp"
#include "core/markup_escape.hpp"
#include "report/notation.hpp"
#include "report/text_layout.hpp"
#include "report/unicode_tex.hpp"

namespace linkage {

namespace {

std::string element(std::string_view tag, std::string_view content, std::string_view attributes = {}) {
  return concat({"<", tag, attributes.empty() ? "" : " ", attributes, ">", content, "</", tag, ">"});
}

std::string space(std::string_view width) { return concat({"<mspace width=\"", width, "\"/>"}); }

// Elements as one: a row of several, or the one itself.
std::string one(const std::vector<std::string>& elements) {
  if (elements.size() == 1) return elements.front();
  std::string row;
  for (const std::string& e : elements) row += e;
  return element("mrow", row);
}

// TeX's widths of its spacing commands, in em (a quad is 1 em).
std::optional<std::string_view> space_width(std::string_view name) {
  constexpr std::array<std::pair<std::string_view, std::string_view>, 6> kSpaces{
      {{",", "0.1667em"}, {":", "0.2222em"}, {";", "0.2778em"}, {" ", "0.3333em"}, {"quad", "1em"}, {"qquad", "2em"}}};
  for (const auto& [n, width] : kSpaces)
    if (n == name) return width;
  return std::nullopt;
}

// Delimiter commands (after \left, \big, or alone) and their characters.
std::optional<std::string_view> delimiter_command(std::string_view name) {
  constexpr std::array<std::pair<std::string_view, std::string_view>, 13> kDelimiters{{{"lvert", "|"},
                                                                                       {"rvert", "|"},
                                                                                       {"vert", "|"},
                                                                                       {"lVert", "‖"},
                                                                                       {"rVert", "‖"},
                                                                                       {"Vert", "‖"},
                                                                                       {"|", "‖"},
                                                                                       {"langle", "⟨"},
                                                                                       {"rangle", "⟩"},
                                                                                       {"lbrace", "{"},
                                                                                       {"rbrace", "}"},
                                                                                       {"{", "{"},
                                                                                       {"}", "}"}}};
  for (const auto& [n, text] : kDelimiters)
    if (n == name) return text;
  return std::nullopt;
}

// \big ... \Bigg: MathJax's heights of TeX's four sizes.
std::optional<std::string_view> big_size(std::string_view name) {
  for (const std::string_view suffix : {"l", "r", "m"})
    if (name.size() > suffix.size() && name.ends_with(suffix)) name.remove_suffix(1);
  if (name == "big") return "1.2em";
  if (name == "Big") return "1.623em";
  if (name == "bigg") return "2.047em";
  if (name == "Bigg") return "2.470em";
  return std::nullopt;
}

// The accents and the spacing characters MathML draws over their base.
std::optional<std::string_view> accent(std::string_view name) {
  if (name == "dot") return "˙";
  if (name == "ddot") return "¨";
  if (name == "hat") return "^";
  if (name == "bar") return "¯";
  if (name == "tilde") return "˜";
  if (name == "vec") return "→";
  return std::nullopt;
}

bool uppercase_greek(std::string_view text) {
  const Utf8Char c = decode_utf8(text, 0);
  return c.size == text.size() && c.cp >= 0x391 && c.cp <= 0x3A9;
}

class Converter {
 public:
  Converter(std::string_view s, std::vector<std::string>* unknown) : s_(s), unknown_(unknown) {}

  std::string run() {
    std::vector<std::string> all;
    while (true) {
      for (std::string& e : row()) all.push_back(std::move(e));
      if (pos_ >= s_.size()) break;
      all.push_back(stray());
    }
    std::string out;
    for (const std::string& e : all) out += e;
    return out;
  }

 private:
  [[nodiscard]] bool at(std::string_view text) const { return s_.substr(pos_).starts_with(text); }
  // \name here, not followed by a letter.
  [[nodiscard]] bool at_command(std::string_view name) const {
    if (pos_ >= s_.size() || s_[pos_] != '\\' || !s_.substr(pos_ + 1).starts_with(name)) return false;
    const std::size_t after = pos_ + 1 + name.size();
    return after >= s_.size() || std::isalpha(static_cast<unsigned char>(s_[after])) == 0;
  }
  void skip_spaces() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
  }
  // Where a row ends: the end, a group's }, a cell's &, a row's \\, an environment's \end
  // or a delimited group's \right.
  [[nodiscard]] bool at_stop() const {
    return pos_ >= s_.size() || s_[pos_] == '}' || s_[pos_] == '&' || at("\\\\") || at_command("end") ||
           at_command("right");
  }

  std::string unknown(std::string_view what) {
    if (unknown_ != nullptr) unknown_->emplace_back(what);
    return element("merror", element("mtext", escape_markup(what)));
  }

  // A stop that nothing open owns, consumed and kept as unknown.
  std::string stray() {
    if (at("\\\\")) {
      pos_ += 2;
      return unknown("\\\\");
    }
    if (s_[pos_] == '\\') {  // \end{...} or \right
      const std::size_t start = pos_;
      ++pos_;
      const std::string_view name = letters();
      if (name == "end") (void)braced_text();
      return unknown(s_.substr(start, pos_ - start));
    }
    return unknown(s_.substr(pos_++, 1));
  }

  std::string_view letters() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_])) != 0) ++pos_;
    return s_.substr(start, pos_ - start);
  }

  // {text} as written, braces balanced (\text's argument, an environment's name).
  std::string_view braced_text() {
    skip_spaces();
    if (pos_ >= s_.size() || s_[pos_] != '{') return {};
    const std::size_t start = ++pos_;
    int open = 1;
    for (; pos_ < s_.size(); ++pos_) {
      if (s_[pos_] == '\\' && pos_ + 1 < s_.size()) {
        ++pos_;
      } else if (s_[pos_] == '{') {
        ++open;
      } else if (s_[pos_] == '}' && --open == 0) {
        return s_.substr(start, pos_++ - start);
      }
    }
    return s_.substr(start);
  }

  void descend(const NestingLevel& level) const {
    if (level.too_deep()) throw LatexNestingError(s_.data() + std::min(pos_, s_.size()));
  }

  // Elements up to a stop; scripts attach to the element before them.
  std::vector<std::string> row() {
    std::vector<std::string> out;
    bool after_function = false;  // sin, cos: a thin space unless a parenthesis follows
    while (true) {
      skip_spaces();
      if (at_stop()) break;
      const char c = s_[pos_];
      if (c == '_' || c == '^') {
        std::string base = out.empty() ? element("mrow", "") : std::move(out.back());
        if (!out.empty()) out.pop_back();
        out.push_back(scripts(std::move(base)));
        continue;
      }
      if (after_function && c != '(' && !at_command("left")) out.push_back(space("0.1667em"));
      after_function = false;
      bool function = false;
      std::string e = atom(function);
      after_function = function;
      // TeX's thin space between a variable and a function's name (a cos): MathML has none.
      if (function && !out.empty() && !out.back().starts_with("<mo") && !out.back().starts_with("<mspace"))
        out.push_back(space("0.1667em"));
      if (!e.empty()) out.push_back(std::move(e));
    }
    return out;
  }

  std::string scripts(std::string base) {
    std::optional<std::string> sub, sup;
    while (true) {
      skip_spaces();
      if (pos_ >= s_.size() || (s_[pos_] != '_' && s_[pos_] != '^')) break;
      std::optional<std::string>& script = s_[pos_] == '_' ? sub : sup;
      ++pos_;
      const std::string value = argument();
      script = script ? one({*script, unknown("double script")}) : value;
    }
    if (sub && sup) return element("msubsup", base + *sub + *sup);
    return sub ? element("msub", base + *sub) : element("msup", base + *sup);
  }

  // A command's or a script's argument: a {group}, else one character or command.
  std::string argument() {
    skip_spaces();
    const NestingLevel level(depth_);
    descend(level);
    if (pos_ >= s_.size() || at_stop()) return element("mrow", "");
    if (s_[pos_] == '{') return group();
    if (std::isdigit(static_cast<unsigned char>(s_[pos_])) != 0) return element("mn", s_.substr(pos_++, 1));
    if (std::isalpha(static_cast<unsigned char>(s_[pos_])) != 0) return identifier(s_.substr(pos_++, 1));
    bool function = false;
    std::string e = atom(function);
    return e.empty() ? element("mrow", "") : e;
  }

  // {...} as one element; a stray &, \\ or \end inside is kept as unknown.
  std::string group() {
    const NestingLevel level(depth_);
    descend(level);
    ++pos_;  // {
    std::vector<std::string> elements;
    while (true) {
      for (std::string& e : row()) elements.push_back(std::move(e));
      if (pos_ >= s_.size()) break;
      if (s_[pos_] == '}') {
        ++pos_;
        break;
      }
      elements.push_back(stray());
    }
    return one(elements);
  }

  std::string identifier(std::string_view text) {
    const bool single = decode_utf8(text, 0).size == text.size();
    // One letter is italic unless upright (\mathrm, capital Greek); several are upright.
    return element("mi", escape_markup(text),
                   single && (upright_ || uppercase_greek(text)) ? "mathvariant=\"normal\"" : "");
  }

  static std::string operator_element(std::string_view text, bool stretchy = true) {
    return element("mo", escape_markup(text == "-" ? "−" : text), stretchy ? "" : "stretchy=\"false\"");
  }

  // One element at pos_ (none for a command that draws nothing); `function`: a function's name.
  std::string atom(bool& function) {
    const char c = s_[pos_];
    if (c == '\\') return command(function);
    if (c == '{') return group();
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 ||
        (c == '.' && pos_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_ + 1])) != 0)) {
      const std::size_t start = pos_;
      while (pos_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[pos_])) != 0 || s_[pos_] == '.')) ++pos_;
      return element("mn", s_.substr(start, pos_ - start));
    }
    if (std::isalpha(static_cast<unsigned char>(c)) != 0) {
      // Upright text is a word (kg, crank); italic letters are each a variable.
      const std::size_t start = pos_++;
      while (upright_ && pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_])) != 0) ++pos_;
      return identifier(s_.substr(start, pos_ - start));
    }
    if (static_cast<unsigned char>(c) >= 0x80) {  // a Unicode character written into the math
      const Utf8Char u = decode_utf8(s_, pos_);
      pos_ += u.size;
      return identifier(s_.substr(pos_ - u.size, u.size));
    }
    ++pos_;
    switch (c) {
      case '(':
      case ')':
      case '[':
      case ']':
      case '|':
        return operator_element(std::string_view(&c, 1), false);  // TeX's plain delimiters keep their size
      case '\'':
        return operator_element("′");
      case '/':  // TeX's slash is a plain symbol (m/s), not an operator spaced apart
        return element("mo", "/", "lspace=\"0\" rspace=\"0\"");
      case '~':
        return space("0.3333em");
      default:
        return operator_element(std::string_view(&c, 1));
    }
  }

  std::string command(bool& function) {
    const std::size_t start = pos_++;
    if (pos_ >= s_.size()) return unknown("\\");
    std::string_view name = letters();
    if (name.empty()) name = s_[pos_] == '\n' ? (++pos_, " ") : s_.substr(pos_++, 1);  // \, \{ \| and "\ "
    if (const auto width = space_width(name)) return space(*width);
    if (name == "!") return {};
    if (name == "frac" || name == "dfrac" || name == "tfrac") {
      std::string numerator = argument();
      return element("mfrac", numerator + argument());
    }
    if (name == "sqrt") {
      skip_spaces();
      if (at("[")) {  // \sqrt[n]{x}: the index converted on its own, a level deeper
        const std::size_t close = std::min(s_.find(']', pos_), s_.size());
        Converter index(s_.substr(pos_ + 1, close - pos_ - 1), unknown_);
        index.depth_ = depth_ + 1;
        const NestingLevel level(index.depth_);
        descend(level);
        pos_ = std::min(close + 1, s_.size());
        const std::string degree = element("mrow", index.run());
        return element("mroot", argument() + degree);
      }
      return element("msqrt", argument());
    }
    if (const auto mark = accent(name)) return element("mover", argument() + element("mo", *mark), "accent=\"true\"");
    if (name == "mathrm" || name == "operatorname" || name == "textrm") {
      const bool was = std::exchange(upright_, true);
      std::string e = argument();
      upright_ = was;
      function = name == "operatorname";
      return e;
    }
    if (name == "text" || name == "mbox" || name == "textit" || name == "textbf")
      return element("mtext", escape_markup(braced_text()));
    if (name == "left") return delimited();
    if (name == "begin") return environment();
    if (const auto size = big_size(name)) {
      const std::string d = delimiter();
      return d.empty()
                 ? std::string{}
                 : element("mo", d, concat({"minsize=\"", *size, "\" maxsize=\"", *size, "\" symmetric=\"true\""}));
    }
    if (const auto d = delimiter_command(name)) return operator_element(*d, false);
    if (const std::optional<TexCommand> symbol = tex_command(name)) {
      switch (symbol->kind) {
        case TexSymbolKind::letter:
          return identifier(symbol->text);
        case TexSymbolKind::op:
          return operator_element(symbol->text);
        case TexSymbolKind::from_tex:
          if (std::isalpha(static_cast<unsigned char>(symbol->text.front())) != 0) {
            function = true;
            return element("mi", symbol->text);
          }
          return operator_element(symbol->text);
      }
    }
    if (name == "#" || name == "%" || name == "&" || name == "$" || name == "_") return operator_element(name);
    return unknown(s_.substr(start, pos_ - start));
  }

  // The delimiter after \left, \right or \big: its character, empty for ".".
  std::string delimiter() {
    skip_spaces();
    if (pos_ >= s_.size()) return {};
    const char c = s_[pos_];
    if (c == '.') {
      ++pos_;
      return {};
    }
    if (c == '\\') {
      const std::size_t start = pos_++;
      std::string_view name = letters();
      if (name.empty() && pos_ < s_.size()) name = s_.substr(pos_++, 1);
      if (const auto d = delimiter_command(name)) return escape_markup(*d);
      if (const std::optional<TexCommand> symbol = tex_command(name)) return escape_markup(symbol->text);
      (void)unknown(s_.substr(start, pos_ - start));
      return "?";
    }
    if (std::string_view("()[]|/<>").find(c) != std::string_view::npos) {
      ++pos_;
      return escape_markup(std::string_view(&c, 1));
    }
    (void)unknown(s_.substr(pos_, 1));
    return "?";
  }

  // \left D ... \right D: a row whose delimiters stretch to its height when it holds a
  // fraction, a root or a table. (Chromium spaces a stretchy delimiter apart from what it
  // holds; around one line a plain one is TeX's size anyway.)
  std::string delimited() {
    const NestingLevel level(depth_);
    descend(level);
    const std::string open = delimiter();
    std::vector<std::string> elements;
    while (true) {
      for (std::string& e : row()) elements.push_back(std::move(e));
      if (pos_ >= s_.size()) {
        elements.push_back(unknown("\\left without \\right"));
        break;
      }
      if (at_command("right")) {
        pos_ += 6;
        break;
      }
      elements.push_back(stray());
    }
    const std::string close = delimiter();
    std::string content;
    for (const std::string& e : elements) content += e;
    const bool tall = content.find("<mfrac") != std::string::npos || content.find("<mtable") != std::string::npos ||
                      content.find("<msqrt") != std::string::npos || content.find("<mroot") != std::string::npos;
    const std::string_view stretch = tall ? "" : "stretchy=\"false\"";
    return element("mrow", concat({open.empty() ? "" : element("mo", open, stretch), content,
                                   close.empty() ? "" : element("mo", close, stretch)}));
  }

  // \begin{NAME} rows of & cells ... \end{NAME}.
  std::string environment() {
    const NestingLevel level(depth_);
    descend(level);
    const std::string name(braced_text());
    const bool aligned = name == "aligned" || name == "align*" || name == "gathered";
    const std::string_view fences = name == "bmatrix" ? "[]" : name == "pmatrix" ? "()" : "";
    const bool matrix = !fences.empty() || name == "matrix";
    std::string rows, cells, cell;
    int cell_count = 0;
    bool gap = false;  // \\[...]: space above the next row
    const auto end_cell = [&] {
      cells += element("mtd", cell);
      cell.clear();
      ++cell_count;
    };
    const auto end_row = [&] {
      end_cell();
      rows += element("mtr", cells, gap ? "class=\"gap\"" : "");
      cells.clear();
      cell_count = 0;
    };
    while (true) {
      for (const std::string& e : row()) cell += e;
      if (pos_ >= s_.size()) {
        end_row();
        cell = unknown("\\begin{" + name + "} without \\end");
        break;
      }
      if (s_[pos_] == '&') {
        ++pos_;
        end_cell();
      } else if (at("\\\\")) {
        pos_ += 2;
        end_row();
        skip_spaces();
        gap = at("[");
        if (gap) pos_ = std::min(s_.find(']', pos_), s_.size() - 1) + 1;
      } else if (at_command("end")) {
        pos_ += 4;
        const std::string_view closing = braced_text();
        // A last \\ before \end starts no row.
        if (!(cell.empty() && cell_count == 0 && !rows.empty())) end_row();
        if (closing != name) cell = unknown("\\end{" + std::string(closing) + "}");
        break;
      } else {
        cell += stray();
      }
    }
    // aligned's equations are set in display style, as TeX sets them; a matrix's cells in text style.
    std::string out = element("mtable", rows,
                              aligned  ? "class=\"aligned\" displaystyle=\"true\""
                              : matrix ? "class=\"matrix\""
                                       : "");
    if (!aligned && !matrix) out = unknown("\\begin{" + name + "}") + out;
    if (!fences.empty())
      out = element("mrow", concat({element("mo", fences.substr(0, 1)), out, element("mo", fences.substr(1, 1))}));
    return out + cell;  // cell: what an unmatched \end left to say
  }

  std::string_view s_;
  std::vector<std::string>* unknown_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  bool upright_ = false;  // inside \mathrm
};

}  // namespace

std::string latex_to_mathml(std::string_view latex, bool display, std::vector<std::string>* unknown) {
  Converter converter(latex, unknown);
  return element("math", converter.run(), display ? "display=\"block\"" : "");
}

}  // namespace linkage
