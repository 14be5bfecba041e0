#pragma once
// A lesson: a title, the inputs it starts from, and an ordered list of steps. Parsing
// validates the whole file (every key, type, range, name, expression and referenced
// file) before anything runs, and records for each step the inputs in effect when it
// runs, so running a range of steps (--only) keeps what earlier `set` steps made.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "integrate/simulation_options.hpp"
#include "lesson/expression.hpp"
#include "lesson/text_template.hpp"
#include "model/inputs.hpp"
#include "pipeline/render_options.hpp"
#include "pipeline/run.hpp"
#include "render/plot.hpp"
#include "render/settings.hpp"
#include "symbolic/system.hpp"

namespace linkage::lesson {

enum class StepKind { say, set, pause, exercise, solve, modes, simulate, render, plot, compare };
inline constexpr std::array<std::string_view, 10> kStepKindNames{"say",   "set",      "pause",  "exercise", "solve",
                                                                 "modes", "simulate", "render", "plot",     "compare"};
[[nodiscard]] constexpr std::string_view name(StepKind k) { return kStepKindNames[static_cast<std::size_t>(k)]; }

/// The parts of a worked solution a solve step can show, in the order they print (the
/// order of report's ReportPart).
enum class SolvePart { inputs, inertia, constraints, energy, symbolic, numeric, solution, residual, comparison };
inline constexpr std::array<std::string_view, 9> kSolvePartNames{
    "inputs", "inertia", "constraints", "energy", "symbolic", "numeric", "solution", "residual", "comparison"};

struct SayStep {
  TextTemplate text;
};
struct SetStep {
  std::vector<std::string> keys;      // the inputs this step sets, in file order
  std::vector<std::string> settings;  // on a mechanism: NAME=VALUE, in file order
  std::vector<std::string> changes;   // and each as "a = 0.08 m (was 0.06)"
};
struct PauseStep {
  std::string prompt;
};
struct ExerciseStep {
  TextTemplate question;
  Expression answer;
  std::string unit;
  std::optional<double> tolerance;  // absolute
  double relative_tolerance = 0.01;
  int attempts = 3;
  int digits = 6;
  TextTemplate hint;
  TextTemplate explanation;
};
struct SolveStep {
  std::vector<int> cases;
  std::array<bool, kSolvePartNames.size()> parts{};
};
/// `linkage modes` of the step's mechanism: its options.
struct ModesStep {
  bool at_initial = false;
  bool verify = false;
  int digits = 6;
};
struct SimulateStep {
  Run run;
  double every = 0;        // s between trajectory rows
  std::string trajectory;  // file in the output folder, empty for none
  // As `linkage simulate --columns`, named as run.built names them (x1 on the homework).
  std::vector<MechanismColumn> mechanism_columns;
};
struct RenderStep {
  std::string out;  // file in the output folder
  std::string caption;
  Run run;  // on run.built's mechanism (the homework's: two-blocks.toml)
  OutputKind kind = OutputKind::mp4;
  // The picture as render_options read it (the settings with the mechanism's title and the
  // equations shown, trails, ensemble, compare); --quality draft shrinks size and fps.
  RenderRequest request;
  int mode = 0;              // a mode drawn about the equilibrium (render --mode N); 0: the run's motion
  double amplitude = 0.1;    // the mode's largest coordinate's displacement, rad or m (--amplitude)
  bool nonlinear = false;    // the full equations started on the mode (--nonlinear)
  bool modes_sheet = false;  // out is every mode in one still (--modes-sheet)
};
struct PlotStep {
  std::string out;  // base name: out.png and out.svg
  std::string caption;
  std::vector<Run> runs;
  Figure figure;
};
struct CompareStep {
  std::string out;  // base name: out.csv, and out.png/.svg with a plot, out-cost.png/.svg
  std::string caption;
  std::vector<Run> runs;
  std::vector<CompareColumn> columns;
  double every = 0;            // s between samples of the errors (and the plot)
  std::optional<Figure> plot;  // a quantity over time for every run
  bool cost_plot = false;      // final error against right-hand-side evaluations
  std::string title;           // of the figures
  int width = 900, height = 600;
};

using StepBody = std::variant<SayStep, SetStep, PauseStep, ExerciseStep, SolveStep, ModesStep, SimulateStep, RenderStep,
                              PlotStep, CompareStep>;

struct Step {
  StepKind kind = StepKind::say;
  int number = 0;       // 1-based, as --only counts
  std::string where;    // "file:line:column" of the step's table
  std::string heading;  // optional section heading
  Inputs inputs;        // in effect when the step runs
  // The mechanism in effect (the step's own or the lesson's, with the settings of earlier
  // set steps); null for the homework.
  std::shared_ptr<const BuiltMechanism> mechanism;
  std::string canonical;  // every option of the step, canonically printed (cache key)
  StepBody body;
};

struct Lesson {
  std::filesystem::path file;
  std::string name;  // the file's stem, e.g. "06-numerical-example"
  std::string title;
  TextTemplate description;
  Inputs inputs;  // at the start
  std::vector<Step> steps;

  /// Every artifact file the lesson declares, relative to the output folder.
  [[nodiscard]] std::vector<std::string> artifacts() const;
};

/// Reads and validates a lesson; throws Error::input "FILE:LINE:COLUMN: problem; valid
/// choices" for the first problem found.
[[nodiscard]] Lesson parse_lesson(const std::filesystem::path& file);

/// The artifact files of one step (empty for steps that write none).
[[nodiscard]] std::vector<std::string> step_artifacts(const Step& step);

}  // namespace linkage::lesson
