#include "report/formula.hpp"

#include <cmath>

#include "core/number_format.hpp"
#include "report/notation.hpp"

namespace linkage {

using expr::Style;

std::string_view Symbol::spelling(Style style) const {
  return style == Style::unicode ? unicode : style == Style::ascii ? ascii : latex;
}

std::string format_number(double value, Style style, int digits) {
  std::string text = digits > 0 ? format_significant(value, digits) : format_roundtrip(value);
  if (text == "-0") text = "0";
  const auto e = text.find('e');
  if (style != Style::latex || e == std::string::npos) return text;
  const std::string mantissa = text.substr(0, e);
  const int exponent = std::stoi(text.substr(e + 1));
  const std::string power = "10^{" + std::to_string(exponent) + "}";
  return mantissa == "1" ? power : mantissa == "-1" ? "-" + power : mantissa + " \\times " + power;
}

namespace {

enum class Op { symbol, integer, add, sub, mul, div, square, sin, cos };

// Binding strength of what a node prints, for parentheses.
enum class Prec { sum = 1, product = 2, power = 3, atom = 4 };

}  // namespace

struct Formula::Node {
  Op op;
  Symbol symbol;
  int integer = 0;
  std::shared_ptr<const Node> a, b;
};

namespace {

using NodePtr = std::shared_ptr<const Formula::Node>;

struct Printer {
  Style style;
  Spelling spelling;
  int digits;

  [[nodiscard]] bool text() const { return style != Style::latex; }
  [[nodiscard]] bool substituted() const { return spelling == Spelling::substituted; }

  // The printed form of a symbol or number, and how strongly it binds.
  // `bare`: no parentheses around a negative value (it is already inside some).
  [[nodiscard]] std::pair<std::string, Prec> leaf(const Formula::Node& n, bool bare = false) const {
    if (n.op == Op::integer) return {std::to_string(n.integer), Prec::atom};
    if (!substituted()) return {std::string(n.symbol.spelling(style)), Prec::atom};
    const std::string number = format_number(n.symbol.value, style, n.symbol.exact ? 0 : digits);
    // A negative value always gets parentheses: "0.15 - (-0.11)", "(-0.3)²".
    if (n.symbol.value < 0 && number != "0" && !bare) return {paren(number), Prec::atom};
    const bool scaled = style == Style::latex && number.find("\\times") != std::string::npos;
    return {number, scaled ? Prec::product : Prec::atom};
  }

  [[nodiscard]] std::string paren(const std::string& inner) const {
    return text() ? "(" + inner + ")" : "\\left(" + inner + "\\right)";
  }

  [[nodiscard]] std::string operand(const NodePtr& n, Prec needed) const {
    auto [text_out, prec] = print(*n);
    return prec < needed ? paren(text_out) : text_out;
  }

  [[nodiscard]] std::string sum_operator(const char* op) const {
    return concat({std::string_view(&kBreakMark, 1), " ", op, " "});
  }

  [[nodiscard]] std::pair<std::string, Prec> function(const char* name, const NodePtr& arg) const {
    if (style == Style::ascii) {
      const std::string inner = arg->op == Op::symbol ? leaf(*arg, true).first : print(*arg).first;
      return {concat({name, "(", inner, ")"}), Prec::atom};
    }
    const std::string head = style == Style::latex ? std::string("\\") + name + " " : std::string(name) + " ";
    return {head + operand(arg, Prec::atom), Prec::product};
  }

  [[nodiscard]] std::pair<std::string, Prec> print(const Formula::Node& n) const {
    switch (n.op) {
      case Op::symbol:
      case Op::integer:
        return leaf(n);
      case Op::add:
        return {print(*n.a).first + sum_operator("+") + operand(n.b, Prec::sum), Prec::sum};
      case Op::sub:
        return {print(*n.a).first + sum_operator("-") + operand(n.b, Prec::product), Prec::sum};
      case Op::mul: {
        const char* times = !substituted()            ? " "
                            : style == Style::unicode ? " × "
                            : style == Style::ascii   ? " * "
                                                      : " \\times ";
        return {operand(n.a, Prec::product) + times + operand(n.b, Prec::product), Prec::product};
      }
      case Op::div:
        if (style == Style::latex) return {"\\frac{" + print(*n.a).first + "}{" + print(*n.b).first + "}", Prec::atom};
        return {operand(n.a, Prec::product) + " / " + operand(n.b, Prec::power), Prec::product};
      case Op::square: {
        std::string base = operand(n.a, Prec::atom);
        if (style == Style::latex && base.find('^') != std::string::npos) base = "{" + base + "}";
        return {base + (style == Style::unicode ? "²" : "^2"), Prec::power};
      }
      case Op::sin:
        return function("sin", n.a);
      case Op::cos:
        return function("cos", n.a);
    }
    return {};
  }
};

double evaluate(const Formula::Node& n) {
  switch (n.op) {
    case Op::symbol:
      return n.symbol.value;
    case Op::integer:
      return n.integer;
    case Op::add:
      return evaluate(*n.a) + evaluate(*n.b);
    case Op::sub:
      return evaluate(*n.a) - evaluate(*n.b);
    case Op::mul:
      return evaluate(*n.a) * evaluate(*n.b);
    case Op::div:
      return evaluate(*n.a) / evaluate(*n.b);
    case Op::square: {
      const double v = evaluate(*n.a);
      return v * v;
    }
    case Op::sin:
      return std::sin(evaluate(*n.a));
    case Op::cos:
      return std::cos(evaluate(*n.a));
  }
  return 0;
}

}  // namespace

Formula::Formula(const Symbol& symbol) : node_(std::make_shared<const Node>(Node{Op::symbol, symbol, 0, {}, {}})) {}

Formula Formula::integer(int n) { return Formula(std::make_shared<const Node>(Node{Op::integer, {}, n, {}, {}})); }

double Formula::eval() const { return evaluate(*node_); }

std::string Formula::print(Style style, Spelling spelling, int digits) const {
  return Printer{style, spelling, digits}.print(*node_).first;
}

namespace {
Formula::Node binary(Op op, const std::shared_ptr<const Formula::Node>& a,
                     const std::shared_ptr<const Formula::Node>& b) {
  return Formula::Node{op, {}, 0, a, b};
}
}  // namespace

Formula operator+(const Formula& a, const Formula& b) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::add, a.node_, b.node_)));
}
Formula operator-(const Formula& a, const Formula& b) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::sub, a.node_, b.node_)));
}
Formula operator*(const Formula& a, const Formula& b) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::mul, a.node_, b.node_)));
}
Formula operator/(const Formula& a, const Formula& b) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::div, a.node_, b.node_)));
}
Formula square(const Formula& a) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::square, a.node_, nullptr)));
}
Formula sin(const Formula& a) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::sin, a.node_, nullptr)));
}
Formula cos(const Formula& a) {
  return Formula(std::make_shared<const Formula::Node>(binary(Op::cos, a.node_, nullptr)));
}

}  // namespace linkage
