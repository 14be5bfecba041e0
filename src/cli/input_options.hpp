#pragma once
// The parameter and state options shared by solve, simulate and render: one flag per
// symbol (--L ... --theta2-dot) and --config FILE; flags override the file.
#include <CLI/CLI.hpp>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/parse_text.hpp"
#include "model/inputs.hpp"

namespace linkage::cli {

struct InputOptions {
  std::string config;
  CLI::Option* config_option = nullptr;
  std::array<std::string, kInputKeys.size()> values;  // as typed, parsed after CLI11
  std::array<CLI::Option*, kInputKeys.size()> options{};
};

/// Adds --config and the thirteen symbol flags to `sub`, in an "Inputs" group.
void add_input_options(CLI::App* sub, InputOptions& options);
/// The defaults (the spec's example), overridden by --config, then by the flags;
/// validated. Throws Error::input naming the bad flag or file:line:column.
[[nodiscard]] Inputs resolve_inputs(const InputOptions& options);

/// The flag of a setting: "theta1_dot" -> "--theta1-dot".
[[nodiscard]] std::string flag_name(std::string_view setting);
/// An error as the command line says it: a setting's error names its flag.
[[nodiscard]] std::string describe(const Error& error);

}  // namespace linkage::cli
