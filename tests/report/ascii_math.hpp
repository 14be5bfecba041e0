#pragma once
// A tiny recursive-descent evaluator for the ASCII spelling of the printed formulas and
// matrix entries, so the tests can check that what is printed means what is computed:
//   expr   := term (('+' | '-') term)*
//   term   := unary (('*' | '/' | juxtaposition) unary)*      "m D sin(th1)" = m*D*sin(th1)
//   unary  := '-' unary | power
//   power  := atom ('^' integer)?
//   atom   := number | name | ('sin' | 'cos') '(' expr ')' | '(' expr ')'
// Names are letters, digits and '_', then optionally "^C"-style superscript letters and
// trailing primes: m, th1'^2 (th1' squared), I_zz^C, x1'', Fx. Unknown names, stray
// characters and trailing input throw std::runtime_error.
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace linkage::test {

class AsciiMath {
 public:
  explicit AsciiMath(std::map<std::string, double> symbols) : symbols_(std::move(symbols)) {}

  /// The value of `text` with the symbols bound.
  [[nodiscard]] double eval(std::string_view text) {
    text_ = text;
    pos_ = 0;
    const double value = expr();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return value;
  }

 private:
  std::map<std::string, double> symbols_;
  std::string_view text_;
  std::size_t pos_ = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(what + " at column " + std::to_string(pos_) + " of \"" + std::string(text_) + "\"");
  }
  void skip_space() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
  }
  [[nodiscard]] char peek() {
    skip_space();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  [[nodiscard]] static bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
  // Whether the next token can start an operand, for juxtaposition.
  [[nodiscard]] bool starts_operand() {
    const char c = peek();
    return c == '(' || c == '.' || name_char(c);
  }

  double expr() {
    double value = term();
    for (char c = peek(); c == '+' || c == '-'; c = peek()) {
      ++pos_;
      value = c == '+' ? value + term() : value - term();
    }
    return value;
  }
  double term() {
    double value = unary();
    for (;;) {
      const char c = peek();
      if (c == '*' || c == '/') {
        ++pos_;
        value = c == '*' ? value * unary() : value / unary();
      } else if (starts_operand()) {
        value *= unary();
      } else {
        return value;
      }
    }
  }
  double unary() {
    if (peek() == '-') {
      ++pos_;
      return -unary();
    }
    return power();
  }
  double power() {
    const double base = atom();
    if (peek() != '^') return base;
    ++pos_;
    const double exponent = atom();
    if (exponent != 2) fail("only squares are printed");
    return base * base;
  }
  double atom() {
    const char c = peek();
    if (c == '(') {
      ++pos_;
      const double value = expr();
      if (peek() != ')') fail("missing ')'");
      ++pos_;
      return value;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '.') return number();
    if (!name_char(c)) fail("expected an operand");
    return named();
  }
  double number() {
    std::size_t end = pos_;
    while (end < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[end])) != 0 || text_[end] == '.'))
      ++end;
    if (end < text_.size() && text_[end] == 'e') {  // exponent: e-05, e+22
      ++end;
      if (end < text_.size() && (text_[end] == '-' || text_[end] == '+')) ++end;
      while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end])) != 0) ++end;
    }
    const double value = std::stod(std::string(text_.substr(pos_, end - pos_)));
    pos_ = end;
    return value;
  }
  double named() {
    std::size_t end = pos_;
    while (end < text_.size() && name_char(text_[end])) ++end;
    // A superscript letter belongs to the name (I_zz^C); "^2" is a power.
    while (end + 1 < text_.size() && text_[end] == '^' && std::isalpha(static_cast<unsigned char>(text_[end + 1])) != 0)
      end += 2;
    while (end < text_.size() && text_[end] == '\'') ++end;
    const std::string name(text_.substr(pos_, end - pos_));
    pos_ = end;
    if ((name == "sin" || name == "cos") && peek() == '(') {
      const double arg = atom();
      return name == "sin" ? std::sin(arg) : std::cos(arg);
    }
    const auto it = symbols_.find(name);
    if (it == symbols_.end()) fail("unknown symbol '" + name + "'");
    return it->second;
  }
};

}  // namespace linkage::test
