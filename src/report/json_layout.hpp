#pragma once
// Compact but readable JSON for `linkage solve --format json`.
#include <nlohmann/json.hpp>
#include <string>

namespace linkage {

/// 2-space indents, every array of scalars (a matrix row, the unknowns) on one line, an
/// object of scalars on one line when that fits in 80 columns. Parses back to the same
/// value as `value.dump()`.
[[nodiscard]] std::string json_layout(const nlohmann::ordered_json& value);

}  // namespace linkage
