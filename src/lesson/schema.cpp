#include "lesson/schema.hpp"

#include <array>
#include <vector>

#include "pipeline/render_options.hpp"

namespace linkage::lesson {
namespace {

constexpr std::array<KeySpec, 7> kLessonKeys{{
    {"title", "string", "(required)"},
    {"description", "string", "\"\""},
    {"config", "string", "none"},
    {"parameters", "table", "the spec's example"},
    {"state", "table", "the spec's example"},
    {"mechanism", "string", "the homework"},
    {"step", "array of tables", "(required)"},
}};

constexpr std::array<KeySpec, 3> kCommonKeys{{
    {"kind", "string", "(required)"},
    {"heading", "string", "none"},
    {"mechanism", "string", "the lesson's"},
}};

constexpr std::array<KeySpec, 11> kRunKeys{{
    {"set", "list of strings", "none"},
    {"case", "integer", "3"},
    {"integrator", "string", "\"dop853\""},
    {"dt", "number", "0.001"},
    {"rtol", "number", "1e-10"},
    {"atol", "number", "1e-10"},
    {"duration", "number", "10"},
    {"stabilize", "string", "\"none\""},
    {"baumgarte_alpha", "number", "10"},
    {"baumgarte_beta", "number", "10"},
    {"evaluator", "string", "\"auto\""},
}};

constexpr std::array<KeySpec, 2> kRunEntryKeys{{
    {"label", "string", "from the options"},
    {"series", "string", "the integrator"},
}};

constexpr std::array<KeySpec, 2> kSayKeys{{
    {"text", "string", "(text or file)"},
    {"file", "string", "(text or file)"},
}};

constexpr std::array<KeySpec, 1> kSetKeys{{
    {"set", "list of strings", "none"},
}};

constexpr std::array<KeySpec, 1> kPauseKeys{{
    {"prompt", "string", "\"Press Enter to continue\""},
}};

constexpr std::array<KeySpec, 9> kExerciseKeys{{
    {"question", "string", "(required)"},
    {"answer", "string or number", "(required)"},
    {"unit", "string", "the quantity's unit"},
    {"tolerance", "number", "none"},
    {"relative_tolerance", "number", "0.01 (without tolerance)"},
    {"attempts", "integer", "3"},
    {"digits", "integer", "6"},
    {"hint", "string", "none"},
    {"explanation", "string", "none"},
}};

constexpr std::array<KeySpec, 2> kSolveKeys{{
    {"case", "integer, \"all\" or list of integers", "\"all\""},
    {"show", "list of strings", "all parts"},
}};

constexpr std::array<KeySpec, 3> kModesKeys{{
    {"at_initial", "boolean", "false"},
    {"digits", "integer", "6"},
    {"verify", "boolean", "false"},
}};

constexpr std::array<KeySpec, 3> kSimulateKeys{{
    {"trajectory", "string", "none"},
    {"every", "number", "duration / 100"},
    {"columns", "list of strings", "all"},
}};

/// A render step's keys: its output and caption, every option of `linkage render`
/// (pipeline/render_options), a mode's, and its timed captions.
std::span<const KeySpec> render_keys() {
  static const std::vector<KeySpec> keys = [] {
    std::vector<KeySpec> out{
        {"out", "string", "(required)"},
        {"caption", "string", "none"},
    };
    for (const RenderOption& o : render_options()) out.push_back({o.name, o.type, o.default_text});
    // A mode of small vibration (render --mode, --modes-sheet; issue 26).
    out.push_back({"mode", "integer", "none"});
    out.push_back({"amplitude", "number", "0.1"});
    out.push_back({"nonlinear", "boolean", "false"});
    out.push_back({"modes_sheet", "boolean", "false"});
    out.push_back({"captions", "array of tables", "none"});
    return out;
  }();
  return keys;
}

constexpr std::array<KeySpec, 3> kCaptionKeys{{
    {"at", "number", "(required)"},
    {"text", "string", "(required)"},
    {"until", "number", "the next caption's at"},
}};

constexpr std::array<KeySpec, 13> kPlotKeys{{
    {"out", "string", "(required)"},
    {"caption", "string", "none"},
    {"title", "string", "none"},
    {"y", "string or list of strings", "(required)"},
    {"x", "string", "\"t\""},
    {"log_x", "boolean", "false"},
    {"log_y", "boolean", "false"},
    {"equal_axes", "boolean", "false"},
    {"difference", "boolean", "false"},
    {"angles", "string", "\"rad\""},
    {"every", "number", "duration / 400"},
    {"size", "string", "\"900x600\""},
    {"runs", "array of tables", "one run of the step's options"},
}};

constexpr std::array<KeySpec, 10> kCompareKeys{{
    {"out", "string", "(required)"},
    {"caption", "string", "none"},
    {"title", "string", "none"},
    {"runs", "array of tables", "(required)"},
    {"columns", "list of strings", "all"},
    {"plot", "string", "none"},
    {"log_y", "boolean", "true"},
    {"every", "number", "duration / 400"},
    {"cost_plot", "boolean", "false"},
    {"size", "string", "\"900x600\""},
}};

struct KindEntry {
  std::string_view name;
  std::span<const KeySpec> keys;
  bool run_keys;
};

const std::array<KindEntry, 10>& kinds() {
  static const std::array<KindEntry, 10> table{{
      {"say", kSayKeys, false},
      {"set", kSetKeys, false},
      {"pause", kPauseKeys, false},
      {"exercise", kExerciseKeys, false},
      {"solve", kSolveKeys, false},
      {"modes", kModesKeys, false},
      {"simulate", kSimulateKeys, true},
      {"render", render_keys(), true},
      {"plot", kPlotKeys, true},
      {"compare", kCompareKeys, true},
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

}  // namespace linkage::lesson
