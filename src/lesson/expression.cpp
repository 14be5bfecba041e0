#include "lesson/expression.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "lesson/suggest.hpp"

namespace linkage::lesson {
namespace {

struct Function {
  std::string_view name;
  int arity;
  double (*apply)(double, double);
};

constexpr std::array<Function, 15> kFunctions{{
    {"sin", 1, [](double a, double) { return std::sin(a); }},
    {"cos", 1, [](double a, double) { return std::cos(a); }},
    {"tan", 1, [](double a, double) { return std::tan(a); }},
    {"asin", 1, [](double a, double) { return std::asin(a); }},
    {"acos", 1, [](double a, double) { return std::acos(a); }},
    {"atan", 1, [](double a, double) { return std::atan(a); }},
    {"atan2", 2, [](double a, double b) { return std::atan2(a, b); }},
    {"sqrt", 1, [](double a, double) { return std::sqrt(a); }},
    {"abs", 1, [](double a, double) { return std::fabs(a); }},
    {"exp", 1, [](double a, double) { return std::exp(a); }},
    {"log", 1, [](double a, double) { return std::log(a); }},
    {"log10", 1, [](double a, double) { return std::log10(a); }},
    {"hypot", 2, [](double a, double b) { return std::hypot(a, b); }},
    {"min", 2, [](double a, double b) { return std::fmin(a, b); }},
    {"max", 2, [](double a, double b) { return std::fmax(a, b); }},
}};

// A nesting level holds at most four operands waiting for their operator (a call's first
// argument, the left sides of + and *, the base of ^), so the evaluation stack of an
// expression within the nesting bound never holds more than this.
constexpr int kMaxStack = 4 * (kMaxNesting + 1) + 1;

class Parser {
 public:
  Parser(std::string_view text, const std::string& origin, std::vector<Expression::Node>& out)
      : text_(text), origin_(origin), out_(out) {}

  void parse() {
    skip_space();
    if (pos_ == text_.size()) fail("the expression is empty");
    expr();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(text_.substr(pos_, 1)) + "'");
  }

 private:
  void expr() {
    term();
    for (;;) {
      skip_space();
      if (accept('+')) {
        term();
        emit(Expression::Op::add, 2);
      } else if (accept('-')) {
        term();
        emit(Expression::Op::subtract, 2);
      } else
        return;
    }
  }
  void term() {
    unary();
    for (;;) {
      skip_space();
      if (accept('*')) {
        unary();
        emit(Expression::Op::multiply, 2);
      } else if (accept('/')) {
        unary();
        emit(Expression::Op::divide, 2);
      } else
        return;
    }
  }
  void unary() {
    skip_space();
    if (accept('-')) {
      const NestingLevel level = deeper();
      unary();
      emit(Expression::Op::negate, 1);
      return;
    }
    if (accept('+')) {
      const NestingLevel level = deeper();
      unary();
      return;
    }
    power();
  }
  void power() {
    primary();
    skip_space();
    if (accept('^')) {
      const NestingLevel level = deeper();
      unary();
      emit(Expression::Op::power, 2);
    }
  }
  void primary() {
    skip_space();
    if (pos_ == text_.size()) fail("the expression ends too early");
    const char c = text_[pos_];
    if (accept('(')) {
      const NestingLevel level = deeper();
      expr();
      expect(')');
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("unexpected '" + std::string(1, c) + "'");
  }
  void number() {
    double value = 0;
    const char* first = text_.data() + pos_;
    const auto [ptr, ec] = std::from_chars(first, text_.data() + text_.size(), value);
    if (ec != std::errc() || !std::isfinite(value)) fail("'" + std::string(first, ptr) + "' is not a number");
    pos_ += static_cast<std::size_t>(ptr - first);
    out_.push_back({Expression::Op::number, value, 0, 0});
    grow(1);
  }
  void name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
    const std::string_view word = text_.substr(start, pos_ - start);
    skip_space();
    if (accept('(')) return call(word, start);
    if (const auto index = find_quantity(word)) {
      out_.push_back({Expression::Op::quantity, 0, *index, 0});
      grow(1);
      return;
    }
    std::vector<std::string_view> names;
    for (const auto& q : kQuantities) names.push_back(q.name);
    std::string message = "unknown name '" + std::string(word) + "' at character " + std::to_string(start + 1);
    if (auto close = closest_match(word, names)) message += " (did you mean '" + std::string(*close) + "'?)";
    throw Error::input(origin_ + ": " + message + "; names: " + join(names));
  }
  void call(std::string_view word, std::size_t start) {
    const Function* f = nullptr;
    for (const auto& candidate : kFunctions)
      if (candidate.name == word) f = &candidate;
    if (f == nullptr) {
      std::vector<std::string_view> names;
      for (const auto& candidate : kFunctions) names.push_back(candidate.name);
      std::string message = "unknown function '" + std::string(word) + "' at character " + std::to_string(start + 1);
      if (auto close = closest_match(word, names)) message += " (did you mean '" + std::string(*close) + "'?)";
      throw Error::input(origin_ + ": " + message + "; functions: " + join(names));
    }
    const NestingLevel level = deeper();
    int args = 0;
    const auto arity_error = [&] {
      fail(std::string(f->name) + " takes " + std::to_string(f->arity) + " argument" + (f->arity == 1 ? "" : "s") +
           ", got " + std::to_string(args));
    };
    do {
      expr();
      // Checked as they come, so a long list cannot pile up operands.
      if (++args > f->arity) arity_error();
      skip_space();
    } while (accept(','));
    expect(')');
    if (args != f->arity) arity_error();
    out_.push_back({Expression::Op::call, 0, static_cast<std::size_t>(f - kFunctions.data()), args});
    grow(1 - args);
  }
  void emit(Expression::Op op, int args) {
    out_.push_back({op, 0, 0, args});
    grow(1 - args);
  }
  // Parentheses, calls, signs and powers recurse: a bound keeps hostile text from
  // exhausting the stack. Returned as a prvalue, so the level lasts the caller's scope.
  // Called just after the character that opens the level, which the error points at.
  [[nodiscard]] NestingLevel deeper() {
    if (nesting_ + 1 > kMaxNesting) {
      --pos_;
      fail(too_deep());
    }
    return NestingLevel(nesting_);
  }
  void grow(int delta) {
    depth_ += delta;
    if (depth_ > kMaxStack) fail(too_deep());  // cannot happen within the nesting bound; kept as a guard
  }
  static std::string too_deep() {
    return "the expression is nested more than " + std::to_string(kMaxNesting) +
           " levels deep (each parenthesis, call, sign and ^ is a level)";
  }
  bool accept(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    skip_space();
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw Error::input(origin_ + ": " + what + " at character " + std::to_string(pos_ + 1) + " of '" +
                       excerpt(text_, pos_) + "'");
  }

