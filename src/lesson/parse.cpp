// Reading and validating a lesson file (lesson.hpp). Everything is checked here, before
// any step runs: a lesson that does not validate renders nothing.
#include <algorithm>
#include <array>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <span>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/number_format.hpp"
#include "encode/video_writer.hpp"
#include "integrate/series.hpp"
#include "lesson/canonical.hpp"
#include "lesson/lesson.hpp"
#include "lesson/markdown.hpp"
#include "lesson/mechanism_render.hpp"
#include "lesson/schema.hpp"
#include "lesson/suggest.hpp"
#include "model/inputs_toml.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/panel_data.hpp"
#include "render/theme.hpp"
#include "report/mechanism_solution.hpp"
#include "scene/scene_builder.hpp"
#include "symbolic/system.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<KeySpec> concat(std::initializer_list<std::span<const KeySpec>> parts) {
  std::vector<KeySpec> out;
  for (auto part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

std::vector<std::string_view> input_names() {
  std::vector<std::string_view> out;
  for (const InputKey& k : kInputKeys) out.push_back(k.key);
  return out;
}

std::vector<std::string_view> series_names() {
  std::vector<std::string_view> out;
  for (const SeriesInfo& s : kSeries) out.push_back(s.name);
  return out;
}

std::vector<std::string_view> integrator_names() {
  std::vector<std::string_view> out;
  for (const IntegratorInfo& i : integrators()) out.push_back(i.name);
  return out;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

/// Each string of a list must be one of `choices`; returns their indices. Errors point
/// at the offending entry.
std::vector<std::size_t> choice_list(const TableReader& r, std::string_view key,
                                     const std::vector<std::string_view>& choices) {
  std::vector<std::size_t> out;
  const toml::node* n = r.node(key);
  if (n == nullptr) return out;
  const auto values = r.strings(key);  // type-checks
  const auto* array = n->as_array();
  for (std::size_t i = 0; i < values->size(); ++i) {
    const std::string& v = (*values)[i];
    const auto it = std::find(choices.begin(), choices.end(), v);
    if (it != choices.end()) {
      out.push_back(static_cast<std::size_t>(it - choices.begin()));
      continue;
    }
    const std::string where = array != nullptr ? position(r.file(), array->get(i)->source()) : r.where(key);
    std::string message = where + ": " + r.context() + ": '" + v + "' in '" + std::string(key) + "' is not valid";
    if (auto close = closest_match(v, choices)) message += " (did you mean '" + std::string(*close) + "'?)";
    throw Error::input(message + "; valid: " + join(choices));
  }
  return out;
}

/// Re-raises a validator's error about a setting (Error::setting(), e.g. "dt") at the
/// lesson key of that name ("file:12:6: step 3 (simulate): dt: ..."), in the innermost
/// table that has it.
[[noreturn]] void rethrow_at(const Error& e, std::initializer_list<const TableReader*> readers) {
  const std::string& key = e.setting();
  for (const TableReader* r : readers)
    if (!key.empty() && r->has(key)) throw e.rephrased(r->prefix(key) + e.what());
  const TableReader& innermost = **readers.begin();
  throw e.rephrased(innermost.prefix("") + e.what());
}

/// A plain file name inside the output folder.
std::string artifact_name(const TableReader& r, std::string_view key) {
  r.require(key);
  std::string name = *r.string(key);
  const bool plain = !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
  });
  if (!plain)
    r.fail(key, "'" + name +
                    "' must be a plain file name (letters, digits, '.', '-', '_'; not starting with '.'); "
                    "it is written in the output folder");
  if (name == "lesson.md") r.fail(key, "'lesson.md' is the lesson document's name; choose another");
  return name;
}

std::string strip_extension(std::string name, std::initializer_list<std::string_view> extensions) {
  for (std::string_view ext : extensions)
    if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0)
      return name.substr(0, name.size() - ext.size());
  return name;
}

