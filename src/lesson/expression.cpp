#include "lesson/expression.hpp"

#include <ginac/ginac.h>

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "report/quotable_values.hpp"
#include "symbolic/expression_reader.hpp"
#include "symbolic/system.hpp"

namespace linkage::lesson {
namespace {
constexpr std::size_t kLongestNameList = 600;  // characters
}  // namespace

struct Expression::Value {
  GiNaC::ex expression;
  GiNaC::exmap at;
};

Expression Expression::parse(std::string_view text, const std::string& origin, const QuotableValues* names) {
  Expression e;
  e.text_ = std::string(text);
  // Every name a symbol while reading; then each one the text uses is its value (so a
  // case is worked out only when the text quotes it).
  GiNaC::symtab table;
  if (names != nullptr)
    for (const std::string& name : names->names()) table[name] = GiNaC::symbol(name);
  if (!table.contains("pi")) table["pi"] = GiNaC::Pi;
  // A mechanism's names run to hundreds (each coordinate's rates and share of each mode):
  // an unknown one lists the undotted and those beside the nearest.
  sym::ExpressionNames known{table};
  known.longest_valid_list = kLongestNameList;
  const GiNaC::ex read = sym::read_expression(text, origin, known);
  if (GiNaC::is_a<GiNaC::symbol>(read)) e.single_name_ = GiNaC::ex_to<GiNaC::symbol>(read).get_name();
  GiNaC::exmap at;
  try {  // a case worked out now may be singular at these values
    for (auto it = read.preorder_begin(); it != read.preorder_end(); ++it)
      if (GiNaC::is_a<GiNaC::symbol>(*it) && names != nullptr)
        at[*it] = names->value(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
  } catch (const Error& error) {
    throw error.rephrased(origin + ": " + error.what());
  }
  // The values substituted, so a mechanism's exact parameters stay exact; where that meets
  // a pole (1/(x1 - 1) at x1 = 1), evaluated in doubles to inf, which the text refuses.
  // Checked in doubles first: GiNaC's subs leaks what it built when it throws pole_error.
  GiNaC::ex value = read;
  bool pole = false;
  try {
    pole = !std::isfinite(sym::evaluate(read, at));
  } catch (const std::logic_error&) {  // a name without a value: subs leaves it
  }
  if (!pole) try {
      value = read.subs(at);
    } catch (const std::exception&) {  // a pole that rounding hid from the doubles
    }
  e.value_ = std::make_shared<const Value>(Value{value, at});
  return e;
}

double Expression::evaluate() const { return sym::evaluate(value_->expression, value_->at); }

}  // namespace linkage::lesson
