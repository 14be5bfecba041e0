#pragma once
// `linkage solve --mechanism FILE` as text, in the layout of the homework's worked
// solution: inputs and definitions, inertia, each joint's constraint at three levels,
// each body's forces, Newton-Euler per body, then each case and the agreement table.
#include <string>

#include "report/mechanism_solution.hpp"
#include "report/report_options.hpp"

namespace linkage {

[[nodiscard]] std::string mechanism_text(const MechanismSolution& solution, const ReportOptions& options);

}  // namespace linkage