/// The keys of a table in file order (toml++ keeps them sorted by name).
std::vector<std::string> keys_in_file_order(const toml::table& table,
                                            const std::function<bool(std::string_view)>& keep) {
  std::vector<std::pair<toml::source_position, std::string>> keys;
  for (const auto& [key, value] : table)
    if (keep(key.str())) keys.emplace_back(key.source().begin, std::string(key.str()));
  std::sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) {
    return a.first.line != b.first.line ? a.first.line < b.first.line : a.first.column < b.first.column;
  });
  std::vector<std::string> out;
  for (auto& [where, key] : keys) out.push_back(std::move(key));
  return out;
}

/// Lesson text with {{...}} placeholders, each a finite number at `inputs` (where the
/// text is shown), so a lesson that would print inf or nan fails when it is read.
TextTemplate text_template(std::string_view text, const std::string& origin, const Inputs& inputs,
                           const MechanismNames* mechanism) {
  TextTemplate t = TextTemplate::parse(text, origin, mechanism);
  if (text.find("{{") != std::string_view::npos) t.require_finite(evaluate_quantities(inputs), origin);
  return t;
}

class Parser {
 public:
  explicit Parser(const fs::path& file) : file_(file), file_text_(file.string()), dir_(file.parent_path()) {}

  /// The lesson file's own errors name it as "lesson: ..." (it is no flag's value).
  toml::table read_lesson_file() const {
    try {
      return parse_toml_file(file_text_, "lesson");
    } catch (const Error& e) {
      throw e.rephrased(e.what());
    }
  }

  Lesson parse() {
    const toml::table root = read_lesson_file();
    TableReader top(root, file_text_, "lesson", lesson_keys());
    top.reject_unknown_keys();

    Lesson lesson;
    lesson.file = file_;
    lesson.name = file_.stem().string();
    top.require("title");
    lesson.title = *top.string("title");
    if (lesson.title.empty()) top.fail("title", "the title is empty");

    Inputs inputs;
    if (auto config = top.string("config")) inputs.apply_file(referenced_file(top, "config", *config));
    read_inputs(top, "parameters", true, inputs);
    read_inputs(top, "state", false, inputs);
    inputs.validate();
    lesson.inputs = inputs;
    if (auto m = top.string("mechanism")) lesson_mechanism_ = mechanism_spec(top, "mechanism", *m);
    lesson.mechanism = lesson_mechanism_;
    if (!lesson_mechanism_.empty()) mechanism_names_ = mechanism_names(sym::System(load_mechanism(lesson_mechanism_)));
    if (auto d = top.string("description"))
      lesson.description = text_template(*d, top.prefix("description") + "description", inputs, names());

    top.require("step");
    const auto steps = top.tables("step");
    if (steps.empty()) top.fail("step", "a lesson needs at least one step");
    for (const toml::table* t : steps)
      lesson.steps.push_back(parse_step(*t, static_cast<int>(lesson.steps.size()) + 1, inputs));
    return lesson;
  }

 private:
  /// A shipped mechanism's name as it is, a file's as its path from the lesson's folder.
  std::string mechanism_spec(const TableReader& r, std::string_view key, const std::string& name) const {
    const bool file = name.find('/') != std::string::npos || name.ends_with(".toml");
    return file ? referenced_file(r, key, name).string() : name;
  }

  fs::path referenced_file(const TableReader& r, std::string_view key, const std::string& name) const {
    const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : dir_ / name;
    std::error_code ec;
    if (!fs::exists(path, ec)) r.fail(key, "the file '" + name + "' does not exist (looked for " + path.string() + ")");
    try {
      require_regular_file(path, std::string(key));  // not a folder, a FIFO or a device
    } catch (const Error& e) {
      r.fail(key, e.detail());
    }
    return path;
  }

  void read_inputs(const TableReader& top, std::string_view key, bool parameters, Inputs& inputs) const {
    const toml::node* n = top.node(key);
    if (n == nullptr) return;
    const toml::table* t = n->as_table();
    if (t == nullptr) top.fail(key, "'" + std::string(key) + "' must be a table, got " + type_phrase(*n));
    for (const auto& [name, value] : *t) {
      const InputKey* input = find_input_key(name.str());
      if (input == nullptr || (input->param != nullptr) == parameters) continue;
      throw Error::input(
          position(file_text_, name.source()) + ": lesson: '" + std::string(name.str()) + "' is " +
          (parameters ? "a state value; put it under [state]" : "a parameter; put it under [parameters]"));
    }
    apply_toml(inputs, *t, file_text_);
  }

