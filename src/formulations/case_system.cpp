#include "formulations/case_system.hpp"

#include <array>

namespace linkage {

CaseSystem linear_system(CaseId id, const std::vector<GiNaC::ex>& rows, const std::vector<GiNaC::symbol>& unknowns) {
  CaseSystem system;
  system.id = id;
  system.unknowns = unknowns;
  GiNaC::exmap zero;
  for (const GiNaC::symbol& u : unknowns) zero[u] = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const GiNaC::ex row = sym::simplify_trig(rows[i]);
    std::vector<GiNaC::ex> a;
    a.reserve(unknowns.size());
    for (const GiNaC::symbol& u : unknowns) a.push_back(row.coeff(u, 1));
    system.A.push_back(std::move(a));
    system.B.push_back(GiNaC::expand(-row.subs(zero)));
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
  if (joints.size() == 1) return joints[0].type == JointType::pin ? "pin force" : "slider force";
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
