// `linkage render`: the flags turned into a Clip (src/pipeline), produced with progress
// on stderr: an MP4 (H.264), GIF or WebM (VP9) through the FFmpeg libraries, an interactive
// HTML page (pipeline/clip_page; with the case's worked equations, report/mechanism_latex), a
// numbered PNG sequence, or one still (PNG, SVG, PDF). Everything is checked before
// any work starts; outputs appear whole or not at all.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/simulation_flags.hpp"
#include "core/deriving.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "formulations/linearization.hpp"
#include "model/spanning_tree.hpp"
#include "pipeline/clip_request.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/mode_motion.hpp"
#include "pipeline/modes_sheet.hpp"
#include "pipeline/render_options.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"
#include "report/mechanism_latex.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::cli {
namespace {
namespace fs = std::filesystem;

struct RenderFlags {
  InputOptions inputs;
  SimulationFlags simulation;
  std::string out = "linkage.mp4", frames, duration, caption;
  bool quiet = false, stats = false;
  CLI::Option* out_option = nullptr;
  CLI::Option* duration_option = nullptr;
  MechanismOptions mechanism;
  std::string mode, amplitude;  // --mode N, --amplitude A as given
  std::string modes_sheet;      // --modes-sheet FILE
  bool nonlinear = false;
  CLI::Option* amplitude_option = nullptr;
  // The picture's options (pipeline/render_options), each flag's values as given.
  std::vector<std::vector<std::string>> values = std::vector<std::vector<std::string>>(render_options().size());
  std::vector<CLI::Option*> flags;
};

/// The output --out names: by default linkage.mp4, unless only a PNG sequence was asked
/// for; the sheet's file with --modes-sheet.
std::optional<fs::path> chosen_out(const RenderFlags& f) {
  if (!f.modes_sheet.empty()) return fs::path(f.modes_sheet);
  if (f.out_option->count() > 0 || f.frames.empty()) return fs::path(f.out);
  return std::nullopt;
}

/// The picture's flags read through the one table of render options; --duration and
/// --caption join them here.
RenderRequest resolve_request(const RenderFlags& f) {
  std::vector<std::pair<std::string, std::string>> given;
  const std::span<const RenderOption> options = render_options();
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (f.flags[i]->count() == 0) continue;
    std::string text;  // a repeated flag's values joined as a list
    for (std::size_t j = 0; j < f.values[i].size(); ++j) text.append(j > 0 ? "," : "").append(f.values[i][j]);
    given.emplace_back(std::string(options[i].name), text);
  }
  RenderSettings base;
  if (!f.duration.empty()) base.duration = parse_number(f.duration, "--duration", "s");
  if (!f.caption.empty()) base.captions = {{0.0, f.caption}};
  const std::optional<fs::path> out = chosen_out(f);
  RenderTarget target;
  target.still = out.has_value();
  try {
    if (out) target.still = is_still(output_kind(*out, "out"));
    if (out) target.page = output_kind(*out, "out") == OutputKind::html;
  } catch (const Error&) {  // a bad --out is the clip's checks' to report
  }
  if (!f.modes_sheet.empty()) target.still = true;
  target.spell = [](std::string_view name) { return flag_name(name); };
  try {
    return resolve_render_options(given, target, base);
  } catch (const Error& e) {
    if (e.setting() == "captions") throw e.rephrased("--caption: " + e.detail());
    throw;
  }
}

/// Where the clip goes and how messages spell its flags.
ClipPlan plan_of(const RenderFlags& f) {
  ClipPlan plan;
  if (!f.frames.empty()) plan.frames = fs::path(f.frames);
  plan.out = chosen_out(f);
  plan.assets = assets_dir(LINKAGE_ASSETS_DIR);
  plan.equations = case_equations_as<EquationsText>;
  plan.spell = [](std::string_view name) { return flag_name(name); };
  return plan;
}

void note_duration(const RenderFlags& f, bool still, bool frames) {
  if (still && !frames && f.duration_option->count() > 0 && !f.quiet)
    std::fprintf(stderr, "linkage: note: --duration applies to a clip; a still shows the time --at (default 0)\n");
}

