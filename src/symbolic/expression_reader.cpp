#include "symbolic/expression_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>

#include "core/character_text.hpp"
#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/name_match.hpp"

namespace linkage::sym {
namespace {

using GiNaC::ex;

struct Function {
  std::string_view name;
  std::size_t arity;
  ex (*apply)(const GiNaC::exvector&);
};

const std::array<Function, 13> kFunctions{{
    {"sin", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::sin(a[0]); }},
    {"cos", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::cos(a[0]); }},
    {"tan", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::tan(a[0]); }},
    {"asin", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::asin(a[0]); }},
    {"acos", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::acos(a[0]); }},
    {"atan", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::atan(a[0]); }},
    {"atan2", 2, [](const GiNaC::exvector& a) -> ex { return GiNaC::atan2(a[0], a[1]); }},
    {"sqrt", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::sqrt(a[0]); }},
    {"exp", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::exp(a[0]); }},
    {"log", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::log(a[0]); }},
    {"abs", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::abs(a[0]); }},
    {"hypot", 2, [](const GiNaC::exvector& a) -> ex { return GiNaC::sqrt(GiNaC::pow(a[0], 2) + GiNaC::pow(a[1], 2)); }},
    {"log10", 1, [](const GiNaC::exvector& a) -> ex { return GiNaC::log(a[0]) / GiNaC::log(ex(10)); }},
}};

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool word(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

class Reader {
 public:
  Reader(std::string_view text, std::string_view origin, const ExpressionNames& names)
      : text_(text), prefix_(origin.empty() ? std::string() : std::string(origin) + ": "), names_(names) {}

  // Problems are reported in reading order: text nested too deep fails at its 65th level
  // however long, text too long where reading passes the limit.
  ex read() {
    skip_space();
    if (pos_ == text_.size()) fail(pos_, "the expression is empty");
    const ex e = sum();
    skip_space();
    if (pos_ != text_.size()) fail(pos_, "unexpected " + describe_character(text_, pos_));
    if (text_.size() > kMaxExpressionLength) too_long();
    return e;
  }

 private:
  ex sum() {
    ex e = product();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if (accept('+')) {
        const ex b = product();
        e = guard(at, [&] { return e + b; });
      } else if (accept('-')) {
        const ex b = product();
        e = guard(at, [&] { return e - b; });
      } else {
        return e;
      }
    }
  }
  ex product() {
    ex e = unary();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if (accept('*')) {
        const ex b = unary();
        e = guard(at, [&] { return e * b; });
      } else if (accept('/')) {
        const ex b = unary();
        e = guard(at, [&] { return e / b; });
      } else {
        return e;
      }
    }
  }
  ex unary() {
    skip_space();
    const std::size_t at = pos_;
    if (accept('-')) {
      const NestingLevel level = deeper(at);
      return -unary();
    }
    if (accept('+')) {
      const NestingLevel level = deeper(at);
      return unary();
    }
    return power();
  }
  ex power() {
    const ex base = primary();
    skip_space();
    const std::size_t at = pos_;
    if (!accept('^')) return base;
    if (in_exponent_ > 0) refuse_power(at);
    const NestingLevel level = deeper(at);
    ++in_exponent_;
    const ex exponent = unary();
    --in_exponent_;
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
      const auto& k = GiNaC::ex_to<GiNaC::numeric>(exponent);
      if (!k.is_real() || GiNaC::abs(k) > kMaxExponent) refuse_power(at);
    }
    return guard(at, [&] { return GiNaC::pow(base, exponent); });
  }
  ex primary() {
    skip_space();
    if (pos_ > kMaxExpressionLength) too_long();  // every operand starts here: reading stops soon after
    if (pos_ == text_.size()) fail(pos_, "the expression ends too early");
    const char c = text_[pos_];
    const std::size_t at = pos_;
    if (accept('(')) {
      const NestingLevel level = deeper(at);
      const ex e = sum();
      expect(')');
      return e;
    }
    if (digit(c) && numeric_body_name()) return name();
    if (digit(c) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_') return name();
    fail(pos_, "unexpected " + describe_character(text_, pos_));  // the whole character: '−' (U+2212), not a byte
  }
  // Digits [. digits] [e [+-] digits], as an exact fraction.
  ex number() {
    const std::size_t start = pos_;
    std::string digits;
    long scale = 0;  // value = digits * 10^-scale
    bool point = false;
    while (pos_ < text_.size() && (digit(text_[pos_]) || (text_[pos_] == '.' && !point))) {
      if (text_[pos_] == '.') {
        point = true;
      } else {
        digits += text_[pos_];
        if (point) ++scale;
      }
      ++pos_;
    }
    if (digits.empty()) fail(start, "'.' is not a number");
    if (pos_ + 1 < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E') &&
        (digit(text_[pos_ + 1]) ||
         ((text_[pos_ + 1] == '-' || text_[pos_ + 1] == '+') && pos_ + 2 < text_.size() && digit(text_[pos_ + 2])))) {
      std::size_t end = pos_ + 1;
      if (text_[end] == '-' || text_[end] == '+') ++end;
      while (end < text_.size() && digit(text_[end])) ++end;
      const long exponent = std::strtol(std::string(text_.substr(pos_ + 1, end - pos_ - 1)).c_str(), nullptr, 10);
      if (exponent > 300 || exponent < -300)
        fail(start, "the number '" + std::string(text_.substr(start, end - start)) + "' is out of range",
             "; valid: powers of ten from -300 to 300");
      scale -= exponent;
      pos_ = end;
    }
    // More digits than a double holds would be kept exactly here and then lost, in different
    // places, when the equations are evaluated in double precision: refused instead.
    if (pos_ > kMaxExpressionLength) too_long();  // the length is the first thing wrong
    const std::size_t first = digits.find_first_not_of('0');
    const std::size_t last = digits.find_last_not_of('0');
    if (first != std::string::npos && last - first + 1 > kMaxDecimalDigits)
      fail(start,
           "the number '" + std::string(text_.substr(start, pos_ - start)) + "' has " +
               std::to_string(last - first + 1) + " significant digits, more than double precision holds",
           "; valid: at most " + std::to_string(kMaxDecimalDigits) + " significant digits");
    const GiNaC::numeric whole(digits.c_str());
    const GiNaC::numeric ten(10);
    return scale >= 0 ? whole / GiNaC::pow(ten, scale) : whole * GiNaC::pow(ten, -scale);
  }
  // Digits '.' a letter or '_' begin a dotted name whose body is numeric ("2.theta",
  // "2.theta_ddot"), unless the letter starts an exponent ("2.e5", "2.E-3") and the name is
  // not known: "2.5" and "2.e5" stay numbers.
  [[nodiscard]] bool numeric_body_name() const {
    std::size_t j = pos_;
    while (j < text_.size() && digit(text_[j])) ++j;
    if (j + 1 >= text_.size() || text_[j] != '.') return false;
    const char c = text_[j + 1];
    if (std::isalpha(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
    std::size_t end = j + 1;
    while (end < text_.size() && word(text_[end])) ++end;
    if (names_.symbols.count(std::string(text_.substr(pos_, end - pos_))) > 0) return true;
    const bool exponent = (c == 'e' || c == 'E') && j + 2 < text_.size() &&
                          (digit(text_[j + 2]) || ((text_[j + 2] == '-' || text_[j + 2] == '+') &&
                                                   j + 3 < text_.size() && digit(text_[j + 3])));
    return !exponent;
  }
  // A name, dotted as BODY.NAME ("B.force_x", "2.theta") when a '.' and a letter follow.
  ex name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && word(text_[pos_])) ++pos_;
    while (pos_ + 1 < text_.size() && text_[pos_] == '.' &&
           (std::isalpha(static_cast<unsigned char>(text_[pos_ + 1])) != 0 || text_[pos_ + 1] == '_')) {
      ++pos_;
      while (pos_ < text_.size() && word(text_[pos_])) ++pos_;
    }
    const std::string w(text_.substr(start, pos_ - start));
    skip_space();
    if (w.find('.') == std::string::npos && accept('(')) return call(w, start);
    if (const auto it = names_.symbols.find(w); it != names_.symbols.end()) return it->second;
    if (names_.refused != nullptr && names_.refused->count(w) > 0)
      fail(start, "the state name '" + w + "' is not allowed here", "; valid: " + std::string(names_.refused_note));
    std::vector<std::string> valid, candidates;
    for (const auto& [n, value] : names_.symbols) {
      candidates.push_back(n);
      if (n != "pi") valid.push_back(n);
    }
    std::string listed = join_names(valid, "(none)");
    if (listed.size() > names_.longest_valid_list) {
      const std::optional<std::string> nearest = closest_name(w, candidates);
      const std::string near = nearest ? nearest->substr(0, nearest->rfind('.') + 1) : std::string();
      std::vector<std::string> some;
      for (const std::string& n : valid)
        if (n.find('.') == std::string::npos ||
            (!near.empty() && n.rfind(near, 0) == 0 && n.find('.', near.size()) == std::string::npos))
          some.push_back(n);
      listed = join_names(some) + " and " + std::to_string(valid.size() - some.size()) + " more";
    }
    std::string valid_text = did_you_mean(w, candidates) + "; valid: " + listed;
    if (!names_.note.empty()) valid_text.append(" ").append(names_.note);
    fail(start, "unknown name '" + w + "'", valid_text);
  }
  ex call(const std::string& w, std::size_t start) {
    const std::vector<std::string>& allowed = names_.functions != nullptr ? *names_.functions : expression_functions();
    const Function* f = nullptr;
    for (const Function& candidate : kFunctions)
      if (candidate.name == w) f = &candidate;
    if (f == nullptr)
      fail(start, "unknown function '" + w + "'", did_you_mean(w, allowed) + "; valid: " + join_names(allowed));
    if (std::find(allowed.begin(), allowed.end(), w) == allowed.end())
      fail(start, "the function '" + w + "' is not available here", "; valid: " + join_names(allowed));
    const NestingLevel level = deeper(start);
    GiNaC::exvector args;
    const auto arity_error = [&] {
      fail(pos_, std::string(f->name) + " takes " + std::to_string(f->arity) + " argument" +
                     (f->arity == 1 ? "" : "s") + ", got " + std::to_string(args.size()));
    };
    do {
      args.push_back(sum());
      if (args.size() > f->arity) arity_error();  // as they come: a long list cannot pile up
      skip_space();
    } while (accept(','));
    expect(')');
    if (args.size() != f->arity) arity_error();
    return guard(start, [&] { return f->apply(args); });
  }

  // GiNaC evaluates as it builds: 1/0, log(0) and tan(pi/2) throw where they are written.
  template <typename F>
  ex guard(std::size_t at, F&& make) {
    try {
      return make();
    } catch (const std::exception& e) {
      const std::string what = e.what();
      if (what.find("division by zero") != std::string::npos)
        fail(at, "division by zero", "; valid: an expression finite at the given values");
      fail(at, "no value (" + what + ")", "; valid: an expression finite at the given values");
    }
  }
  // Parentheses, calls, signs and powers recurse: a bound keeps hostile text from
  // exhausting the stack. The level lasts the caller's scope.
  [[nodiscard]] NestingLevel deeper(std::size_t at) {
    if (nesting_ + 1 > kMaxNesting)
      fail(at, "the expression is nested more than " + std::to_string(kMaxNesting) +
                   " levels deep (each parenthesis, call, sign and ^ is a level)");
    return NestingLevel(nesting_);
  }
  [[noreturn]] void refuse_power(std::size_t at) const {
    fail(at, "the power is too high or nested",
         "; valid: exponents from -" + std::to_string(kMaxExponent) + " to " + std::to_string(kMaxExponent) +
             ", a name, or a group without ^");
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
    if (!accept(c)) fail(pos_, std::string("expected '") + c + "'");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) ++pos_;
  }
  [[noreturn]] void too_long() const {
    throw Error::input(prefix_ + "the expression '" + excerpt(text_, 0) + "' is " + std::to_string(text_.size()) +
                       " characters long; valid: at most " + std::to_string(kMaxExpressionLength));
  }
  [[noreturn]] void fail(std::size_t at, const std::string& what, const std::string& valid = {}) const {
    if (at > kMaxExpressionLength) too_long();
    throw Error::input(prefix_ + what + " at character " + std::to_string(at + 1) + " of '" + excerpt(text_, at) + "'" +
                       valid);
  }

  std::string_view text_;
  std::string prefix_;
  const ExpressionNames& names_;
  std::size_t pos_ = 0;
  int nesting_ = 0;
  int in_exponent_ = 0;
};

}  // namespace

const std::vector<std::string>& expression_functions() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Function& f : kFunctions) out.emplace_back(f.name);
    return out;
  }();
  return names;
}

const std::vector<std::string>& equation_functions() {
  static const std::vector<std::string> names{"sin", "cos", "tan", "sqrt", "exp", "log", "hypot", "log10"};
  return names;
}

ex read_expression(std::string_view text, std::string_view origin, const ExpressionNames& names) {
  return Reader(text, origin, names).read();
}

}  // namespace linkage::sym