  Step parse_step(const toml::table& table, int number, Inputs& inputs) {
    Step step;
    step.number = number;
    step.where = position(file_text_, table.source());
    const std::string bare_context = "step " + std::to_string(number);
    {
      TableReader kind_reader(table, file_text_, bare_context, common_step_keys());
      kind_reader.require("kind");
      const std::vector<std::string_view> kinds(kStepKindNames.begin(), kStepKindNames.end());
      const std::string kind = *kind_reader.choice("kind", kinds);
      step.kind = static_cast<StepKind>(std::find(kinds.begin(), kinds.end(), kind) - kinds.begin());
    }
    const std::string_view kind = name(step.kind);
    const std::string context = bare_context + " (" + std::string(kind) + ")";
    std::vector<KeySpec> keys = concat({common_step_keys(), step_keys(kind)});
    std::vector<std::string_view> extra;
    if (takes_run_keys(kind)) {
      keys = concat({keys, run_keys()});
      extra = input_names();
    }
    if (step.kind == StepKind::set) extra = input_names();
    const TableReader r(table, file_text_, context, keys, extra);
    r.reject_unknown_keys();
    if (auto h = r.string("heading")) step.heading = *h;
    for (const std::string_view key : {"caption", "unit"})  // Markdown shown as written (no {{...}})
      if (auto text = r.string(key)) check_markdown(*text, r.prefix(key) + std::string(key));
    step.canonical = canonical_text(table, {"heading", "caption"});

    switch (step.kind) {
      case StepKind::say:
        step.body = parse_say(r, inputs);
        break;
      case StepKind::set:
        step.body = parse_set(r, inputs);
        break;
      case StepKind::pause:
        step.body = PauseStep{r.string("prompt").value_or("Press Enter to continue")};
        break;
      case StepKind::exercise:
        step.body = parse_exercise(r, inputs);
        break;
      case StepKind::solve:
        step.body = parse_solve(r, inputs);
        break;
      case StepKind::simulate:
        step.body = parse_simulate(r, inputs);
        break;
      case StepKind::render: {
        RenderStep render = parse_render(r, inputs);
        // The mechanism (and a file's text) belongs to the cached clip's key.
        if (!render.mechanism.empty()) {
          step.canonical += ";mechanism=" + render.mechanism;
          if (fs::exists(render.mechanism)) {
            std::ifstream in(render.mechanism, std::ios::binary);
            std::stringstream content;
            content << in.rdbuf();
            step.canonical += ";" + content_hash(content.str());
          }
        }
        step.body = std::move(render);
        break;
      }
      case StepKind::plot:
        step.body = parse_plot(r, inputs);
        break;
      case StepKind::compare:
        step.body = parse_compare(r, inputs);
        break;
    }
    step.inputs = inputs;
    for (const std::string& artifact : step_artifacts(step)) {
      const auto [it, fresh] = artifacts_.emplace(artifact, step.where);
      if (!fresh)
        r.fail(step.kind == StepKind::simulate ? "trajectory" : "out",
               "'" + artifact + "' is also written by the step at " + it->second + "; give each output its own name");
    }
    return step;
  }

  SayStep parse_say(const TableReader& r, const Inputs& inputs) const {
    const auto text = r.string("text");
    const auto file = r.string("file");
    if (text && file) r.fail("file", "give either 'text' or 'file', not both");
    if (!text && !file) r.require("text");
    if (text) return {text_template(*text, r.prefix("text") + "text", inputs, names())};
    const fs::path path = referenced_file(r, "file", *file);
    std::ifstream in(path, std::ios::binary);
    std::stringstream content;
    content << in.rdbuf();
    if (!in && !in.eof()) r.fail("file", "cannot read '" + path.string() + "'");
    return {text_template(content.str(), r.prefix("file") + path.string(), inputs, names())};
  }