void print_stats(const RenderStats& s, const std::string& evaluator) {
  const nlohmann::json json = {
      {"evaluator", evaluator},
      {"frames_drawn", s.frames_drawn},
      {"static_layer_draws", s.static_layer_draws},
      {"trail_points_drawn", s.trail_points_drawn},
      {"force_evaluations", s.force_evaluations},
      {"samples", s.samples},
      {"encoder_opened", s.encoder_opened},
      {"png_files_written", s.png_files_written},
      {"seconds",
       {{"simulate", s.simulate_seconds},
        {"draw", s.draw_seconds},
        {"convert", s.convert_seconds},
        {"encode", s.encode_seconds},
        {"png", s.png_seconds}}},
  };
  std::printf("%s\n", json.dump(2).c_str());
}

/// The picture's flag `name` was given.
bool given(const RenderFlags& f, std::string_view name) {
  const std::span<const RenderOption> options = render_options();
  for (std::size_t i = 0; i < options.size(); ++i)
    if (options[i].name == name) return f.flags[i]->count() > 0;
  return false;
}

/// --mode N, checked against the other flags before any work: the mode's number; 0 without --mode.
int mode_number(const RenderFlags& f, const SimulationOptions& simulation) {
  if (f.mode.empty()) {
    if (f.amplitude_option->count() > 0) throw Error::input("--amplitude: applies only with --mode N");
    if (f.nonlinear) throw Error::input("--nonlinear: applies only with --mode N");
    return 0;
  }
  const double n = parse_number(f.mode, "--mode", "");
  if (n != std::floor(n) || n < 1 || n > 1e6)
    throw Error::input("--mode: '" + f.mode +
                       "' is not a mode's number; valid: a whole number from 1, as linkage modes numbers them");
  for (const char* other : {"ensemble", "compare"})
    if (given(f, other))
      throw Error::input("--mode: draws one mode about the equilibrium; it does not combine with " + flag_name(other));
  if (!f.nonlinear && simulation.case_id != 3)
    throw Error::input("--case: " + std::to_string(simulation.case_id) +
                       " applies to --mode only with --nonlinear; the linear motion is in Case 3's coordinates");
  return static_cast<int>(n);
}

/// --modes-sheet FILE: every mode in one still, its flags checked before any work.
ClipResult render_modes_sheet(const RenderFlags& f) {
  const std::string alone = "--modes-sheet: draws every mode in one still; it does not combine with ";
  for (const std::string_view other : kModesSheetConflicts)
    if (given(f, other) || (other == "mode" && !f.mode.empty()) || (other == "nonlinear" && f.nonlinear))
      throw Error::input(alone + flag_name(other));
  if (!f.caption.empty()) throw Error::input(alone + "--caption (each panel has its own)");
  if (f.duration_option->count() > 0) throw Error::input(alone + "--duration");
  if (f.out_option->count() > 0) throw Error::input(alone + "--out '" + f.out + "'; the sheet is its own output");
  if (!f.frames.empty()) throw Error::input(alone + "--frames");
  const fs::path out(f.modes_sheet);
  bool still = false;
  try {
    still = is_still(output_kind(out, "modes_sheet"));
  } catch (const Error&) {  // not a picture at all: the same answer
  }
  if (!still)
    throw Error::invalid("modes_sheet", "'" + f.modes_sheet + "' is not a still; valid: a .png, .svg or .pdf file");
  const double amplitude = f.amplitude.empty() ? 0.1 : parse_number(f.amplitude, "--amplitude", "rad or m");
  check_amplitude(amplitude);
  const RenderRequest request = resolve_request(f);
  const SimulationOptions simulation = resolve_simulation_flags(f.simulation, request.settings.duration);
  if (simulation.case_id != 3)
    throw Error::input("--case: " + std::to_string(simulation.case_id) +
                       " does not apply to --modes-sheet; the modes are in Case 3's coordinates");
  Deriving deriving(f.quiet);
  const MechanismSolution checked = work_out_mechanism(chosen_mechanism(f.mechanism, f.inputs), {CaseId::reduced});
  ClipPlan plan = plan_of(f);
  plan.frames.reset();
  CheckedMechanismClip made;
  try {
    made = mechanism_clip(request, *checked.system, checked.state, simulation, plan);
  } catch (const Error& e) {
    if (e.setting() == "out") throw e.rephrased("--modes-sheet: " + e.detail());
    throw;
  }
  deriving.done();
  const EndAtOnceOnSignal until_a_file_is_begun;
  try {
    produce_modes_sheet(*checked.system, made.clip, amplitude, out, "modes_sheet");
  } catch (const Error& e) {  // what linearize refuses, named by the flag that asked for it
    const std::string what = e.what();
    if (e.code() == ExitCode::bad_input && what.rfind("modes: ", 0) == 0)
      throw e.rephrased("--modes-sheet: " + what.substr(7));
    throw;
  }
  ClipResult result;
  result.stats.png_files_written = output_kind(out, "modes_sheet") == OutputKind::png ? 1 : 0;
  return result;
}

