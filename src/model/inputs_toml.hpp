#pragma once
// Inputs from a parsed TOML table: a --config file, or a lesson's parameter table.
#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "model/inputs.hpp"

namespace linkage {

/// Applies every key of `table` (in file order), read by TableReader: an unknown key (with
/// the closest valid one), a value that is not a number, or a non-finite number is an
/// Error::input "file:line:column: CONTEXT: problem". `context` names the table: "config"
/// for a --config file, "[parameters]" or "[state]" for a lesson's.
void apply_toml(Inputs& inputs, const toml::table& table, const std::string& file,
                const std::string& context = "inputs");

/// Parses a TOML file, turning a syntax error into Error::input with file:line:column
/// and an unreadable file into Error::input naming `origin`.
[[nodiscard]] toml::table parse_toml_file(const std::string& path, const std::string& origin);

/// Parses TOML text read from `path` (a file name or a built-in's name) as
/// parse_toml_file does: a syntax error or an overly nested key is Error::input with
/// path:line:column.
[[nodiscard]] toml::table parse_toml_text(std::string_view toml_text, const std::string& path,
                                          const std::string& origin);

}  // namespace linkage