  SetStep parse_set(const TableReader& r, Inputs& inputs) const {
    SetStep step;
    step.keys = keys_in_file_order(r.table(), [](std::string_view k) { return find_input_key(k) != nullptr; });
    if (step.keys.empty()) throw Error::input(r.prefix("") + "a set step needs at least one of " + input_key_list());
    try {
      for (const std::string& key : step.keys)
        inputs.set(*find_input_key(key), *r.number(key, -kInf, kInf, ""), r.where(key));
      inputs.validate();
    } catch (const Error& e) {
      // The error is about the value's origin, FILE:LINE:COLUMN of a key: name the step too.
      for (const std::string& key : step.keys)
        if (e.setting() == r.where(key)) throw e.rephrased(r.prefix(key) + e.detail());
      throw;
    }
    return step;
  }

  ExerciseStep parse_exercise(const TableReader& r, const Inputs& inputs) const {
    ExerciseStep e;
    r.require("question");
    r.require("answer");
    e.question = text_template(*r.string("question"), r.prefix("question") + "question", inputs, names());
    const toml::node& answer = *r.node("answer");
    if (const auto* s = answer.as_string()) {
      e.answer = Expression::parse(s->get(), r.prefix("answer") + "answer", names());
    } else if (answer.is_number()) {
      e.answer =
          Expression::parse(format_roundtrip(*r.number("answer", -kInf, kInf, "")), r.prefix("answer") + "answer");
    } else {
      r.fail("answer",
             "'answer' must be an expression string (e.g. \"I_zz_P\") or a number, got " + type_phrase(answer));
    }
    const double value = e.answer.evaluate(evaluate_quantities(inputs));
    if (!std::isfinite(value))
      r.fail("answer", "'" + e.answer.text() + "' is not a finite number at this step's inputs");
    if (auto unit = r.string("unit"))
      e.unit = *unit;
    else if (const QuantityInfo* q = e.answer.single_quantity())
      e.unit = q->unit;
    e.tolerance = r.number("tolerance", 0, kInf, "valid: tolerance >= 0");
    e.relative_tolerance = r.number("relative_tolerance", 0, 1, "valid: 0 to 1").value_or(e.tolerance ? 0.0 : 0.01);
    e.attempts = static_cast<int>(r.integer("attempts", 1, 10).value_or(3));
    e.digits = static_cast<int>(r.integer("digits", 1, 17).value_or(6));
    if (auto hint = r.string("hint")) e.hint = text_template(*hint, r.prefix("hint") + "hint", inputs, names());
    if (auto x = r.string("explanation"))
      e.explanation = text_template(*x, r.prefix("explanation") + "explanation", inputs, names());
    return e;
  }

  SolveStep parse_solve(const TableReader& r, const Inputs& inputs) const {
    SolveStep s;
    const toml::node* c = r.node("case");
    if (c == nullptr || (c->is_string() && c->as_string()->get() == "all")) {
      s.cases = {1, 2, 3};
    } else if (c->is_integer()) {
      s.cases = {static_cast<int>(*r.integer("case", 1, 3))};
    } else if (const auto* array = c->as_array(); array != nullptr && !array->empty()) {
      for (const toml::node& element : *array) {
        const auto* i = element.as_integer();
        if (i == nullptr || i->get() < 1 || i->get() > 3)
          throw Error::input(position(file_text_, element.source()) + ": " + r.context() +
                             ": every entry of 'case' must be 1, 2 or 3");
        s.cases.push_back(static_cast<int>(i->get()));
      }
    } else {
      r.fail("case", "'case' must be 1, 2, 3, a list of them like [1, 3], or \"all\"");
    }
    try {  // inputs that overflow a derived quantity or make a matrix singular: refused now
      (void)work_out_mechanism(homework_mechanism(inputs), case_ids(s.cases));
    } catch (const Error& e) {
      throw e.rephrased(r.prefix("") + e.what());
    }
    const std::vector<std::string_view> parts(kSolvePartNames.begin(), kSolvePartNames.end());
    if (!r.has("show")) s.parts.fill(true);
    for (std::size_t i : choice_list(r, "show", parts)) s.parts[i] = true;
    return s;
  }