/// The mechanism's clip (the homework's flags and --config are settings of two-blocks.toml):
/// its scene and camera, its outputs, every check before any work.
ClipResult render_mechanism(const RenderFlags& f, const ClipProgress& progress) {
  if (!f.modes_sheet.empty()) return render_modes_sheet(f);
  RenderRequest request = resolve_request(f);
  const ClipPlan plan = plan_of(f);
  const SimulationOptions simulation = resolve_simulation_flags(f.simulation, request.settings.duration);
  const int mode = mode_number(f, simulation);
  const double amplitude = f.amplitude.empty() ? 0.1 : parse_number(f.amplitude, "--amplitude", "rad or m");
  Deriving deriving(f.quiet);
  // The initial state worked out as solve does, so a value that breaks it is named the same way.
  const MechanismSolution checked =
      work_out_mechanism(chosen_mechanism(f.mechanism, f.inputs), {static_cast<CaseId>(simulation.case_id)});
  const sym::System& system = *checked.system;
  std::optional<ModeMotion> shown;  // --mode: the motion drawn instead of the file's initial state's
  if (mode > 0) {
    const Linearization linear = linearize(system);
    shown = mode_motion(system, linear, modal_analysis(linear), mode, amplitude, f.nonlinear);
    if (f.caption.empty()) request.settings.captions = {{0.0, shown->caption}};
  }
  const GiNaC::exmap& initial = shown ? shown->initial : checked.state;
  CheckedMechanismClip made = mechanism_clip(request, system, initial, simulation, plan);
  made.clip.derived = checked.cases.front().system;
  if (shown) show_mode(made.clip, *shown);
  // A page shows the case's worked equations beside the clip: `solve --case N --format markdown`'s.
  if (made.clip.out && output_kind(*made.clip.out, "out") == OutputKind::html)
    made.clip.equations_html = mechanism_html(checked, ReportOptions{});
  const MechanismClip& clip = made.clip;
  deriving.done();
  note_duration(f, clip.is_still(), clip.frames.has_value());
  if (!f.quiet) {
    // Only whether the case keeps any constraint matters to the notes: Case 1 keeps every
    // joint, Cases 2 and 3 the joints that close loops.
    int kept = 0;
    for (const sym::JointSystem& joint : system.joints())
      if (clip.simulation.case_id == 1 || !joint.in_tree) ++kept;
    note_ignored_simulation_flags(f.simulation, clip.simulation, kept,
                                  !system.drivers().empty() && degrees_of_freedom(system.mechanism()) == 0);
    if (!checked.closure_note.empty()) std::fprintf(stderr, "linkage: note: %s\n", checked.closure_note.c_str());
  }
  // Sampling the motion compiles more of a long chain's expressions: until the output is
  // begun (file_begun), a signal still ends the run at once.
  const EndAtOnceOnSignal until_a_file_is_begun;
  return produce_mechanism_clip(system, initial, clip, progress);
}

