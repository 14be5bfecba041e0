#pragma once
// The simulation options shared by commands that run the motion (render; simulate has
// the same flags): --case, --integrator, --dt, --rtol, --atol, --stabilize and the
// Baumgarte gains, --evaluator, with the same help and checks.
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <string_view>

#include "integrate/simulation_options.hpp"

namespace linkage::cli {

struct SimulationFlags {
  std::string which_case = "3";
  std::string integrator = "dop853";
  std::map<std::string_view, std::string> numbers;  // by kNumberOptions' name: "dt", "rtol", ...
  std::string stabilize = "none";
  std::string evaluator = "auto";
  CLI::Option* integrator_option = nullptr;
  CLI::Option* dt_option = nullptr;
  CLI::Option* stabilize_option = nullptr;
  CLI::Option* rtol_option = nullptr;
  CLI::Option* atol_option = nullptr;
  CLI::Option* alpha_option = nullptr;
  CLI::Option* beta_option = nullptr;
};

/// Adds the flags to `sub` in a "Simulation" group.
void add_simulation_flags(CLI::App* sub, SimulationFlags& flags);
/// The options the flags give, with `duration`; validated (Error::input naming the flag).
[[nodiscard]] SimulationOptions resolve_simulation_flags(const SimulationFlags& flags, double duration);
/// Notes on stderr for flags that do nothing in this configuration (e.g. --stabilize
/// with Case 3, --rtol with a fixed-step integrator). `kept_constraints`: for a mechanism
/// file, how many constraint rows the case keeps; -1 for the homework. `kinematic`: the
/// drivers take every degree of freedom, so nothing is integrated and one note names the
/// integrator's flags given.
void note_ignored_simulation_flags(const SimulationFlags& flags, const SimulationOptions& options,
                                   int kept_constraints = -1, bool kinematic = false);

}  // namespace linkage::cli
