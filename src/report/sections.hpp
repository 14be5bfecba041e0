#pragma once
// The order of a worked solution, shared by the text, LaTeX and Markdown writers: the
// title, the inputs, the derivation groups, each selected case, and (with two or more
// cases) the table of how closely they agree.
#include <string>

#include "report/derivation.hpp"
#include "report/worked_solution.hpp"

namespace linkage {

/// Calls the writer's section functions in order and returns its text. `Writer` has
/// title(), inputs(), derivation_group(const DerivationGroup&), one_case(const
/// CaseSolution&), agreement() and text().
template <class Writer>
[[nodiscard]] std::string write_sections(Writer& writer, const WorkedSolution& worked) {
  writer.title();
  writer.inputs();
  for (const DerivationGroup& group : derivation(worked)) writer.derivation_group(group);
  for (const CaseSolution& c : worked.cases) writer.one_case(c);
  if (!worked.agreement.empty()) writer.agreement();
  return writer.text();
}

}  // namespace linkage