void run_render(const RenderFlags& flags) {
  std::optional<Progress> progress;
  ClipStage shown = ClipStage::simulate;
  const ClipProgress report = [&](ClipStage stage, long done, long total) {
    if (!progress || stage != shown) {
      if (progress) progress->finish();
      progress.emplace(std::string(name(stage)), total, stage == ClipStage::simulate ? "samples" : "frames",
                       flags.quiet);
      shown = stage;
    }
    progress->update(done);
  };
  const ClipResult result = render_mechanism(flags, report);
  if (progress) progress->finish();
  if (!flags.quiet)
    for (const std::string& note : result.notes) std::fprintf(stderr, "linkage: %s\n", note.c_str());
  for (const std::string& warning : result.warnings) std::fprintf(stderr, "linkage: warning: %s\n", warning.c_str());
  if (flags.stats) print_stats(result.stats, result.evaluator);
}

}  // namespace

void register_render(CLI::App& app) {
  auto f = std::make_shared<RenderFlags>();
  CLI::App* sub = app.add_subcommand("render",
                                     "Draw the motion: an MP4 clip, an interactive HTML page, a PNG sequence, or a "
                                     "PNG/SVG/PDF still");
  const std::string output = "Output";
  f->out_option = sub->add_option("--out", f->out,
                                  "Output file: .mp4 (H.264), .gif or .webm (VP9) clip, .html (interactive page: play, "
                                  "scrub, toggle forces, read values; one self-contained file), .png (still), .svg or "
                                  ".pdf (vector still); "
                                  "written atomically (default linkage.mp4, or none with --frames alone)")
                      ->type_name("FILE")
                      ->group(output);
  sub->add_option("--frames", f->frames,
                  "Also (or instead) write the clip as DIR/frame_00000.png ... (DIR is made with its parents)")
      ->type_name("DIR")
      ->group(output);
  f->duration_option =
      sub->add_option("--duration", f->duration,
                      "Simulated time the clip shows, s (default 10); the video lasts duration / speed "
                      "and has round(duration / speed x fps) frames")
          ->type_name("S")
          ->group(output);
  sub->add_flag("--quiet", f->quiet, "No progress or notes on stderr")->group(output);
  sub->add_flag("--stats", f->stats, "Print counters and per-stage times as JSON on stdout")->group(output);

  sub->add_option("--caption", f->caption, "Words shown under the picture in every frame (wrapped)")
      ->type_name("TEXT")
      ->group(output);
  const std::span<const RenderOption> options = render_options();
  for (std::size_t i = 0; i < options.size(); ++i) {
    const RenderOption& o = options[i];
    // A plain default (a number or a word) is said after the meaning; others are in it.
    std::string fallback(o.default_text);
    std::erase(fallback, '"');
    std::string help = o.doc;
    if (fallback != "none" && fallback.find(' ') == std::string::npos) help += " (default " + fallback + ")";
    CLI::Option* flag = sub->add_option(flag_name(o.name), f->values[i], help)
                            ->type_name(std::string(o.placeholder))
                            ->expected(1)
                            ->group("Picture");
    flag->multi_option_policy(o.value == RenderValue::list ? CLI::MultiOptionPolicy::TakeAll
                                                           : CLI::MultiOptionPolicy::TakeLast);
    f->flags.push_back(flag);
  }
  const std::string modes = "Mode (linkage modes)";
  sub->add_option("--mode", f->mode,
                  "Draw mode N (from 1, as linkage modes numbers them) about the equilibrium: the linear motion "
                  "q0 + A shape cos(omega t), prescribed, not integrated")
      ->type_name("N")
      ->group(modes);
  f->amplitude_option =
      sub->add_option("--amplitude", f->amplitude,
                      "The mode's amplitude: the largest coordinate's displacement, rad or m (default 0.1)")
          ->type_name("A")
          ->group(modes);
  sub->add_option("--modes-sheet", f->modes_sheet,
                  "Instead of a clip, every mode in one still (.png, .svg or .pdf): a panel per mode, the mechanism "
                  "at +A and -A about the equilibrium, its frequency and shape; --amplitude sets A")
      ->type_name("FILE")
      ->group(modes);
  sub->add_flag("--nonlinear", f->nonlinear,
                "With --mode: the full equations started at rest on the equilibrium displaced along the mode")
      ->group(modes);
  add_simulation_flags(sub, f->simulation);
  add_input_options(sub, f->inputs);
  add_mechanism_options(sub, f->mechanism);
  add_runner(sub, [f] { run_render(*f); });
}

}  // namespace linkage::cli
