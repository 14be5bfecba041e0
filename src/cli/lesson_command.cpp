// `linkage lesson FILE`: runs a lesson script (lessons/README.md describes the format).
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/step_range.hpp"
#include "core/deriving.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/program_path.hpp"
#include "lesson/lesson.hpp"
#include "lesson/runner.hpp"
#include "render/theme.hpp"
#include "report/report_options.hpp"

namespace linkage::cli {
namespace {

struct LessonOptions {
  std::string file;
  std::string out;
  bool step = false;
  std::string quality = "draft";
  std::string format = "text";
  std::string only;
  bool force = false;
  bool check = false;
  bool pdf = false;
};

/// $COLUMNS when set, else the terminal's width, else 80; never below 40.
std::size_t terminal_width() {
  std::size_t width = 80;
  if (const char* columns = std::getenv("COLUMNS"); columns != nullptr && *columns != '\0') {
    std::size_t value = 0;
    const char* end = columns + std::char_traits<char>::length(columns);
    if (auto [ptr, ec] = std::from_chars(columns, end, value); ec == std::errc() && ptr == end) width = value;
  } else if (::isatty(STDOUT_FILENO) == 1) {
    winsize size{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) width = size.ws_col;
  }
  return std::max<std::size_t>(width, 40);
}

void run_lesson_command(const LessonOptions& o) {
  lesson::RunnerOptions options;
  if (o.quality == "draft")
    options.quality = lesson::Quality::draft;
  else if (o.quality == "final")
    options.quality = lesson::Quality::final;
  else
    throw Error::input("--quality: '" + o.quality + "' is not a quality" + did_you_mean(o.quality, {"draft", "final"}) +
                       "; valid: draft, final");
  if (o.format == "text")
    options.format = DocumentFormat::text;
  else if (o.format == "markdown")
    options.format = DocumentFormat::markdown;
  else if (o.format == "latex")
    options.format = DocumentFormat::latex;
  else
    throw Error::input("--format: '" + o.format + "' is not a format; valid: text, markdown, latex");

  // Reading a lesson derives its mechanisms' equations.
  Deriving deriving;
  const lesson::Lesson lesson = lesson::parse_lesson(o.file);
  deriving.done();
  if (!o.only.empty()) options.selected = parse_step_range(o.only, lesson.steps.size());
  if (o.check) {
    std::cout << o.file << ": valid; " << lesson.steps.size() << " steps";
    const std::vector<std::string> artifacts = lesson.artifacts();
    for (std::size_t i = 0; i < artifacts.size(); ++i) std::cout << (i == 0 ? "; writes " : ", ") << artifacts[i];
    std::cout << "\n";
    return;
  }
  options.out_dir = o.out.empty() ? std::filesystem::path(lesson.name) : std::filesystem::path(o.out);
  options.interactive = o.step;
  options.pdf = o.pdf;
  if (o.pdf && !on_path("pdflatex"))
    throw Error::input(
        "--pdf: pdflatex is not installed; install Debian's texlive-latex-recommended and lmodern, or leave out "
        "--pdf (lesson.tex is written either way)");
  options.force = o.force;
  options.width = terminal_width();
  options.style = text_style_from_locale();
  options.assets = assets_dir(LINKAGE_ASSETS_DIR);
  const lesson::RunSummary summary = lesson::run_lesson(lesson, options, std::cin, std::cout, std::cerr);
  // The lesson's text must have arrived before the summary says it ran.
  errno = 0;
  if (!std::cout.flush() || std::fflush(stdout) != 0 || std::ferror(stdout) != 0)
    throw Error::failure("cannot write standard output: " +
                         std::string(errno != 0 ? std::strerror(errno) : "write error"));
  std::cerr << "lesson: ran " << summary.steps_run << " of " << lesson.steps.size() << " steps; " << summary.made
            << " made, " << summary.reused << " reused; "
            << (summary.document.empty() ? "lesson.md left as it was (--only ran part of the lesson)"
                                         : "document " + summary.document.string())
            << (summary.handout.empty() ? "" : ", handout " + summary.handout.string())
            << (summary.pdf.empty() ? "" : " and " + summary.pdf.string()) << "\n";
}

}  // namespace

void register_lesson(CLI::App& app) {
  auto o = std::make_shared<LessonOptions>();
  CLI::App* sub = app.add_subcommand(
      "lesson",
      "Run a lesson script: print it, write its clips, plots and tables, and a lesson document (lessons/README.md)");
  sub->add_option("FILE", o->file, "The lesson, a TOML file (e.g. lessons/06-numerical-example.toml)")
      ->required()
      ->type_name("FILE");
  sub->add_option("--out", o->out, "Folder for the artifacts and lesson.md (default: a folder named after the lesson)")
      ->type_name("DIR");
  sub->add_flag("--step", o->step, "Go step by step: wait for Enter at pauses and ask the exercises");
  sub->add_option("--quality", o->quality,
                  "draft (480x270 at 15 fps, fast) or final (each render step's own size and rate) (default draft)")
      ->type_name("draft|final");
  sub->add_option("--format", o->format, "Terminal output: text, markdown or latex (default text)")
      ->type_name("FORMAT");
  sub->add_option("--only", o->only,
                  "Run only these steps, e.g. 3, 2-5, 4-, -3 or 1,4-6; earlier set steps still apply")
      ->type_name("RANGE");
  sub->add_flag("--force", o->force, "Make every artifact again, even if unchanged since the last run");
  sub->add_flag("--check", o->check, "Only validate the lesson and list the files it would write");
  sub->add_flag("--pdf", o->pdf,
                "Also compile the handout lesson.tex (always written beside lesson.md) to lesson.pdf with pdflatex");
  add_runner(sub, [o] { run_lesson_command(*o); });
}

}  // namespace linkage::cli