  /// Applies the run keys of `r` (a step, or one of its `runs` entries) to `run`.
  void apply_run_keys(const TableReader& r, Run& run) const {
    SimulationOptions& o = run.options;
    if (auto c = r.integer("case", 1, 3)) o.case_id = static_cast<int>(*c);
    if (auto i = r.choice("integrator", integrator_names())) o.integrator = parse_integrator(*i, r.where("integrator"));
    if (auto s = r.choice("stabilize", {"none", "baumgarte", "projection"}))
      o.stabilization = parse_stabilization(*s, r.where("stabilize"));
    o.dt = r.number("dt", -kInf, kInf, "").value_or(o.dt);
    o.rtol = r.number("rtol", -kInf, kInf, "").value_or(o.rtol);
    o.atol = r.number("atol", -kInf, kInf, "").value_or(o.atol);
    o.duration = r.number("duration", -kInf, kInf, "").value_or(o.duration);
    o.baumgarte_alpha = r.number("baumgarte_alpha", -kInf, kInf, "").value_or(o.baumgarte_alpha);
    o.baumgarte_beta = r.number("baumgarte_beta", -kInf, kInf, "").value_or(o.baumgarte_beta);
    for (const InputKey& key : kInputKeys)
      if (auto v = r.number(key.key, -kInf, kInf, "")) run.inputs.set(key, *v, r.where(key.key));
    run.inputs.validate();
  }

  static std::string default_label(const Run& run, const Inputs& base) {
    const SimulationOptions& o = run.options;
    const IntegratorInfo& i = info(o.integrator);
    std::string label = "Case " + std::to_string(o.case_id) + ", " + std::string(i.name);
    label += i.adaptive ? ", rtol " + format_significant(o.rtol, 3) : ", dt " + format_significant(o.dt, 3) + " s";
    if (o.case_id == 1) label += ", " + std::string(name(o.stabilization));
    for (const InputKey& key : kInputKeys)
      if (run.inputs.value(key) != base.value(key))
        label += ", " + std::string(key.key) + " = " + format_significant(run.inputs.value(key), 4);
    return label;
  }

  /// The step's own run (its run keys over the current inputs).
  Run step_run(const TableReader& r, const Inputs& inputs) const {
    Run run;
    run.inputs = inputs;
    apply_run_keys(r, run);
    try {
      run.options.validate();
    } catch (const Error& e) {
      rethrow_at(e, {&r});
    }
    run.label = default_label(run, inputs);
    run.series = std::string(info(run.options.integrator).name);
    return run;
  }

