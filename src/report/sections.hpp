#pragma once
// The order of a worked solution, shared by the text, LaTeX and Markdown writers: the
// title, the inputs, the derivation groups, each selected case, and (with two or more
// cases) the table of how closely they agree.
#include <string>

#include "report/derivation.hpp"
#include "report/worked_solution.hpp"

namespace linkage {

/// Calls the writer's section functions in order, for the parts `options` shows, and
/// returns its text. `Writer` has title(), inputs(), derivation_group(const
/// DerivationGroup&), one_case(const CaseSolution&) (which checks the per-case parts),
/// agreement() and text().
template <class Writer>
[[nodiscard]] std::string write_sections(Writer& writer, const WorkedSolution& worked, const ReportOptions& options) {
  writer.title();
  if (options.shows(ReportPart::inputs)) writer.inputs();
  for (const DerivationGroup& group : derivation(worked))
    if (options.shows(group.part)) writer.derivation_group(group);
  const bool case_parts = options.shows(ReportPart::symbolic) || options.shows(ReportPart::numeric) ||
                          options.shows(ReportPart::solution) || options.shows(ReportPart::residual);
  if (case_parts)
    for (const CaseSolution& c : worked.cases) writer.one_case(c);
  if (!worked.agreement.empty() && options.shows(ReportPart::comparison)) writer.agreement();
  return writer.text();
}

}  // namespace linkage
