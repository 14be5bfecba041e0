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

#include "core/angle_unit.hpp"
#include "integrate/mechanism_columns.hpp"
#include "integrate/simulation.hpp"
#include "model/inputs.hpp"
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
};

/// One simulation: the inputs it starts from and how it integrates.
struct Run {
  std::string label;   // legend and table name
  std::string series;  // runs with the same series form one curve in a cost plot
  Inputs inputs;
  SimulationOptions options;
  // On a mechanism (null: the homework): its spec, the settings in effect (earlier set
  // steps', the step's `set`, the entry's `set`) and the system built from them.
  std::string mechanism;
  std::vector<std::string> settings;
  std::shared_ptr<const BuiltMechanism> built;
};

/// A time-series figure: quantities against time (or another quantity) for some runs.
struct Figure {
  std::vector<std::size_t> y;  // series indices
  std::size_t x = 0;           // series index ("t")
  // On a mechanism: its trajectory columns instead of the series.
  std::vector<MechanismColumn> mechanism_y;
  std::optional<MechanismColumn> mechanism_x;
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
