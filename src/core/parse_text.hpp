#pragma once
// Reading the values people type (a flag's value, a lesson key's text): one reading of a
// number and of a comma list for every command and file, with one wording of errors.
#include <string>
#include <vector>

namespace linkage {

/// A whole-string finite double ("+1.5" and "1e-3" too); otherwise Error::invalid
/// (`setting`, ...) saying what is wrong, with `unit` naming what it counts.
[[nodiscard]] double parse_number(const std::string& text, const std::string& setting, const std::string& unit);

/// "a,b,,c" -> {"a", "b", "", "c"} (an empty item stays, for its reader to refuse); "" -> {};
/// a comma inside parentheses stays in its item: "t,a=atan2(y, x)" -> {"t", "a=atan2(y, x)"}.
[[nodiscard]] std::vector<std::string> split_commas(const std::string& list);

}  // namespace linkage
