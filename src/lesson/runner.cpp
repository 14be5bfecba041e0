// The lesson runner: the order of things, the cache, and the steps that only print
// (say, set, pause, exercise, solve, modes). Steps that simulate or draw live in
// step_runs.cpp and step_render.cpp.
#include "lesson/runner.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>

#include "core/atomic_file.hpp"
#include "core/character_text.hpp"
#include "core/content_hash.hpp"
#include "core/deriving.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "lesson/runner_context.hpp"
#include "linkage/version.hpp"
#include "model/mechanism_toml.hpp"
#include "report/modes_report.hpp"

namespace linkage::lesson {

namespace fs = std::filesystem;

// --- shared pieces --------------------------------------------------------------------

void RunContext::flush() {
  errno = 0;
  out << terminal->take();
  out.flush();
  // A full disk or a closed pipe ends the lesson now, with the reason, not at its end.
  if (!out)
    throw Error::failure("cannot write standard output: " +
                         std::string(errno != 0 ? std::strerror(errno) : "write error"));
}

void RunContext::note(const Step& step, const std::string& text) {
  status << "lesson: step " << step.number << " (" << name(step.kind) << "): " << text << "\n";
  status.flush();
}

void RunContext::warn(const Step& step, const nlohmann::json& results) {
  const auto warnings = results.find("warnings");
  if (warnings == results.end() || !warnings->is_array()) return;
  for (const nlohmann::json& warning : *warnings)
    if (warning.is_string()) note(step, "warning: " + warning.get<std::string>());
}

FigureRef RunContext::figure(const std::string& file, FigureRef::Kind kind, const std::string& caption) const {
  return {options.out_dir / file, file, kind, caption};
}

nlohmann::json RunContext::cached(const Step& step, const std::function<nlohmann::json()>& make) {
  const std::vector<std::string> artifacts = step_artifacts(step);
  const std::string hash = step_hash(step, options.quality);
  std::string names;
  for (const std::string& a : artifacts) names += (names.empty() ? "" : ", ") + a;
  if (auto hit = cache.lookup(artifacts, hash)) {
    note(step, "reused " + names + " (unchanged since the last run; --force makes it again)");
    ++summary.reused;
    return *hit;
  }
  cache.invalidate(artifacts);
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json results = make();
  cache.store(artifacts, hash, results);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  note(step, "made " + names + " in " + format_significant(seconds, 2) + " s");
  ++summary.made;
  return results;
}

std::string step_hash(const Step& step, Quality quality) {
  std::string text = "linkage lesson cache 1\nversion=" + std::string(kVersion);
  // Only clips and stills depend on --quality; plots and tables are the same either way.
  text += "\nquality=";
  text += step.kind != StepKind::render ? "any" : quality == Quality::draft ? "draft" : "final";
  text += "\ninputs=" + canonical_text(step.inputs) + "\nstep=" + step.canonical + "\n";
  return content_hash(text);
}

// --- steps that only print --------------------------------------------------------------

namespace {

std::string with_unit(double value, int digits, const std::string& unit) {
  return format_significant(value, digits) + (unit.empty() ? "" : " " + unit);
}

void run_set(RunContext& c, const Step& step, const SetStep& s) {
  const Inputs& before =
      step.number > 1 ? c.lesson.steps[static_cast<std::size_t>(step.number - 2)].inputs : c.lesson.inputs;
  std::string text = "*From here on:* ";
  if (!s.settings.empty()) {  // a mechanism's NAME=VALUE settings
    for (std::size_t i = 0; i < s.changes.size(); ++i) text += (i > 0 ? ", " : "") + s.changes[i];
    c.both([&](Writer& w) { w.markdown(text + "."); });
    return;
  }
  for (std::size_t i = 0; i < s.keys.size(); ++i) {
    const InputKey& key = *find_input_key(s.keys[i]);
    text += (i > 0 ? ", " : "") + std::string(key.key) + " = " + format_roundtrip(step.inputs.value(key)) + " " +
            std::string(key.unit) + " (was " + format_roundtrip(before.value(key)) + ")";
  }
  c.both([&](Writer& w) { w.markdown(text + "."); });
}

void wait_for_enter(RunContext& c, const std::string& prompt) {
  c.flush();
  c.out << "\n[" << prompt << "] ";
  c.out.flush();
  std::string line;
  std::getline(c.in, line);
  throw_if_interrupted();  // a signal ends the wait at once (the read returns early)
}

std::optional<double> parse_answer(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::size_t start = 0;
  while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start]))) ++start;
  if (start < text.size() && text[start] == '+') ++start;
  double value = 0;
  const char* first = text.data() + start;
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (first == last || ec != std::errc() || ptr != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

void run_exercise(RunContext& c, const ExerciseStep& e) {
  const double answer = e.answer.evaluate();
  const std::string answer_text = with_unit(answer, e.digits, e.unit);
  const std::string question = e.question.render();
  const std::string explanation = e.explanation.render();
  c.document->exercise(question, answer_text, explanation);
  if (!c.options.interactive) {
    c.terminal->exercise(question, answer_text, explanation);
    return;
  }
  c.terminal->markdown("**Exercise.** " + question);
  c.flush();
  const double tolerance = std::max(e.tolerance.value_or(0.0), e.relative_tolerance * std::fabs(answer));
  auto reveal = [&](const std::string& lead) {
    c.terminal->markdown(lead + "The answer is " + answer_text + "." + (explanation.empty() ? "" : " " + explanation));
  };
  int tries_left = e.attempts;
  while (tries_left > 0) {
    c.out << "\nYour answer" << (e.unit.empty() ? "" : " (" + e.unit + ")") << ": ";
    c.out.flush();
    std::string line;
    const bool answered = static_cast<bool>(std::getline(c.in, line));
    throw_if_interrupted();
    if (!answered) {
      c.out << "\n";
      reveal("No answer given. ");
      break;
    }
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      reveal("");
      break;
    }
    const auto given = parse_answer(line);
    if (!given) {
      c.out << "'" << line << "' is not a number" << lookalike_advice(line)
            << "; type one like 0.0123 or 1.2e-3, or press Enter to see the answer.\n";
      continue;
    }
    if (std::fabs(*given - answer) <= tolerance) {
      reveal("Right. ");
      break;
    }
    --tries_left;
    const std::string hint = e.hint.render();
    if (tries_left == 0) {
      reveal("Not quite. ");
      break;
    }
    c.out << "Not quite" << (hint.empty() ? "." : ". Hint: " + hint) << " (" << tries_left
          << (tries_left == 1 ? " try" : " tries") << " left)\n";
  }
}

