#include "evaluate/substitute.hpp"

#include "core/interrupt.hpp"

namespace linkage::eval {

GiNaC::ex substitute_in_turn(const GiNaC::ex& e, std::initializer_list<const GiNaC::exmap*> maps, bool expanded) {
  const auto one = [&](const GiNaC::ex& term) {
    GiNaC::ex out = term;
    for (const GiNaC::exmap* map : maps) out = out.subs(*map, GiNaC::subs_options::no_pattern);
    return expanded ? GiNaC::expand(out) : out;
  };
  if (!GiNaC::is_a<GiNaC::add>(e)) return one(e);
  GiNaC::exvector terms;
  terms.reserve(e.nops());
  for (const GiNaC::ex& term : e) {
    throw_if_interrupted();
    terms.push_back(one(term));
  }
  return GiNaC::add(terms);
}

void free_checking(std::vector<GiNaC::ex>& expressions) {
  while (!expressions.empty()) {
    throw_if_interrupted();
    expressions.pop_back();
  }
}

}  // namespace linkage::eval
