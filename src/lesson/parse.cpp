// Reading and validating a lesson file (lesson.hpp). Everything is checked here, before
// any step runs: a lesson that does not validate renders nothing.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <sstream>

#include "columns/expression_column.hpp"
#include "core/content_hash.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "encode/video_writer.hpp"
#include "lesson/lesson.hpp"
#include "lesson/schema.hpp"
#include "model/inputs_toml.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip_request.hpp"
#include "pipeline/clip_result.hpp"
#include "pipeline/mode_motion.hpp"
#include "pipeline/modes_sheet.hpp"
#include "pipeline/panel_data.hpp"
#include "pipeline/render_options.hpp"
#include "pipeline/run_samples.hpp"
#include "render/theme.hpp"
#include "report/markdown.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"
#include "report/modes_report.hpp"
#include "report/quotable_values.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/system.hpp"
#include "toml/toml_table.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<KeySpec> concat(std::initializer_list<std::span<const KeySpec>> parts) {
  std::vector<KeySpec> out;
  for (auto part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

/// The names of a table's entries, e.g. spellings(kInputKeys, &InputKey::key).
template <class Range, class Member>
std::vector<std::string_view> spellings(const Range& entries, Member name) {
  std::vector<std::string_view> out;
  for (const auto& entry : entries) out.push_back(entry.*name);
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

/// Runs `f`, re-raising its bad-input errors at the keys of `readers` (rethrow_at).
template <class F>
auto at_keys(std::initializer_list<const TableReader*> readers, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error& e) {
    if (e.code() != ExitCode::bad_input) throw;
    rethrow_at(e, readers);
  }
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

/// Lesson text with {{...}} placeholders over `names()` (where the text is shown, worked
/// out only for a text that has one), each a finite number, so a lesson that would print
/// inf or nan fails when it is read.
TextTemplate text_template(std::string_view text, const std::string& origin,
                           const std::function<const QuotableValues*()>& names) {
  if (text.find("{{") == std::string_view::npos) return TextTemplate::parse(text, origin);
  TextTemplate t = TextTemplate::parse(text, origin, names());
  t.require_finite(origin);
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
    if (!lesson_mechanism_.empty())
      at_keys({&top}, [&] {
        const auto built = build(lesson_mechanism_, {}, top.where("mechanism"));
        if (top.has("description")) step_names_ = &names_of(*built);
        step_spec_ = lesson_mechanism_;
        for (const Parameter& p : built->system->mechanism().parameters) settable_names_.push_back(p.name);
        for (const sym::GeneralizedCoordinate& g : built->system->coordinates())
          settable_names_.insert(settable_names_.end(), {g.coordinate.key, g.coordinate.key + "_dot"});
      });
    if (auto d = top.string("description"))
      lesson.description = text_template(*d, top.prefix("description") + "description",
                                         [&] { return names(inputs, top.where("description")); });

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
    return is_mechanism_file(name) ? referenced_file(r, key, name).string() : name;
  }

  /// The mechanism `spec` with `settings` applied (errors name `origin`), loops closed,
  /// `aliased` for the homework's names; built once per distinct spec and settings.
  std::shared_ptr<const BuiltMechanism> build(const std::string& spec, const std::vector<std::string>& settings,
                                              const std::string& origin, bool aliased = false) const {
    std::string key = spec + (aliased ? "\naliased" : "");
    for (const std::string& setting : settings) key += "\n" + setting;
    if (const auto it = built_.find(key); it != built_.end()) return it->second;
    return built_[key] = build_mechanism(spec, settings, origin, aliased);
  }

  /// The step's mechanism (its own `mechanism`, else the lesson's) and the settings it
  /// starts from: the lesson's mechanism keeps what earlier set steps set.
  void choose_step_mechanism(const TableReader& r, StepKind kind) {
    step_spec_ = lesson_mechanism_;
    step_settings_ = lesson_settings_;
    if (auto m = r.string("mechanism")) {
      if (kind == StepKind::set || kind == StepKind::pause)
        r.fail("mechanism",
               "'mechanism' applies to the steps that work on one (say, exercise, solve, modes, simulate, "
               "render, plot, compare); give it at the top to change the lesson's");
      const std::string spec = mechanism_spec(r, "mechanism", *m);
      if (spec != lesson_mechanism_) {
        step_spec_ = spec;
        step_settings_.clear();
      }
    }
  }

  /// The names {{...}} and answers may use on `built`, worked out once per mechanism and settings.
  const QuotableValues& names_of(const BuiltMechanism& built) const {
    auto [it, fresh] = names_cache_.try_emplace(&built);
    if (fresh) it->second = std::make_unique<const QuotableValues>(built.system);
    return *it->second;
  }

  /// The names of the step's mechanism; on the homework, two-blocks.toml's at `inputs` (its
  /// settings, as the homework's flags are), named by its [aliases] as the homework's
  /// quantities are. A value that breaks the worked solution is named at `origin`.
  const QuotableValues* names(const Inputs& inputs, const std::string& origin) const {
    if (!step_spec_.empty()) return step_names_;
    const auto built = build(kDefaultMechanism, default_mechanism_settings(inputs), origin, true);
    try {
      return &names_of(*built);
    } catch (const Error& e) {
      throw e.rephrased(origin + ": " + e.what());
    }
  }

  fs::path referenced_file(const TableReader& r, std::string_view key, const std::string& name) const {
    const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : dir_ / name;
    std::error_code ec;
    if (!fs::exists(path, ec) && !ec)  // else a loop or a folder it may not enter: said below
      r.fail(key, "the file '" + name + "' does not exist (looked for " + path.string() + ")");
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
    if (!n->is_table()) top.fail(key, "'" + std::string(key) + "' must be a table, got " + type_phrase(*n));
    for (const auto& [name, value] : *n->as_table())
      if (const InputKey* input = find_input_key(name.str()); input && input->parameter != parameters)
        throw Error::input(
            position(file_text_, name.source()) + ": lesson: '" + std::string(name.str()) + "' is " +
            (parameters ? "a state value; put it under [state]" : "a parameter; put it under [parameters]"));
    apply_toml(inputs, *n->as_table(), file_text_, parameters ? "[parameters]" : "[state]");
  }

  Step parse_step(const toml::table& table, int number, Inputs& inputs) {
    Step step;
    step.number = number;
    step.where = position(file_text_, table.source());
    const std::string bare_context = "step " + std::to_string(number);
    const TableReader kind_reader(table, file_text_, bare_context, common_step_keys());
    kind_reader.require("kind");
    const std::vector<std::string_view> kinds(kStepKindNames.begin(), kStepKindNames.end());
    const auto kind_at = std::find(kinds.begin(), kinds.end(), *kind_reader.choice("kind", kinds));
    step.kind = static_cast<StepKind>(kind_at - kinds.begin());
    const std::string_view kind = name(step.kind);
    const bool run_keys_too = takes_run_keys(kind);
    const std::vector<KeySpec> keys =
        concat({common_step_keys(), step_keys(kind), run_keys_too ? run_keys() : std::span<const KeySpec>{}});
    std::vector<std::string_view> extra;
    if (run_keys_too || step.kind == StepKind::set) extra = spellings(kInputKeys, &InputKey::key);
    if (step.kind == StepKind::set && !lesson_mechanism_.empty())
      extra.assign(settable_names_.begin(), settable_names_.end());
    const TableReader r(table, file_text_, bare_context + " (" + std::string(kind) + ")", keys, extra);
    r.reject_unknown_keys();
    if (auto h = r.string("heading")) step.heading = *h;
    for (const std::string_view key : {"caption", "unit"})  // Markdown shown as written (no {{...}})
      if (auto text = r.string(key)) check_markdown(*text, r.prefix(key) + std::string(key));
    step.canonical = canonical_text(table, {"heading", "caption"});
    choose_step_mechanism(r, step.kind);
    if (!step_spec_.empty() && step.kind != StepKind::set) {
      step.mechanism = at_keys({&r}, [&] { return build(step_spec_, step_settings_, r.where("mechanism")); });
      if (step.kind == StepKind::say || step.kind == StepKind::exercise) step_names_ = &names_of(*step.mechanism);
    }

    const std::array<std::function<StepBody()>, kStepKindNames.size()> read{{
        // In StepKind's order.
        [&] { return StepBody(parse_say(r, inputs)); },
        [&] { return StepBody(parse_set(r, inputs)); },
        [&] { return StepBody(PauseStep{r.string("prompt").value_or("Press Enter to continue")}); },
        [&] { return StepBody(parse_exercise(r, inputs)); },
        [&] { return StepBody(parse_solve(r, inputs, step)); },
        [&] { return StepBody(parse_modes(r, step)); },
        [&] { return StepBody(parse_simulate(r, inputs)); },
        [&] { return StepBody(parse_render(r, inputs)); },
        [&] { return StepBody(parse_plot(r, inputs)); },
        [&] { return StepBody(parse_compare(r, inputs)); },
    }};
    step.body = read[static_cast<std::size_t>(step.kind)]();
    step.inputs = inputs;
    if (step.kind == StepKind::set && !lesson_mechanism_.empty())
      step.mechanism = build(lesson_mechanism_, lesson_settings_, r.where("set"));
    // The mechanism, its settings (and a file's text) belong to the cached artifacts' key.
    if (step.mechanism) {
      step.canonical += ";mechanism=" + step.mechanism->spec + ";settings=";
      for (const std::string& setting : step.mechanism->settings) step.canonical += setting + ",";
      if (fs::exists(step.mechanism->spec))
        step.canonical += ";" + content_hash(read_file_text(step.mechanism->spec).value_or(""));
    }
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
    if (text) return {text_template(*text, r.prefix("text") + "text", [&] { return names(inputs, r.where("text")); })};
    const fs::path path = referenced_file(r, "file", *file);
    const auto content = read_file_text(path);
    if (!content) r.fail("file", "cannot read '" + path.string() + "'");
    return {text_template(*content, r.prefix("file") + path.string(), [&] { return names(inputs, r.where("file")); })};
  }

  SetStep parse_set(const TableReader& r, Inputs& inputs) {
    SetStep step;
    if (lesson_mechanism_.empty()) {
      if (r.has("set")) r.fail("set", "'set' applies to a mechanism: give mechanism = \"NAME\" at the top");
      step.keys = r.keys_in_file_order([](std::string_view k) { return find_input_key(k) != nullptr; });
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
    // The lesson's mechanism: `set = ["NAME=VALUE", ...]` and NAME = VALUE keys, in file order.
    if (auto list = r.strings("set")) step.settings = *list;
    for (const std::string& key : r.keys_in_file_order([&](std::string_view k) {
           return std::find(settable_names_.begin(), settable_names_.end(), k) != settable_names_.end();
         }))
      step.settings.push_back(key + "=" + format_roundtrip(*r.number(key, -kInf, kInf, "")));
    if (step.settings.empty())
      throw Error::input(r.prefix("") + "a set step needs set = [\"NAME=VALUE\", ...] or NAME = VALUE keys; names: " +
                         join_names(settable_names_));
    std::vector<std::string> settings = lesson_settings_;
    settings.insert(settings.end(), step.settings.begin(), step.settings.end());
    const auto [before, after] = at_keys({&r}, [&] {
      return std::pair{build(lesson_mechanism_, lesson_settings_, r.where("")),
                       build(lesson_mechanism_, settings, r.where(r.has("set") ? "set" : ""))};
    });
    // A parameter's value, or an initial coordinate's or rate's with the loops closed.
    const auto value = [](const BuiltMechanism& built, const std::string& name) {
      const GiNaC::ex symbol = built.system->table().find(name)->symbol;
      return format_roundtrip(sym::to_double(symbol.subs(built.initial).subs(built.system->parameter_values())));
    };
    for (const std::string& setting : step.settings) {
      const std::string name = setting.substr(0, setting.find('='));
      const std::string& unit = after->system->table().find(name)->unit;
      step.changes.push_back(name + " = " + value(*after, name) + (unit.empty() ? "" : " " + unit) + " (was " +
                             value(*before, name) + ")");
    }
    lesson_settings_ = std::move(settings);
    return step;
  }

  /// The text of `key`, a {{...}} template checked at `inputs`.
  TextTemplate text_at(const TableReader& r, std::string_view key, const Inputs& inputs) const {
    return text_template(*r.string(key), r.prefix(key) + std::string(key), [&] { return names(inputs, r.where(key)); });
  }

  ExerciseStep parse_exercise(const TableReader& r, const Inputs& inputs) const {
    ExerciseStep e;
    r.require("question");
    r.require("answer");
    e.question = text_at(r, "question", inputs);
    const toml::node& answer = *r.node("answer");
    if (const auto* s = answer.as_string()) {
      e.answer = Expression::parse(s->get(), r.prefix("answer") + "answer", names(inputs, r.where("answer")));
    } else if (answer.is_number()) {
      e.answer =
          Expression::parse(format_roundtrip(*r.number("answer", -kInf, kInf, "")), r.prefix("answer") + "answer");
    } else {
      r.fail("answer",
             "'answer' must be an expression string (e.g. \"I_zz_P\") or a number, got " + type_phrase(answer));
    }
    if (!std::isfinite(e.answer.evaluate()))
      r.fail("answer", "'" + e.answer.text() + "' is not a finite number at this step's inputs");
    if (auto unit = r.string("unit"))
      e.unit = *unit;
    else if (const auto& name = e.answer.single_name())
      e.unit = names(inputs, r.where("answer"))->unit(*name);  // a parameter, coordinate, derived value ...
    e.tolerance = r.number("tolerance", 0, kInf, "valid: tolerance >= 0");
    e.relative_tolerance = r.number("relative_tolerance", 0, 1, "valid: 0 to 1").value_or(e.tolerance ? 0.0 : 0.01);
    e.attempts = static_cast<int>(r.integer("attempts", 1, 10).value_or(3));
    e.digits = static_cast<int>(r.integer("digits", 1, 17).value_or(6));
    if (r.has("hint")) e.hint = text_at(r, "hint", inputs);
    if (r.has("explanation")) e.explanation = text_at(r, "explanation", inputs);
    return e;
  }

  SolveStep parse_solve(const TableReader& r, const Inputs& inputs, const Step& step) const {
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
      (void)work_out_mechanism(step.mechanism ? step.mechanism->system->mechanism() : default_mechanism(inputs),
                               case_ids(s.cases));
    } catch (const Error& e) {
      throw e.rephrased(r.prefix("") + e.what());
    }
    const std::vector<std::string_view> parts(kSolvePartNames.begin(), kSolvePartNames.end());
    if (!r.has("show")) s.parts.fill(true);
    for (std::size_t i : r.choice_list("show", parts)) s.parts[i] = true;
    return s;
  }

  /// A modes step: `linkage modes` on the step's mechanism (the homework's blocks fall
  /// freely: no equilibrium), linearized now so a lesson without one fails when it is read.
  static ModesStep parse_modes(const TableReader& r, const Step& step) {
    ModesStep s;
    s.at_initial = r.boolean("at_initial").value_or(false);
    s.verify = r.boolean("verify").value_or(false);
    s.digits = static_cast<int>(r.integer("digits", 1, 17).value_or(6));
    if (!step.mechanism)
      throw Error::input(r.prefix("") +
                         "a modes step needs a mechanism with an equilibrium (the homework's two blocks fall "
                         "freely); give mechanism = \"NAME\" here or at the top, e.g. \"double-pendulum\"");
    try {
      (void)analyse_modes(*step.mechanism->system, s.at_initial, false);
    } catch (const Error& e) {
      if (e.code() != ExitCode::bad_input) throw;
      throw e.rephrased(r.prefix("") + e.what());
    }
    return s;
  }

  /// Applies the run keys of `r` (a step, or one of its `runs` entries) to `run`.
  void apply_run_keys(const TableReader& r, Run& run) const {
    SimulationOptions& o = run.options;
    if (auto c = r.integer("case", 1, 3)) o.case_id = static_cast<int>(*c);
    if (auto i = r.choice("integrator", spellings(integrators(), &IntegratorInfo::name)))
      o.integrator = parse_integrator(*i, r.where("integrator"));
    if (auto s = r.choice("stabilize", {"none", "baumgarte", "projection"}))
      o.stabilization = parse_stabilization(*s, r.where("stabilize"));
    if (auto e = r.choice("evaluator", {"auto", "compiled", "interpreted"}))
      o.evaluator = parse_evaluator(*e, r.where("evaluator"));
    for (const NumberOption& n : kNumberOptions) o.*n.field = r.number(n.name, -kInf, kInf, "").value_or(o.*n.field);
    if (auto settings = r.strings("set")) {
      if (run.mechanism.empty())
        r.fail("set", "'set' applies to a mechanism: give mechanism = \"NAME\" here or at the top");
      run.settings.insert(run.settings.end(), settings->begin(), settings->end());
    }
    for (const InputKey& key : kInputKeys) {
      if (!r.has(key.key)) continue;
      if (!run.mechanism.empty())
        r.fail(key.key, "'" + std::string(key.key) + "' is an input of the homework; on a mechanism write set = [\"" +
                            "NAME=VALUE\"] with the mechanism's names");
      run.inputs.set(key, *r.number(key.key, -kInf, kInf, ""), r.where(key.key));
    }
    run.inputs.validate();
  }

  /// A run of the step's mechanism and settings from `inputs`, with the run keys of `r`.
  Run base_run(const TableReader& r, const Inputs& inputs) const {
    Run run;
    run.inputs = inputs;
    run.mechanism = step_spec_;
    run.settings = step_settings_;
    apply_run_keys(r, run);
    return run;
  }

  /// `run` checked and named: its options, its mechanism built with its settings, errors at
  /// the innermost of `readers` (a `runs` entry, then its step) that has the key.
  Run finish_run(Run run, std::initializer_list<const TableReader*> readers, const Inputs& inputs) const {
    at_keys(readers, [&] { run.options.validate(); });
    const auto with_set = std::find_if(readers.begin(), readers.end(), [](auto* r) { return r->has("set"); });
    const std::string origin = (with_set != readers.end() ? *with_set : *readers.begin())->where("set");
    // The homework is two-blocks.toml with the run's inputs as its settings (as the
    // homework's flags are), named by its [aliases] as the homework's inputs are.
    run.built = at_keys(readers, [&] {
      return run.mechanism.empty() ? build(kDefaultMechanism, default_mechanism_settings(run.inputs), origin, true)
                                   : build(run.mechanism, run.settings, origin);
    });
    // The initial state worked out as solve does (as `simulate --mechanism` does), so a
    // value that breaks it is named with its likely causes; once per mechanism and case.
    if (checked_.emplace(run.built.get(), run.options.case_id).second)
      at_keys(readers,
              [&] { (void)work_out_mechanism(run.built->system, {static_cast<CaseId>(run.options.case_id)}); });
    const TableReader& innermost = **readers.begin();
    run.label = innermost.string("label").value_or(default_label(run, inputs));
    run.series = innermost.string("series").value_or(std::string(info(run.options.integrator).name));
    return run;
  }

  std::string default_label(const Run& run, const Inputs& base) const {
    const SimulationOptions& o = run.options;
    const IntegratorInfo& i = info(o.integrator);
    std::string label = "Case " + std::to_string(o.case_id) + ", " + std::string(i.name);
    label += i.adaptive ? ", rtol " + format_significant(o.rtol, 3) : ", dt " + format_significant(o.dt, 3) + " s";
    if (o.case_id == 1) label += ", " + std::string(name(o.stabilization));
    for (std::size_t k = step_settings_.size(); k < run.settings.size(); ++k) {
      std::string setting = run.settings[k];
      if (const auto equals = setting.find('='); equals != std::string::npos) setting.replace(equals, 1, " = ");
      label += ", " + setting;
    }
    for (const InputKey& key : kInputKeys)
      if (run.inputs.value(key) != base.value(key))
        label += ", " + std::string(key.key) + " = " + format_significant(run.inputs.value(key), 4);
    return label;
  }

  /// The step's own run (its run keys over the current inputs).
  Run step_run(const TableReader& r, const Inputs& inputs) const {
    return finish_run(base_run(r, inputs), {&r}, inputs);
  }

  /// The `runs` entries, each the step's run with the entry's keys on top.
  std::vector<Run> runs(const TableReader& r, const Inputs& inputs, bool required) const {
    if (required) r.require("runs");
    const auto tables = r.tables("runs");
    if (tables.empty()) {
      if (r.has("runs")) r.fail("runs", "'runs' is empty; give at least one run");
      return {step_run(r, inputs)};
    }
    const Run base = base_run(r, inputs);
    const std::vector<KeySpec> keys = concat({run_keys(), run_entry_keys()});
    std::vector<Run> out;
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const TableReader entry(*tables[i], file_text_, r.context() + ", run " + std::to_string(i + 1), keys,
                              spellings(kInputKeys, &InputKey::key));
      entry.reject_unknown_keys();
      Run run = base;
      apply_run_keys(entry, run);
      out.push_back(finish_run(std::move(run), {&entry, &r}, inputs));
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

  /// "file:line:column: context: key" of entry `i` of a list key (of the key for a single string).
  static std::string entry_origin(const TableReader& r, std::string_view key, std::size_t i) {
    const toml::array* array = r.node(key)->as_array();
    const std::string where = array != nullptr ? position(r.file(), array->get(i)->source()) : r.where(key);
    return where + ": " + r.context() + ": " + std::string(key);
  }

  SimulateStep parse_simulate(const TableReader& r, const Inputs& inputs) const {
    SimulateStep s;
    s.run = step_run(r, inputs);
    s.every = sample_interval(r, s.run.options.duration, 100);
    if (r.has("trajectory")) s.trajectory = strip_extension(artifact_name(r, "trajectory"), {".csv"}) + ".csv";
    // As `linkage simulate --columns`: t first, "default" without the key.
    const auto names = r.strings("columns").value_or(std::vector<std::string>{"default"});
    if (names.empty()) r.fail("columns", "'columns' is empty; name at least one column, \"default\" or \"all\"");
    s.mechanism_columns = select_mechanism_columns(
        s.run.built->named_columns(), names, [&](std::size_t i) { return entry_origin(r, "columns", i); },
        s.run.built->system.get());
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
      if (entry.has("until"))
        c.until = *entry.number("until", c.at, limit, format_significant(c.at, 6) + " .. " + rule.substr(5));
      if (entry.has("until") && !(c.until > c.at))
        entry.fail("until", format_significant(c.until, 6) + " s must come after the caption's at (" +
                                format_significant(c.at, 6) + " s)");
      if (!out.empty() && std::isfinite(out.back().until) && out.back().until > c.at)
        entry.fail("at", format_significant(c.at, 6) + " s comes before caption " + std::to_string(i) + " ends (" +
                             format_significant(out.back().until, 6) + " s)");
      out.push_back(std::move(c));
    }
    return out;
  }

  /// A render step's `panel` names as the mechanism's keys: the homework's spelling
  /// (theta1) becomes the file's (1.theta); an unknown name is refused as a mechanism's
  /// panel refuses it, listing the names in the spelling the lesson uses.
  static std::vector<std::string> panel_keys(const BuiltMechanism& built, const std::vector<std::string>& names) {
    if (!built.aliased || names.empty()) return names;
    const std::vector<MechanismColumn> named = built.named_columns();
    const std::vector<MechanismColumn> all = mechanism_columns(*built.system);
    std::vector<std::string> out;
    for (const MechanismColumn& c : mechanism_panel_columns(named, names, built.system.get())) {
      if (c.quantity == MechanismQuantity::expression) {  // reads both spellings
        out.push_back(c.name + "=" + c.expression->text);
        continue;
      }
      const auto at = std::find_if(named.begin(), named.end(), [&](const auto& n) { return n.name == c.name; });
      out.push_back(all[static_cast<std::size_t>(at - named.begin())].name);
    }
    return out;
  }

  /// A render step's `compare` items on the homework: its inputs (theta1=...) as the
  /// settings of two-blocks.toml they are (1.theta=...); integrator and case as given.
  static std::string compare_settings(const TableReader& r, const BuiltMechanism& built, const std::string& compare) {
    if (!built.aliased) return compare;
    std::string out;
    std::stringstream in(compare);
    for (std::string item; std::getline(in, item, ',');) {
      const auto equals = item.find('=');
      std::string name = item.substr(0, equals);
      std::replace(name.begin(), name.end(), '-', '_');  // theta1-dot as the flag spells it
      if (equals != std::string::npos && name != "integrator" && name != "case") {
        const InputKey* key = find_input_key(name);
        if (key == nullptr) {
          const auto near = closest_input_key(name);
          throw Error::input(r.where("compare") + ": " + r.context() + ": compare: '" + name + "' is not an input" +
                             (near ? " (did you mean '" + std::string(*near) + "'?)" : std::string()) +
                             "; valid: " + input_key_list() + ", integrator, case");
        }
        item = std::string(key->mechanism_key) + item.substr(equals);
      }
      out += (out.empty() ? "" : ",") + item;
    }
    return out;
  }

  /// A render step's mode keys (render --mode, --modes-sheet), checked as the command
  /// checks its flags; the mode's number and amplitude against the mechanism's modes.
  static void mode_keys(const TableReader& r, RenderStep& s) {
    if (r.has("mode")) s.mode = static_cast<int>(*r.integer("mode", 1, 1000000));
    if (r.has("amplitude")) s.amplitude = *r.number("amplitude", -kInf, kInf, "");
    s.nonlinear = r.boolean("nonlinear").value_or(false);
    s.modes_sheet = r.boolean("modes_sheet").value_or(false);
    if (s.modes_sheet) {
      const auto refuse = [&](std::string_view other) {
        if (r.has(other))
          r.fail(other, "'" + std::string(other) +
                            "' does not combine with 'modes_sheet', which draws every mode in one still");
      };
      for (const std::string_view other : kModesSheetConflicts) refuse(other);
      refuse("captions");  // each panel has its own
      refuse("duration");
      if (!is_still(s.kind))
        r.fail("out", "'" + s.out + "' is a video; a step with 'modes_sheet' writes one still: .png, .svg or .pdf");
    } else if (s.mode == 0) {
      for (const char* other : {"amplitude", "nonlinear"})
        if (r.has(other)) r.fail(other, "'" + std::string(other) + "' applies only with 'mode' or 'modes_sheet'");
    } else {
      for (const char* other : {"ensemble", "compare"})
        if (r.has(other)) r.fail(other, "'" + std::string(other) + "' does not combine with 'mode'");
      if (!s.nonlinear && s.run.options.case_id != 3)
        r.fail("case", "case = " + std::to_string(s.run.options.case_id) +
                           " applies to 'mode' only with 'nonlinear'; the linear motion is in Case 3's coordinates");
    }
    if (!s.modes_sheet && s.mode == 0) return;
    if (s.modes_sheet && s.run.options.case_id != 3)
      r.fail("case", "case = " + std::to_string(s.run.options.case_id) +
                         " does not apply to 'modes_sheet'; the modes are in Case 3's coordinates");
    check_amplitude(s.amplitude);
    const sym::System& system = *s.run.built->system;
    const Linearization linear = linearize(system);
    if (s.mode > 0) (void)mode_motion(system, linear, modal_analysis(linear), s.mode, s.amplitude, s.nonlinear);
  }

  RenderStep parse_render(const TableReader& r, const Inputs& inputs) const {
    RenderStep s;
    s.out = artifact_name(r, "out");
    s.caption = r.string("caption").value_or("");
    s.run = step_run(r, inputs);
    // Each render option's TOML value as the text its flag would carry.
    std::vector<std::pair<std::string, std::string>> given;
    for (const RenderOption& o : render_options()) {
      if (!r.has(o.name)) continue;
      std::string text;
      if (o.value == RenderValue::integer) {
        text = std::to_string(
            *r.integer(o.name, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()));
      } else if (o.value == RenderValue::number) {
        text = format_roundtrip(*r.number(o.name, -kInf, kInf, ""));
      } else if (o.value == RenderValue::list) {
        const std::vector<std::string> items = *r.strings(o.name);
        for (std::size_t i = 0; i < items.size(); ++i) text.append(i > 0 ? "," : "").append(items[i]);
      } else {
        text = *r.string(o.name);
      }
      given.emplace_back(std::string(o.name), std::move(text));
    }
    try {
      s.kind = output_kind(s.out, r.where("out") + ": " + r.context() + ": out");
      RenderSettings base;
      base.duration = s.run.options.duration;
      base.captions = captions(r, s.kind, base.duration);
      RenderTarget target;
      target.still = is_still(s.kind);
      target.page = s.kind == OutputKind::html;
      target.spell = [](std::string_view key) { return std::string(key); };
      RenderRequest& request = s.request = resolve_render_options(given, target, base);
      if (is_still(s.kind) && r.has("duration"))
        r.fail("duration", "'duration' applies to a clip; a still (" + s.out + ") shows the time 'at'");
      request.settings.panel = panel_keys(*s.run.built, request.settings.panel);
      request.compare = compare_settings(r, *s.run.built, request.compare);
      // The whole clip checked now, so a bad lesson fails before any step runs; the settings
      // keep the mechanism's title and the equations shown. Its output is checked by name:
      // the folder is the runner's, known when the step runs (not the current one).
      ClipPlan plan;
      std::error_code no_temp;
      const fs::path temp = fs::temp_directory_path(no_temp);
      plan.out = no_temp ? fs::path(s.out) : temp / s.out;
      plan.equations = case_equations_as<EquationsText>;
      plan.compare_files = false;
      plan.compare_origin = "compare";
      request.settings =
          mechanism_clip(request, *s.run.built->system, s.run.built->initial, s.run.options, plan).clip.settings;
      if (is_video(s.kind)) VideoWriter::validate(clip_video_options(request.settings, s.kind));
      mode_keys(r, s);
    } catch (const Error& e) {
      if (e.code() != ExitCode::bad_input) throw;
      const std::string what = e.what();
      if (what.rfind(file_text_ + ":", 0) == 0) throw;
      rethrow_at(e, {&r});
    }
    return s;
  }

  /// The columns a figure of `runs` may draw: the mechanism's, under the names it goes by
  /// (the homework's x1, x_com through two-blocks.toml's [aliases]).
  static std::vector<MechanismColumn> figure_columns(const std::vector<Run>& runs) {
    return runs.front().built->named_columns();
  }

  Figure figure(const TableReader& r, const std::vector<Run>& runs) const {
    Figure f;
    f.x = find_mechanism_column(figure_columns(runs), r.string("x").value_or("t"), r.prefix("x") + "x", false,
                                runs.front().built->system.get());
    f.log_x = r.boolean("log_x").value_or(false);
    f.log_y = r.boolean("log_y").value_or(false);
    f.title = r.string("title").value_or("");
    f.every = sample_interval(r, longest(runs), 400);
    figure_size(r, f.width, f.height);
    return f;
  }

  /// A defined column reads its parameters from the first run's mechanism: every run must
  /// give them the same values.
  static void check_defined_columns(const TableReader& r, const std::string& key,
                                    const std::vector<MechanismColumn>& columns, const std::vector<Run>& runs) {
    const auto value = [](const Run& run, const std::string& name) {
      const sym::System& system = *run.built->system;
      GiNaC::exmap values = system.parameter_values();
      for (const auto& [symbol, expression] : system.constants()) values[symbol] = expression;
      return sym::evaluate(system.names().at(name), values);
    };
    for (const MechanismColumn& c : columns) {
      if (c.quantity != MechanismQuantity::expression) continue;
      for (const std::string& name : c.expression->parameters)
        for (const Run& run : runs)
          if (const double v = value(run, name), v0 = value(runs.front(), name); v != v0)
            r.fail(key, "column '" + c.name + "' uses '" + name + "', which run '" + run.label + "' sets to " +
                            format_roundtrip(v) + " and run '" + runs.front().label + "' to " + format_roundtrip(v0) +
                            "; valid: a definition without it, or runs that agree on it");
    }
  }

  /// `difference` subtracts the first run sample by sample: two runs or more, against
  /// time, all sampled at the same times.
  static void check_difference(const TableReader& r, const PlotStep& s) {
    if (s.runs.size() < 2)
      r.fail("difference", "'difference' needs two runs or more in 'runs' (the first is the reference)");
    if (r.has("x") && r.string("x").value_or("t") != "t")
      r.fail("difference", "'difference' compares runs at the same time; remove 'x' (the default is t)");
    const std::vector<double> times = run_sample_times(s.runs.front().options, s.figure.every);
    for (const Run& run : s.runs)
      if (run_sample_times(run.options, s.figure.every) != times)
        r.fail("difference", "run '" + run.label + "' is sampled at other times than run '" + s.runs.front().label +
                                 "' (another duration or fixed step); 'difference' needs the same");
  }

  PlotStep parse_plot(const TableReader& r, const Inputs& inputs) const {
    PlotStep s;
    s.out = strip_extension(artifact_name(r, "out"), {".png", ".svg"});
    s.caption = r.string("caption").value_or("");
    s.runs = runs(r, inputs, false);
    r.require("y");
    s.figure = figure(r, s.runs);
    s.figure.difference = r.boolean("difference").value_or(false);
    if (auto a = r.choice("angles", {"rad", "deg"})) s.figure.angles = parse_angle_unit(*a, r.where("angles"));
    if (s.figure.difference) check_difference(r, s);
    const std::vector<MechanismColumn> all = figure_columns(s.runs);
    const auto names = *r.strings("y");
    for (std::size_t i = 0; i < names.size(); ++i)
      s.figure.y.push_back(
          find_mechanism_column(all, names[i], entry_origin(r, "y", i), false, s.runs.front().built->system.get()));
    if (s.figure.y.empty()) r.fail("y", "'y' is empty; name at least one column");
    check_defined_columns(r, "x", {s.figure.x}, s.runs);
    check_defined_columns(r, "y", s.figure.y, s.runs);
    std::vector<std::string> units;
    for (const MechanismColumn& c : s.figure.y) units.push_back(c.unit);
    check_equal_axes(r, s, s.figure.x.unit, units);
    return s;
  }

  /// `equal_axes` draws x and y at one scale: both linear, and in one unit (a length
  /// against a length), else a metre on one axis would be matched to a radian.
  static void check_equal_axes(const TableReader& r, PlotStep& s, const std::string& x_unit,
                               const std::vector<std::string>& y_units) {
    s.figure.equal_axes = r.boolean("equal_axes").value_or(false);
    if (!s.figure.equal_axes) return;
    if (s.figure.log_x || s.figure.log_y)
      r.fail("equal_axes", "'equal_axes' needs linear axes; remove 'log_x' and 'log_y' or 'equal_axes'");
    for (const std::string& unit : y_units)
      if (unit != x_unit)
        r.fail("equal_axes", "'equal_axes' needs x and y in one unit; x is in '" + x_unit + "', y in '" + unit + "'");
  }

  CompareStep parse_compare(const TableReader& r, const Inputs& inputs) const {
    CompareStep s;
    s.out = strip_extension(artifact_name(r, "out"), {".csv", ".png", ".svg"});
    s.caption = r.string("caption").value_or("");
    s.runs = runs(r, inputs, true);
    const std::vector<std::string_view> columns(kCompareColumnNames.begin(), kCompareColumnNames.end());
    for (std::size_t i : r.choice_list("columns", columns)) s.columns.push_back(static_cast<CompareColumn>(i));
    if (s.columns.empty())
      for (std::size_t i = 0; i < columns.size(); ++i) s.columns.push_back(static_cast<CompareColumn>(i));
    Figure f = figure(r, s.runs);  // against t (a compare step has no x), every 1/400 of the run
    s.every = f.every;
    s.title = f.title;
    s.width = f.width;
    s.height = f.height;
    if (auto y = r.string("plot")) {
      f.y = {find_mechanism_column(figure_columns(s.runs), *y, r.prefix("plot") + "plot", false,
                                   s.runs.front().built->system.get())};
      check_defined_columns(r, "plot", f.y, s.runs);
      f.log_y = r.boolean("log_y").value_or(true);
      s.plot = f;
    } else if (r.has("log_y")) {
      r.fail("log_y", "'log_y' applies to the plot; add plot = \"SERIES\" or remove it");
    }
    s.cost_plot = r.boolean("cost_plot").value_or(false);
    return s;
  }

  fs::path file_;
  std::string file_text_;
  std::string lesson_mechanism_;              // the lesson's `mechanism`
  std::vector<std::string> lesson_settings_;  // its settings from the set steps so far
  std::vector<std::string> settable_names_;   // its parameters, coordinates and rates
  std::string step_spec_;                     // the step being read: its mechanism and settings
  std::vector<std::string> step_settings_;
  const QuotableValues* step_names_ = nullptr;  // names of the step's mechanism for {{...}} and answers
  mutable std::map<std::string, std::shared_ptr<const BuiltMechanism>> built_;
  mutable std::set<std::pair<const BuiltMechanism*, int>> checked_;  // runs' states worked out
  mutable std::map<const BuiltMechanism*, std::unique_ptr<const QuotableValues>> names_cache_;
  fs::path dir_;
  std::map<std::string, std::string> artifacts_;  // file name -> the step that writes it
};

}  // namespace

std::vector<std::string> step_artifacts(const Step& step) {
  std::vector<std::string> out;
  const auto figure = [&](const std::string& base) { out.insert(out.end(), {base + ".png", base + ".svg"}); };
  if (const auto* s = std::get_if<SimulateStep>(&step.body)) {
    if (!s->trajectory.empty()) out.push_back(s->trajectory);
  } else if (const auto* r = std::get_if<RenderStep>(&step.body)) {
    out.push_back(r->out);
  } else if (const auto* p = std::get_if<PlotStep>(&step.body)) {
    figure(p->out);
  } else if (const auto* c = std::get_if<CompareStep>(&step.body)) {
    out.push_back(c->out + ".csv");
    if (c->plot) figure(c->out);
    if (c->cost_plot) figure(c->out + "-cost");
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
