#pragma once
// --mechanism NAME|FILE and --set NAME=VALUE, shared by solve, simulate and render: which
// mechanism a command works on, with its parameters and initial coordinates set.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/input_options.hpp"
#include "model/mechanism.hpp"

namespace linkage::cli {

struct MechanismOptions {
  std::string mechanism;
  CLI::Option* mechanism_option = nullptr;
  std::vector<std::string> settings;  // --set NAME=VALUE, in order
  /// Whether --mechanism was given.
  [[nodiscard]] bool chosen() const { return !mechanism.empty(); }
};

/// Adds --mechanism and --set to `sub`.
void add_mechanism_options(CLI::App* sub, MechanismOptions& options);

/// The mechanism a command works on: a file or shipped name with --mechanism, else the
/// homework with its flags and --config (validated as the homework's inputs always are);
/// then --set in order. The homework's flags with --mechanism are an error naming --set.
[[nodiscard]] Mechanism chosen_mechanism(const MechanismOptions& options, const InputOptions& inputs);

}  // namespace linkage::cli
