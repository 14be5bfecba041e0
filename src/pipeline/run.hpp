#pragma once
// A simulation as a lesson's steps (and the commands) describe it: its inputs, how it
// integrates, and on what mechanism; a time-series figure of several runs; the columns of
// a table comparing runs.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "core/angle_unit.hpp"
#include "integrate/simulation_options.hpp"
#include "model/inputs.hpp"
#include "model/mechanism_toml.hpp"  // kDefaultMechanism, with default_mechanism_settings
#include "symbolic/system.hpp"

namespace linkage {

/// A mechanism (a shipped name or a file's path) with its NAME=VALUE settings applied in
/// order and its loops closed: built once when the lesson is read, shared by the steps
/// and runs that use it.
struct BuiltMechanism {
  std::string spec;
  std::vector<std::string> settings;
  std::shared_ptr<const sym::System> system;
  GiNaC::exmap initial;  // generalized coordinates and rates, loops closed
  // Named as the homework's interface names it (its inputs, flags and CSV columns): by
  // the file's [aliases], x1 for 1.x, F_x for P.force_x; else by the file's own keys.
  bool aliased = false;

  /// `key` (a column's or a coordinate's) under the names this mechanism goes by.
  [[nodiscard]] std::string named(const std::string& key) const {
    return aliased ? system->mechanism().aliased(key) : key;
  }
  /// Its trajectory columns (mechanism_columns), each under `named` for lookups and headers.
  [[nodiscard]] std::vector<MechanismColumn> named_columns() const;
};

/// The mechanism `spec` (a shipped name or a file) with `settings` (NAME=VALUE) applied in
/// order, errors naming `origin`, its loops closed; `aliased`: named by its [aliases].
[[nodiscard]] std::shared_ptr<const BuiltMechanism> build_mechanism(const std::string& spec,
                                                                    const std::vector<std::string>& settings,
                                                                    const std::string& origin, bool aliased = false);
/// The default mechanism's named inputs as its settings ("L=0.3", "1.x=1", ... every input
/// given, so a run does not depend on the file's defaults).
[[nodiscard]] std::vector<std::string> default_mechanism_settings(const Inputs& inputs);

/// One simulation: the inputs it starts from and how it integrates.
struct Run {
  std::string label;   // legend and table name
  std::string series;  // runs with the same series form one curve in a cost plot
  Inputs inputs;
  SimulationOptions options;
  // On a mechanism (empty: the homework, whose inputs are settings of two-blocks.toml):
  // its spec and the settings in effect (earlier set steps', the step's `set`, the
  // entry's `set`); the system built from them (always set).
  std::string mechanism;
  std::vector<std::string> settings;
  std::shared_ptr<const BuiltMechanism> built;
};

/// A time-series figure: quantities against time (or another quantity) for some runs.
struct Figure {
  // The mechanism's trajectory columns, under the names the run's mechanism goes by.
  std::vector<MechanismColumn> y;
  MechanismColumn x;  // t unless given
  bool log_x = false, log_y = false;
  bool equal_axes = false;            // plot steps: x and y at one scale (a path keeps its shape)
  bool difference = false;            // plot steps: each run after the first as abs(run - first run)
  AngleUnit angles = AngleUnit::rad;  // plot steps: angles and angular rates in rad or deg
  std::string title;
  double every = 0;  // s between samples
  int width = 900, height = 600;
};

/// Columns of a compare table.
enum class CompareColumn { final_error, energy_error, constraint_error, steps, rejected, rhs_evaluations, run_time };
inline constexpr std::array<std::string_view, 7> kCompareColumnNames{
    "final_error", "energy_error", "constraint_error", "steps", "rejected", "rhs_evaluations", "run_time"};

}  // namespace linkage