  std::string_view text_;
  const std::string& origin_;
  std::vector<Expression::Node>& out_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  int nesting_ = 0;
};

}  // namespace

Expression Expression::parse(std::string_view text, const std::string& origin) {
  Expression e;
  e.text_ = std::string(text);
  Parser(e.text_, origin, e.program_).parse();
  return e;
}

double Expression::evaluate(const QuantityValues& values) const {
  std::array<double, kMaxStack + 1> stack{};
  int top = 0;  // number of values on the stack
  for (const Node& n : program_) {
    switch (n.op) {
      case Op::number:
        stack[static_cast<std::size_t>(top++)] = n.number;
        break;
      case Op::quantity:
        stack[static_cast<std::size_t>(top++)] = values[n.index];
        break;
      case Op::negate:
        stack[static_cast<std::size_t>(top - 1)] = -stack[static_cast<std::size_t>(top - 1)];
        break;
      case Op::call: {
        const Function& f = kFunctions[n.index];
        const double a = stack[static_cast<std::size_t>(top - n.args)];
        const double b = n.args == 2 ? stack[static_cast<std::size_t>(top - 1)] : 0.0;
        top -= n.args;
        stack[static_cast<std::size_t>(top++)] = f.apply(a, b);
        break;
      }
      default: {
        const double b = stack[static_cast<std::size_t>(--top)];
        double& a = stack[static_cast<std::size_t>(top - 1)];
        switch (n.op) {
          case Op::add:
            a += b;
            break;
          case Op::subtract:
            a -= b;
            break;
          case Op::multiply:
            a *= b;
            break;
          case Op::divide:
            a /= b;
            break;
          case Op::power:
            a = std::pow(a, b);
            break;
          default:
            break;
        }
      }
    }
  }
  return stack[0];
}

bool Expression::is_constant() const {
  for (const Node& n : program_)
    if (n.op == Op::quantity) return false;
  return true;
}

const QuantityInfo* Expression::single_quantity() const {
  if (program_.size() == 1 && program_[0].op == Op::quantity) return &kQuantities[program_[0].index];
  return nullptr;
}

}  // namespace linkage::lesson
