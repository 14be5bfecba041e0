#pragma once
// The one expression language of mechanism files, lesson {{...}} text and exercise answers,
// read into GiNaC over a table of names:
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary ('^' unary)?
//   primary := number | name | function '(' expr (',' expr)* ')' | '(' expr ')'
//   name    := word ('.' word)*   e.g. "m", "B.force_x", "2.theta" (digits '.' a letter
//              begin a name, unless it is unknown and the letter starts an exponent: "2.e5")
// Numbers are exact (0.08 is 8/100), so expanding leaves no float residue. Our own reader
// rather than GiNaC's parser, which reads 2*-3+1 as -4, crashes on sin(), gives no position
// and accepts I, Euler and {lists}. Bounds: kMaxExpressionLength characters, kMaxNesting
// levels (each parenthesis, call, sign and ^), and an exponent a number from -kMaxExponent to
// kMaxExponent, a name or a group without ^ (GiNaC computes numeric powers exactly, so
// 9^9^9 must never get there).
#include <ginac/ginac.h>

#include <string>
#include <string_view>
#include <vector>

namespace linkage::sym {

inline constexpr std::size_t kMaxExpressionLength = 500;
inline constexpr int kMaxExponent = 12;
/// The most significant digits of a decimal: what a double holds (std::numeric_limits<double>::max_digits10).
inline constexpr std::size_t kMaxDecimalDigits = 17;

/// The functions, as error messages list them: sin cos tan asin acos atan atan2 sqrt exp log
/// abs (GiNaC's), hypot(a, b) read as sqrt(a^2 + b^2) and log10(x) as log(x)/log(10).
[[nodiscard]] const std::vector<std::string>& expression_functions();

/// The functions a mechanism's equations can carry (printed, compiled, exported): the
/// others are for lessons until the printers and exporters spell them.
[[nodiscard]] const std::vector<std::string>& equation_functions();

/// The names an expression may use: each maps to a GiNaC symbol or constant (pi -> Pi).
/// `note` follows the list of valid names in an unknown-name error; `functions`, when
/// given, the subset of expression_functions() allowed.
struct ExpressionNames {
  const GiNaC::symtab& symbols;
  std::string_view note = {};
  const std::vector<std::string>* functions = nullptr;
  /// Names known but not allowed here (the state's, outside loads): refused with
  /// `refused_note` as the valid part rather than as unknown.
  const GiNaC::symtab* refused = nullptr;
  std::string_view refused_note = {};
  /// Past this many characters the valid names of an unknown-name error are cut to the
  /// undotted ones and those beside the nearest ("3.P." for "3.P.z"), and "N more".
  std::size_t longest_valid_list = std::string_view::npos;
};

/// Reads `text`. Throws Error::input, one line: "ORIGIN: problem at character N of 'TEXT'"
/// with, for an unknown name or function, the nearest known one and the valid ones.
/// `origin` is where the text is ("FILE:LINE:COLUMN" or "FILE:LINE:COLUMN: answer").
[[nodiscard]] GiNaC::ex read_expression(std::string_view text, std::string_view origin, const ExpressionNames& names);

}  // namespace linkage::sym