  /// The `runs` entries, each the step's run with the entry's keys on top.
  std::vector<Run> runs(const TableReader& r, const Inputs& inputs, bool required) const {
    if (required) r.require("runs");
    const auto tables = r.tables("runs");
    if (tables.empty()) {
      if (r.has("runs")) r.fail("runs", "'runs' is empty; give at least one run");
      return {step_run(r, inputs)};
    }
    Run base;
    base.inputs = inputs;
    apply_run_keys(r, base);
    const std::vector<KeySpec> keys = concat({run_keys(), run_entry_keys()});
    std::vector<Run> out;
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const TableReader entry(*tables[i], file_text_, r.context() + ", run " + std::to_string(i + 1), keys,
                              input_names());
      entry.reject_unknown_keys();
      Run run = base;
      apply_run_keys(entry, run);
      try {
        run.options.validate();
      } catch (const Error& e) {
        rethrow_at(e, {&entry, &r});
      }
      run.label = entry.string("label").value_or(default_label(run, inputs));
      run.series = entry.string("series").value_or(std::string(info(run.options.integrator).name));
      out.push_back(std::move(run));
    }
    return out;
  }

  static double longest(const std::vector<Run>& runs) {
    double d = 0;
    for (const Run& run : runs) d = std::max(d, run.options.duration);
    return d;
  }

  double sample_interval(const TableReader& r, double duration, double parts) const {
    const double every = r.number("every", 0, kInf, "valid: every > 0").value_or(duration / parts);
    if (!(every > 0)) r.fail("every", "'every' must be > 0");
    if (every > duration)
      r.fail("every", "'every' = " + format_roundtrip(every) + " s is longer than the run (" +
                          format_roundtrip(duration) + " s)");
    if (duration / every > 1e6)
      r.fail("every", "'every' = " + format_roundtrip(every) + " s gives more than a million samples");
    return every;
  }

  static void figure_size(const TableReader& r, int& width, int& height) {
    const auto size = r.string("size");
    if (!size) return;
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(*size);
    if (!(in >> w >> x >> h) || x != 'x' || (in >> extra) || w < 200 || h < 150 || w > 4000 || h > 4000)
      r.fail("size",
             "'" + *size +
                 "' is not a figure size; write WxH with 200 <= W <= 4000 and 150 <= H <= 4000, e.g. \"900x600\"");
    width = w;
    height = h;
  }

  SimulateStep parse_simulate(const TableReader& r, const Inputs& inputs) const {
    SimulateStep s;
    s.run = step_run(r, inputs);
    s.every = sample_interval(r, s.run.options.duration, 100);
    if (r.has("trajectory")) s.trajectory = strip_extension(artifact_name(r, "trajectory"), {".csv"}) + ".csv";
    if (auto columns = r.strings("columns")) {
      std::string list;
      for (const std::string& c : *columns) {
        if (!list.empty()) list += ',';
        list += c;
      }
      s.columns = parse_columns(list, r.prefix("columns") + "columns");
    } else {
      s.columns = parse_columns("all", "columns");
    }
    return s;
  }

  // The clip's checks, made here so a bad lesson fails before any step runs.
  /// A render step's timed captions, each checked where it is written.
  std::vector<Caption> captions(const TableReader& r, OutputKind kind, double duration) const {
    const auto tables = r.tables("captions");
    if (r.has("captions") && tables.empty()) r.fail("captions", "'captions' is empty; give {at = S, text = \"...\"}");
    std::vector<Caption> out;
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const TableReader entry(*tables[i], file_text_, r.context() + ", caption " + std::to_string(i + 1),
                              caption_entry_keys());
      entry.reject_unknown_keys();
      entry.require("at");
      entry.require("text");
      const double limit = is_still(kind) ? kMaxStillTime : duration;
      std::string rule = "0 .. ";
      rule += format_significant(limit, 6) + (is_still(kind) ? " s" : " s, the clip's duration");
      Caption c{*entry.number("at", 0, limit, rule), *entry.string("text")};
      if (c.text.find_first_not_of(" \t\n") == std::string::npos) entry.fail("text", "the caption has no words");
      if (!out.empty() && !(c.at > out.back().at))
        entry.fail("at", format_significant(c.at, 6) + " s must come after caption " + std::to_string(i) + "'s " +
                             format_significant(out.back().at, 6) + " s");
      out.push_back(std::move(c));
    }
    return out;
  }

  RenderStep parse_render(const TableReader& r, const Inputs& inputs) const {
    RenderStep s;
    s.out = artifact_name(r, "out");
    s.caption = r.string("caption").value_or("");
    s.run = step_run(r, inputs);
    RenderSettings& g = s.settings;
    if (auto m = r.string("mechanism")) s.mechanism = mechanism_spec(r, "mechanism", *m);
    if (s.mechanism.empty()) s.mechanism = lesson_mechanism_;
    s.settings_list = r.strings("set").value_or(std::vector<std::string>{});
    s.trails = r.strings("trail").value_or(std::vector<std::string>{});
    if (auto n = r.integer("ensemble", 2, 200)) s.ensemble = static_cast<int>(*n);
    if (auto x = r.number("spread", std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                          "a finite number > 0 (rad or m)")) {
      if (s.ensemble == 0) r.fail("spread", "'spread' applies with 'ensemble = N'");
      s.spread = *x;
    }
    s.compare = r.strings("compare").value_or(std::vector<std::string>{});
    for (const std::string_view key : {"set", "trail"})
      if (s.mechanism.empty() && r.has(key))
        r.fail(key, "'" + std::string(key) + "' applies to a mechanism: give mechanism = \"NAME\" here or at the top");
    if (!s.mechanism.empty())
      for (const std::string_view key : {"show", "hide", "camera", "view"})
        if (r.has(key))
          r.fail(key, "'" + std::string(key) + "' is the homework's; a mechanism's clip fits its whole motion");
    try {
      s.kind = output_kind(s.out, r.where("out") + ": " + r.context() + ": out");
      g.duration = s.run.options.duration;
      std::vector<std::string_view> qualities;
      for (const Quality& q : kQualities) qualities.push_back(q.name);
      const Quality& preset = parse_quality(r.choice("quality", qualities).value_or("medium"), r.where("quality"));
      g.width = preset.width;
      g.height = preset.height;
      g.fps = preset.fps;
      if (auto size = r.string("size"))
        parse_size(*size, r.where("size") + ": " + r.context() + ": size", g.width, g.height);
      if (auto fps = r.integer("fps", 1, kMaxFps)) g.fps = static_cast<int>(*fps);
      g.at = r.number("at", -kInf, kInf, "").value_or(g.at);
      g.speed = r.number("speed", -kInf, kInf, "").value_or(g.speed);
      const auto camera = r.choice("camera", {"follow", "fixed", "fit"});
      g.camera = camera          ? parse_camera(*camera, r.where("camera"))
                 : r.has("view") ? CameraMode::fixed
                                 : CameraMode::follow;
      if (auto v = r.string("view")) {
        g.view = parse_view(*v, r.where("view") + ": " + r.context() + ": view");
        if (g.camera != CameraMode::fixed)
          r.fail("view", "'view' applies only to camera = \"fixed\" (the " + *camera + " camera chooses its own view)");
      } else if (g.camera == CameraMode::fixed) {
        r.fail("camera", "camera = \"fixed\" needs a view = \"xmin,ymin,xmax,ymax\" in metres");
      }
      std::vector<std::string> theme_names = split_list(theme_name_list());
      const std::vector<std::string_view> themes(theme_names.begin(), theme_names.end());
      if (auto t = r.choice("theme", themes)) g.theme = *t;
      if (auto t = r.string("title")) g.title = *t;
      if (auto a = r.string("arrow_scale")) {
        static constexpr std::array<std::string_view, 2> kMechanismKinds{"joint", "applied"};
        g.arrow_scale =
            parse_arrow_scale_request(*a, r.where("arrow_scale") + ": " + r.context() + ": arrow_scale",
                                      s.mechanism.empty() ? std::span<const std::string_view>(kArrowKindNames)
                                                          : std::span<const std::string_view>(kMechanismKinds));
      }
      std::vector<std::string> show = r.strings("show").value_or(std::vector<std::string>{});
      std::vector<std::string> hide = r.strings("hide").value_or(std::vector<std::string>{});
      apply_show_hide(g.elements, show, hide);
      g.panel = r.strings("panel").value_or(std::vector<std::string>{});
      if (r.has("panel") && g.panel.empty()) r.fail("panel", "'panel' is empty; give at least one quantity");
      g.captions = captions(r, s.kind, g.duration);
      g.validate();
      if (s.mechanism.empty() && !g.panel.empty()) validate_homework_panel(g.panel);
      if (is_still(s.kind) && r.has("duration"))
        r.fail("duration", "'duration' applies to a clip; a still (" + s.out + ") shows the time 'at'");
      if (!is_still(s.kind) && r.has("at"))
        r.fail("at", "'at' applies to a still (out = \"NAME.png\", .svg or .pdf); a clip shows 0 .. duration");
      if (!s.mechanism.empty()) {
        if (s.kind == OutputKind::svg || s.kind == OutputKind::pdf)
          r.fail("out", "a mechanism's still is a .png (or a clip .mp4, .gif or .webm)");
        // The whole mechanism checked now, so a bad lesson fails before any step runs.
        const MechanismRender made = mechanism_render(s, r.where("set"));
        if (!r.has("title")) g.title = made.system->mechanism().title;
      }
      if (s.mechanism.empty() && !s.compare.empty())  // the homework's input names, checked now
        (void)homework_compared_run(s.compare, s.run.inputs, s.run.options,
                                    r.where("compare") + ": " + r.context() + ": compare");
      if (is_video(s.kind)) VideoWriter::validate(clip_video_options(g, s.kind));
    } catch (const Error& e) {
      if (e.code() != ExitCode::bad_input) throw;
      const std::string what = e.what();
      if (what.rfind(file_text_ + ":", 0) == 0) throw;
      rethrow_at(e, {&r});
    }
    return s;
  }

  Figure figure(const TableReader& r, const std::vector<Run>& runs) const {
    Figure f;
    f.x = *find_series(r.choice("x", series_names()).value_or("t"));
    f.log_x = r.boolean("log_x").value_or(false);
    f.log_y = r.boolean("log_y").value_or(false);
    f.title = r.string("title").value_or("");
    f.every = sample_interval(r, longest(runs), 400);
    figure_size(r, f.width, f.height);
    return f;
  }

  PlotStep parse_plot(const TableReader& r, const Inputs& inputs) const {
    PlotStep s;
    s.out = strip_extension(artifact_name(r, "out"), {".png", ".svg"});
    s.caption = r.string("caption").value_or("");
    s.runs = runs(r, inputs, false);
    r.require("y");
    s.figure = figure(r, s.runs);
    s.figure.y = choice_list(r, "y", series_names());
    if (s.figure.y.empty()) r.fail("y", "'y' is empty; name at least one series");
    return s;
  }

  CompareStep parse_compare(const TableReader& r, const Inputs& inputs) const {
    CompareStep s;
    s.out = strip_extension(artifact_name(r, "out"), {".csv", ".png", ".svg"});
    s.caption = r.string("caption").value_or("");
    s.runs = runs(r, inputs, true);
    const std::vector<std::string_view> columns(kCompareColumnNames.begin(), kCompareColumnNames.end());
    for (std::size_t i : choice_list(r, "columns", columns)) s.columns.push_back(static_cast<CompareColumn>(i));
    if (s.columns.empty())
      for (std::size_t i = 0; i < columns.size(); ++i) s.columns.push_back(static_cast<CompareColumn>(i));
    s.every = sample_interval(r, longest(s.runs), 400);
    s.title = r.string("title").value_or("");
    figure_size(r, s.width, s.height);
    if (auto y = r.choice("plot", series_names())) {
      Figure f;
      f.y = {*find_series(*y)};
      f.x = *find_series("t");
      f.log_y = r.boolean("log_y").value_or(true);
      f.title = s.title;
      f.every = s.every;
      f.width = s.width;
      f.height = s.height;
      s.plot = f;
    } else if (r.has("log_y")) {
      r.fail("log_y", "'log_y' applies to the plot; add plot = \"SERIES\" or remove it");
    }
    s.cost_plot = r.boolean("cost_plot").value_or(false);
    return s;
  }

  fs::path file_;
  std::string file_text_;
  std::string lesson_mechanism_;    // the lesson's `mechanism`, for its render steps
  MechanismNames mechanism_names_;  // its names for {{...}} and answers, when it has one
  [[nodiscard]] const MechanismNames* names() const { return lesson_mechanism_.empty() ? nullptr : &mechanism_names_; }
  fs::path dir_;
  std::map<std::string, std::string> artifacts_;  // file name -> the step that writes it
};

}  // namespace

std::vector<std::string> step_artifacts(const Step& step) {
  std::vector<std::string> out;
  if (const auto* s = std::get_if<SimulateStep>(&step.body)) {
    if (!s->trajectory.empty()) out.push_back(s->trajectory);
  } else if (const auto* r = std::get_if<RenderStep>(&step.body)) {
    out.push_back(r->out);
  } else if (const auto* p = std::get_if<PlotStep>(&step.body)) {
    out.push_back(p->out + ".png");
    out.push_back(p->out + ".svg");
  } else if (const auto* c = std::get_if<CompareStep>(&step.body)) {
    out.push_back(c->out + ".csv");
    if (c->plot) {
      out.push_back(c->out + ".png");
      out.push_back(c->out + ".svg");
    }
    if (c->cost_plot) {
      out.push_back(c->out + "-cost.png");
      out.push_back(c->out + "-cost.svg");
    }
  }
  return out;
}

std::vector<std::string> Lesson::artifacts() const {
  std::vector<std::string> out;
  for (const Step& step : steps)
    for (std::string& a : step_artifacts(step)) out.push_back(std::move(a));
  return out;
}

Lesson parse_lesson(const std::filesystem::path& file) { return Parser(file).parse(); }

}  // namespace linkage::lesson