void run_solve(RunContext& c, const Step& step, const SolveStep& s) {
  const Deriving deriving;  // with the printed forms: no file is begun
  const MechanismSolution worked = work_out_mechanism(
      step.mechanism ? step.mechanism->system->mechanism() : default_mechanism(step.inputs), case_ids(s.cases));
  ReportOptions options;
  options.width = c.options.width;
  options.text_style = c.options.style;
  static_assert(kSolvePartNames.size() == kReportPartCount, "a solve part for every report part, in its order");
  options.parts = s.parts;
  c.both([&](Writer& w) { w.worked_solution(worked, options); });
}

void run_modes(RunContext& c, const Step& step, const ModesStep& s) {
  const sym::System& system = *step.mechanism->system;  // parse_modes refuses a step without one
  const ModesAnalysis a = analyse_modes(system, s.at_initial, s.verify);
  ReportOptions options;
  options.width = c.options.width;
  options.text_style = c.options.style;
  options.digits = s.digits;
  c.both([&](Writer& w) { w.modes(system, a.linear, a.modes, a.checked(), options); });
}

void run_step(RunContext& c, const Step& step) {
  if (!step.heading.empty()) c.both([&](Writer& w) { w.heading(step.heading); });
  std::visit(
      [&](const auto& body) {
        using T = std::decay_t<decltype(body)>;
        if constexpr (std::is_same_v<T, SayStep>) {
          const std::string text = body.text.render();
          c.both([&](Writer& w) { w.markdown(text); });
        } else if constexpr (std::is_same_v<T, SetStep>) {
          run_set(c, step, body);
        } else if constexpr (std::is_same_v<T, PauseStep>) {
          if (c.options.interactive) wait_for_enter(c, body.prompt);
        } else if constexpr (std::is_same_v<T, ExerciseStep>) {
          run_exercise(c, body);
        } else if constexpr (std::is_same_v<T, SolveStep>) {
          run_solve(c, step, body);
        } else if constexpr (std::is_same_v<T, ModesStep>) {
          run_modes(c, step, body);
        } else if constexpr (std::is_same_v<T, SimulateStep>) {
          run_simulate(c, step, body);
        } else if constexpr (std::is_same_v<T, RenderStep>) {
          run_render(c, step, body);
        } else if constexpr (std::is_same_v<T, PlotStep>) {
          run_plot(c, step, body);
        } else {
          run_compare(c, step, body);
        }
      },
      step.body);
}

}  // namespace

RunSummary run_lesson(const Lesson& lesson, const RunnerOptions& options, std::istream& in, std::ostream& out,
                      std::ostream& status) {
  ensure_directory(options.out_dir, "out");
  RunContext c{lesson,
               options,
               in,
               out,
               status,
               make_writer(options.format, options.width, options.style),
               make_markdown_writer(),
               make_latex_writer(true),
               ArtifactCache(options.out_dir, options.force, status),
               {}};
  const std::string description = lesson.description.render();
  c.both([&](Writer& w) { w.title(lesson.title, description); });
  c.flush();
  for (const Step& step : lesson.steps) {
    if (!options.selected.empty() && !options.selected[static_cast<std::size_t>(step.number - 1)]) continue;
    try {
      run_step(c, step);
    } catch (const Error& e) {
      if (e.code() == ExitCode::interrupted) throw;
      // Name the step, so a run-time failure points into the lesson file.
      throw Error(e.code(), step.where + ": step " + std::to_string(step.number) + " (" + std::string(name(step.kind)) +
                                "): " + e.what());
    }
    ++c.summary.steps_run;
    c.flush();
  }
  // A run of part of the lesson (--only) leaves the whole lesson's document as it was.
  const bool whole = std::find(options.selected.begin(), options.selected.end(), false) == options.selected.end();
  if (whole) {
    c.summary.document = options.out_dir / "lesson.md";
    write_file_atomically(c.summary.document, c.document->take(), "out");
    c.summary.handout = options.out_dir / "lesson.tex";
    const std::string tex = latex_document(c.handout->take());
    const bool same = std::filesystem::exists(c.summary.handout) && read_file_text(c.summary.handout) == tex &&
                      std::filesystem::exists(options.out_dir / "lesson.pdf");
    write_file_atomically(c.summary.handout, tex, "out");
    if (same && options.pdf)
      c.summary.pdf = options.out_dir / "lesson.pdf";  // made from this very text before
    else if (options.pdf)
      c.summary.pdf = compile_latex_pdf(options.out_dir / "lesson.tex");
  }
  return c.summary;
}

}  // namespace linkage::lesson
