#pragma once
// `linkage solve --format json`: one object with "parameters", "state", "derived" (the
// keys of the spec's example.json) and "cases".
#include <string>

#include "report/worked_solution.hpp"

namespace linkage {

/// The JSON document, pretty-printed, numbers in shortest round-trip form.
[[nodiscard]] std::string json_report(const WorkedSolution& w);

}  // namespace linkage
