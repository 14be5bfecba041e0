#pragma once
// The form an expression is compiled in: lengths, coordinates and constants substituted
// by their expressions, in turn, and expanded where one form is wanted whatever GiNaC's
// term order.
#include <ginac/ginac.h>

#include <initializer_list>
#include <vector>

namespace linkage::eval {

/// `e` with each map substituted in turn (no patterns), then expanded if `expanded`. A
/// sum goes term by term with a check for a signal between terms: a long chain's sums
/// (its angular momentum, its B) take seconds whole. Exact coefficients make the sum of
/// the terms' results the same expression as the result of the whole.
[[nodiscard]] GiNaC::ex substitute_in_turn(const GiNaC::ex& e, std::initializer_list<const GiNaC::exmap*> maps,
                                           bool expanded);

/// Empties `expressions` last first with a signal check between them (a vector's
/// destructor cannot check): a long chain's compiled outputs take seconds to free.
void free_checking(std::vector<GiNaC::ex>& expressions);

}  // namespace linkage::eval
