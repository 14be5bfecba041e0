#pragma once
// `linkage solve --format json`: one object with "parameters", "state", "derived" (the
// keys of the spec's example.json plus the angular momentum) and "cases", each with
// "case", "title", "unknowns", "A" (rows), "B", "solution", "recovered" (the unknowns
// the case eliminated, from solution_value), "residual", "condition_number" and
// "equations" (labels in row order); with two or more cases also "agreement" (the
// largest difference of each unknown between cases).
#include <nlohmann/json.hpp>
#include <string>

#include "report/worked_solution.hpp"

namespace linkage {

/// The JSON document, numbers in shortest round-trip form, laid out by json_layout.
[[nodiscard]] std::string json_report(const WorkedSolution& w);

/// Compact but readable JSON: 2-space indents, every array of scalars (a matrix row,
/// the unknowns) on one line, an object of scalars on one line when that fits in
/// 80 columns. Parses back to the same value as `value.dump()`.
[[nodiscard]] std::string json_layout(const nlohmann::ordered_json& value);

}  // namespace linkage
