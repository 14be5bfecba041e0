#pragma once
// GiNaC expressions as MATLAB/Octave or Python (NumPy) source, for the exported cases
// (code_export.hpp). Numbers are printed exactly: a rational as a/b (float division in
// both languages), one that is a decimal of the mechanism file (3/10) as that decimal
// (0.3), a float in its shortest round-trip form.
// Terms and factors print in an order fixed by their text and the symbol table's ranks,
// never by GiNaC's internal order (which follows symbol creation), and a sum factor takes
// the sign its text prefers, so the same expressions print the same code in any process.
#include <ginac/ginac.h>

#include <map>
#include <string>

#include "symbolic/symbols.hpp"

namespace linkage {

enum class CodeLanguage { matlab, python };

class CodePrinter {
 public:
  /// `names`: the identifier of every symbol an expression may hold; `table` gives the
  /// ranks that order a product's factors.
  CodePrinter(CodeLanguage language, const sym::SymbolTable& table,
              std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names);

  /// The expression as source; throws std::logic_error on a symbol without a name or a
  /// construct neither language is given (a complex number, an unknown function).
  [[nodiscard]] std::string operator()(const GiNaC::ex& e) const;

 private:
  struct Text {
    std::string text;
    int level;  // precedence of its outermost operator: 1 sum, 2 product or sign, 3 power, 4 atom
  };
  [[nodiscard]] Text print(const GiNaC::ex& e) const;
  [[nodiscard]] Text print_number(const GiNaC::numeric& n) const;
  [[nodiscard]] Text print_sum(const GiNaC::ex& e, std::size_t* negatives = nullptr) const;
  /// A product's magnitude; `negative` says whether it is subtracted.
  [[nodiscard]] Text print_product(const GiNaC::numeric& coefficient, const GiNaC::exvector& factors,
                                   bool& negative) const;
  [[nodiscard]] Text signed_product(const GiNaC::numeric& coefficient, const GiNaC::exvector& factors) const;
  [[nodiscard]] std::string factor_text(const GiNaC::ex& factor, bool& flipped) const;
  [[nodiscard]] Text print_power(const GiNaC::ex& base, const GiNaC::ex& exponent) const;
  [[nodiscard]] Text print_function(const GiNaC::ex& e) const;
  [[nodiscard]] std::string wrapped(const GiNaC::ex& e, int level) const;
  [[nodiscard]] int rank(const GiNaC::ex& factor) const;

  CodeLanguage language_;
  const sym::SymbolTable& table_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names_;
};

}  // namespace linkage
