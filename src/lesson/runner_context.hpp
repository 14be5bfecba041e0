#pragma once
// What every step of a running lesson shares (internal to the runner's files).
#include <functional>
#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>

#include "lesson/cache.hpp"
#include "lesson/runner.hpp"
#include "report/document_writer.hpp"

namespace linkage::lesson {

struct RunContext {
  const Lesson& lesson;
  const RunnerOptions& options;
  std::istream& in;
  std::ostream& out;
  std::ostream& status;
  std::unique_ptr<Writer> terminal;
  std::unique_ptr<Writer> document;
  std::unique_ptr<Writer> handout;  // lesson.tex
  ArtifactCache cache;
  RunSummary summary;

  /// Calls `f` on the terminal writer and on the document writers (lesson.md, lesson.tex).
  template <class F>
  void both(F&& f) {
    f(*terminal);
    f(*document);
    f(*handout);
  }
  /// Sends the terminal writer's text to `out`.
  void flush();
  /// A status line on `status`: "lesson: step 5 (render): ...".
  void note(const Step& step, const std::string& text);
  /// A "warning: ..." status line for each of `results`' "warnings" (runs whose numbers
  /// are meaningless, see result_warning), whether the results are new or reused.
  void warn(const Step& step, const nlohmann::json& results);
  /// A file the step wrote, for the writers.
  [[nodiscard]] FigureRef figure(const std::string& name, FigureRef::Kind kind, const std::string& caption) const;
  /// Runs `make` (which writes the step's artifacts and returns what it printed) unless
  /// the artifacts are cached; returns the results either way.
  nlohmann::json cached(const Step& step, const std::function<nlohmann::json()>& make);
};

void run_simulate(RunContext& c, const Step& step, const SimulateStep& s);
void run_plot(RunContext& c, const Step& step, const PlotStep& s);
void run_compare(RunContext& c, const Step& step, const CompareStep& s);
void run_render(RunContext& c, const Step& step, const RenderStep& s);

}  // namespace linkage::lesson
