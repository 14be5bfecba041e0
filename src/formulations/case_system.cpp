#include "formulations/case_system.hpp"

#include <array>
#include <map>

#include "core/interrupt.hpp"
#include "model/joint_types.hpp"

namespace linkage {

namespace {

// Each unknown's terms of an expanded row: the sum of the terms holding it as a factor
// (rows are linear in the unknowns), so that its coefficient comes from those terms
// alone, the same as the coefficient in the whole row.
std::vector<GiNaC::exvector> terms_by_unknown(const GiNaC::ex& row,
                                              const std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less>& index) {
  std::vector<GiNaC::exvector> out(index.size());
  auto place = [&](const GiNaC::ex& term) {
    if (const auto it = index.find(term); it != index.end()) {
      out[it->second].push_back(term);
      return;
    }
    if (!GiNaC::is_a<GiNaC::mul>(term)) return;
    for (std::size_t k = 0; k < term.nops(); ++k)
      if (const auto it = index.find(term.op(k)); it != index.end()) out[it->second].push_back(term);
  };
  if (GiNaC::is_a<GiNaC::add>(row))
    for (std::size_t k = 0; k < row.nops(); ++k) place(row.op(k));
  else
    place(row);
  return out;
}

}  // namespace

CaseSystem linear_system(CaseId id, const std::vector<GiNaC::ex>& rows, const std::vector<GiNaC::symbol>& unknowns) {
  CaseSystem system;
  system.id = id;
  system.unknowns = unknowns;
  GiNaC::exmap zero;
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index;
  for (std::size_t k = 0; k < unknowns.size(); ++k) {
    zero[unknowns[k]] = 0;
    index[unknowns[k]] = k;
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    throw_if_interrupted();
    const GiNaC::ex row = sym::simplify_trig(rows[i]);
    const std::vector<GiNaC::exvector> terms = terms_by_unknown(row, index);
    std::vector<GiNaC::ex> a;
    a.reserve(unknowns.size());
    for (std::size_t k = 0; k < unknowns.size(); ++k)
      a.push_back(terms[k].empty() ? GiNaC::ex(0) : GiNaC::ex(GiNaC::add(terms[k])).coeff(unknowns[k], 1));
    system.A.push_back(std::move(a));
    // Keys that are symbols only: no_pattern looks each node up in the map instead of
    // matching it against every key (hundreds for a long chain), with the same result.
    system.B.push_back(GiNaC::expand(-row.subs(zero, GiNaC::subs_options::no_pattern)));
    system.labels.push_back(std::to_string(i + 1) + "." + std::to_string(case_number(id)));
  }
  return system;
}

CaseSystem derive_case(const sym::System& system, CaseId id) {
  switch (id) {
    case CaseId::maximal:
      return maximal_case(system);
    case CaseId::generalized:
      return generalized_case(system);
    case CaseId::reduced:
      return reduced_case(system);
  }
  return maximal_case(system);
}

std::string force_phrase(const sym::System& system) {
  const auto& joints = system.mechanism().joints;
  if (joints.size() == 1) return std::string(joint_type_name(joints[0].type)) + " force";
  return "joint forces";
}

std::string count_word(std::size_t n) {
  static constexpr std::array<const char*, 21> kWords{
      "no",       "one",     "two",     "three",     "four",     "five",     "six",
      "seven",    "eight",   "nine",    "ten",       "eleven",   "twelve",   "thirteen",
      "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"};
  return n < kWords.size() ? kWords[n] : std::to_string(n);
}

}  // namespace linkage
