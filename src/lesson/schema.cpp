#include "lesson/schema.hpp"

#include <array>
#include <vector>

#include "pipeline/render_options.hpp"

namespace linkage::lesson {
namespace {

constexpr std::array<KeySpec, 7> kLessonKeys{{
    {"title", "string", "(required)", "The lesson's title, printed first and used as the document's heading."},
    {"description", "string", "\"\"", "A Markdown paragraph printed under the title; may quote values as {{NAME}}."},
    {"config", "string", "none",
     "A TOML file of inputs (as `linkage solve --config`), relative to the lesson file; "
     "[parameters] and [state] override it."},
    {"parameters", "table", "the spec's example", "Any of L, w, b, m, g (m, m, m, kg, m/s^2)."},
    {"state", "table", "the spec's example",
     "Any of x1, y1, theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot (m, rad, m/s, rad/s)."},
    {"mechanism", "string", "the homework",
     "A shipped mechanism (`linkage mechanisms`) or a mechanism file, relative to the lesson file, that the "
     "render steps draw, and whose parameters, definitions and inertias {{...}} and answers may use; a render "
     "step's own `mechanism` overrides it for that step."},
    {"step", "array of tables", "(required)", "The steps, in order: one [[step]] table each."},
}};

constexpr std::array<KeySpec, 3> kCommonKeys{{
    {"kind", "string", "(required)",
     "What the step does: say, set, pause, exercise, solve, simulate, render, plot or compare."},
    {"heading", "string", "none", "A section heading printed before the step."},
    {"mechanism", "string", "the lesson's",
     "Work on this mechanism (a shipped name or a file relative to the lesson) in this step instead of the "
     "lesson's; it starts from the file's values (earlier set steps change the lesson's mechanism only)."},
}};

constexpr std::array<KeySpec, 10> kRunKeys{{
    {"set", "list of strings", "none",
     "With a mechanism: NAME=VALUE settings of its parameters or initial coordinates, as --set "
     "([\"a=0.12\", \"2.theta=0.3\"]), after those of earlier set steps."},
    {"case", "integer", "3", "The formulation: 1 (eight DAEs), 2 (six equations) or 3 (four equations)."},
    {"integrator", "string", "\"dop853\"",
     "euler, symplectic-euler, rk4, dopri5, dop853 or gauss-legendre (as `linkage simulate`)."},
    {"dt", "number", "0.001", "Step size in s (fixed-step methods), or the first step of adaptive ones."},
    {"rtol", "number", "1e-10", "Relative tolerance of adaptive methods."},
    {"atol", "number", "1e-10", "Absolute tolerance of adaptive methods."},
    {"duration", "number", "10", "Simulated time in s."},
    {"stabilize", "string", "\"none\"", "Case 1 constraint stabilization: none, baumgarte or projection."},
    {"baumgarte_alpha", "number", "10", "Baumgarte damping gain, 1/s."},
    {"baumgarte_beta", "number", "10", "Baumgarte stiffness gain, 1/s."},
}};

constexpr std::array<KeySpec, 2> kRunEntryKeys{{
    {"label", "string", "from the options", "The run's name in tables and legends."},
    {"series", "string", "the integrator", "Runs with the same series are joined into one curve of a cost plot."},
}};

constexpr std::array<KeySpec, 2> kSayKeys{{
    {"text", "string", "(text or file)",
     "Markdown, wrapped to the terminal; {{NAME}} or {{EXPRESSION : DIGITS}} "
     "is replaced by the value at the current inputs."},
    {"file", "string", "(text or file)", "Read the Markdown from this file (relative to the lesson file) instead."},
}};

constexpr std::array<KeySpec, 1> kSetKeys{{
    {"set", "list of strings", "none",
     "With a mechanism: NAME=VALUE settings of its parameters or initial coordinates for the following steps."},
}};

constexpr std::array<KeySpec, 1> kPauseKeys{{
    {"prompt", "string", "\"Press Enter to continue\"", "What --step shows while it waits."},
}};

constexpr std::array<KeySpec, 9> kExerciseKeys{{
    {"question", "string", "(required)", "Markdown, as a say step's text."},
    {"answer", "string or number", "(required)",
     "The answer: preferably an expression the tool computes, e.g. \"I_zz_P\" or \"m * D^2\"."},
    {"unit", "string", "the quantity's unit", "Unit printed with the answer (default: the named quantity's)."},
    {"tolerance", "number", "none", "Absolute tolerance of a right answer."},
    {"relative_tolerance", "number", "0.01 (without tolerance)", "Relative tolerance of a right answer."},
    {"attempts", "integer", "3", "Tries with --step before the answer is shown (1 to 10)."},
    {"digits", "integer", "6", "Significant digits of the printed answer (1 to 17)."},
    {"hint", "string", "none", "Markdown shown after a wrong try."},
    {"explanation", "string", "none", "Markdown shown with the answer."},
}};

constexpr std::array<KeySpec, 2> kSolveKeys{{
    {"case", "integer, \"all\" or list of integers", "\"all\"", "Which cases to solve: 1, 2, 3, [1, 3] or \"all\"."},
    {"show", "list of strings", "all parts",
     "Which parts to print: inputs, inertia, constraints, energy, symbolic, numeric, solution, residual, comparison."},
}};

constexpr std::array<KeySpec, 3> kSimulateKeys{{
    {"trajectory", "string", "none", "Write the samples to this CSV file in the output folder."},
    {"every", "number", "duration / 100", "Seconds between trajectory rows."},
    {"columns", "list of strings", "all",
     "Trajectory columns, as `linkage simulate --columns` (t, x1, ..., F_x, F_y, "
     "energy, momentum_x, ..., constraint_velocity_error)."},
}};

/// A render step's keys: its output and caption, every option of `linkage render`
/// (pipeline/render_options), and its timed captions.
std::span<const KeySpec> render_keys() {
  static const std::vector<KeySpec> keys = [] {
    std::vector<KeySpec> out{
        {"out", "string", "(required)", "The file in the output folder: .mp4 (a clip), .png, .svg or .pdf (a still)."},
        {"caption", "string", "none", "Text under the clip or still in the lesson document."},
    };
    for (const RenderOption& o : render_options()) out.push_back({o.name, o.type, o.default_text, o.doc});
    out.push_back({"captions", "array of tables", "none",
                   "Timed words under the picture: [{at = 2.0, text = \"...\"}, ...], each shown from `at` s until "
                   "the next."});
    return out;
  }();
  return keys;
}

constexpr std::array<KeySpec, 2> kCaptionKeys{{
    {"at", "number", "(required)", "The time in s the caption appears; later than the one before."},
    {"text", "string", "(required)", "The words, wrapped to the frame's width."},
}};

constexpr std::array<KeySpec, 12> kPlotKeys{{
    {"out", "string", "(required)", "Base file name: writes OUT.png and OUT.svg in the output folder."},
    {"caption", "string", "none", "Text under the figure in the lesson document."},
    {"title", "string", "none", "The figure's title."},
    {"y", "string or list of strings", "(required)", "Series drawn against x, one curve per run and series."},
    {"x", "string", "\"t\"", "The series along the horizontal axis."},
    {"log_x", "boolean", "false", "Logarithmic horizontal axis."},
    {"log_y", "boolean", "false", "Logarithmic vertical axis (non-positive values are left out)."},
    {"difference", "boolean", "false",
     "Draw each run after the first as abs(run - first run), sample by sample: how far nearby runs part."},
    {"angles", "string", "\"rad\"",
     "Unit of plotted angles and angular rates, on either axis: rad or deg (deg, deg/s), as render --angles."},
    {"every", "number", "duration / 400", "Seconds between samples."},
    {"size", "string", "\"900x600\"", "Figure size WxH in pixels (PNG) and points (SVG)."},
    {"runs", "array of tables", "one run of the step's options",
     "The runs: each a table of run keys, label and series."},
}};

constexpr std::array<KeySpec, 10> kCompareKeys{{
    {"out", "string", "(required)",
     "Base file name: writes OUT.csv (the table) and, with a plot, OUT.png and OUT.svg."},
    {"caption", "string", "none", "Text under the table in the lesson document."},
    {"title", "string", "none", "The figure's title."},
    {"runs", "array of tables", "(required)",
     "The configurations compared: each a table of run keys, label and series."},
    {"columns", "list of strings", "all",
     "Table columns: final_error, energy_error, constraint_error, steps, rejected, rhs_evaluations, run_time."},
    {"plot", "string", "none", "A series drawn against time for every run (e.g. \"constraint_position_error\")."},
    {"log_y", "boolean", "true", "Logarithmic vertical axis for the plot."},
    {"every", "number", "duration / 400", "Seconds between samples for the errors and the plot."},
    {"cost_plot", "boolean", "false",
     "Also draw final error against right-hand-side evaluations (log-log), "
     "to OUT-cost.png and OUT-cost.svg."},
    {"size", "string", "\"900x600\"", "Figure size WxH."},
}};

struct KindEntry {
  std::string_view name;
  std::string_view summary;
  std::span<const KeySpec> keys;
  bool run_keys;
};

const std::array<KindEntry, 9>& kinds() {
  static const std::array<KindEntry, 9> table{{
      {"say", "A Markdown paragraph, wrapped to the terminal.", kSayKeys, false},
      {"set", "Changes inputs (any of the thirteen names, or a mechanism's settings) for the following steps.",
       kSetKeys, false},
      {"pause", "Waits for Enter with --step; ignored otherwise.", kPauseKeys, false},
      {"exercise", "A question with a numeric answer: asked and checked with --step, answered otherwise.",
       kExerciseKeys, false},
      {"solve", "The worked solution of `linkage solve`, showing the chosen parts.", kSolveKeys, false},
      {"simulate", "Runs the motion and prints a summary; optionally writes the trajectory.", kSimulateKeys, true},
      {"render", "A clip or a still, with any option of the render command.", render_keys(), true},
      {"plot", "Series against time for several runs, to PNG and SVG.", kPlotKeys, true},
      {"compare", "Several runs side by side in a table, optionally with plots.", kCompareKeys, true},
  }};
  return table;
}

const KindEntry* find_kind(std::string_view kind) {
  for (const KindEntry& k : kinds())
    if (k.name == kind) return &k;
  return nullptr;
}

}  // namespace

std::span<const KeySpec> lesson_keys() { return kLessonKeys; }
std::span<const KeySpec> common_step_keys() { return kCommonKeys; }
std::span<const KeySpec> run_keys() { return kRunKeys; }
std::span<const KeySpec> run_entry_keys() { return kRunEntryKeys; }
std::span<const KeySpec> caption_entry_keys() { return kCaptionKeys; }

std::span<const KeySpec> step_keys(std::string_view kind) {
  const KindEntry* k = find_kind(kind);
  return k != nullptr ? k->keys : std::span<const KeySpec>{};
}

bool takes_run_keys(std::string_view kind) {
  const KindEntry* k = find_kind(kind);
  return k != nullptr && k->run_keys;
}

std::string_view step_summary(std::string_view kind) {
  const KindEntry* k = find_kind(kind);
  return k != nullptr ? k->summary : std::string_view{};
}

}  // namespace linkage::lesson
