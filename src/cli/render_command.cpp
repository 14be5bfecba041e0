// `linkage render`: the flags turned into a Clip (src/pipeline), produced with progress
// on stderr: an MP4 (H.264), GIF or WebM (VP9) through the FFmpeg libraries, a numbered PNG sequence, or
// one still (PNG, SVG, PDF). Everything is checked before any work starts; outputs
// appear whole or not at all.
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

#include "cli/angle_option.hpp"
#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/overlay_options.hpp"
#include "cli/simulation_flags.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"
#include "report/mechanism_text.hpp"
#include "scene/scene_builder.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::cli {
namespace {
namespace fs = std::filesystem;

struct RenderFlags {
  InputOptions inputs;
  SimulationFlags simulation;
  std::string out = "linkage.mp4", frames, quality = "medium", size, fps, duration, speed, at;
  std::string camera = "follow", view, theme = "light", title, panel, caption, arrow_scale;
  std::vector<std::string> show, hide;
  std::string angles = "rad";
  bool quiet = false, stats = false;
  CLI::Option* out_option = nullptr;
  CLI::Option* title_option = nullptr;
  CLI::Option* camera_option = nullptr;
  CLI::Option* at_option = nullptr;
  CLI::Option* duration_option = nullptr;
  CLI::Option* show_option = nullptr;
  CLI::Option* hide_option = nullptr;
  CLI::Option* view_option = nullptr;
  MechanismOptions mechanism;
  std::vector<std::string> trails;  // --trail BODY.POINT, with --mechanism
  OverlayFlags overlays;            // --ensemble, --spread, --compare
};

int parse_whole(const std::string& text, const std::string& origin) {
  const double value = parse_number(text, origin, "");
  if (value != std::floor(value) || std::fabs(value) > 1e9)
    throw Error::input(origin + ": '" + text + "' is not a whole number");
  return static_cast<int>(value);
}

RenderSettings resolve_settings(const RenderFlags& f) {
  RenderSettings s;
  const Quality& quality = parse_quality(f.quality, "--quality");
  s.width = quality.width;
  s.height = quality.height;
  s.fps = quality.fps;
  if (!f.size.empty()) parse_size(f.size, "--size", s.width, s.height);
  if (!f.fps.empty()) s.fps = parse_whole(f.fps, "--fps");
  if (!f.duration.empty()) s.duration = parse_number(f.duration, "--duration", "s");
  if (!f.speed.empty()) s.speed = parse_number(f.speed, "--speed", "simulated s per video s");
  if (!f.at.empty()) s.at = parse_number(f.at, "--at", "s");
  // --view alone implies the fixed camera; with another camera it is a mistake.
  // "--view fbd" is the free-body view instead, with any camera.
  const bool camera_given = f.camera_option->count() > 0;
  s.free_body = f.view == "fbd";
  const std::string rectangle = s.free_body ? "" : f.view;
  s.camera =
      camera_given ? parse_camera(f.camera, "--camera") : (rectangle.empty() ? CameraMode::follow : CameraMode::fixed);
  if (!rectangle.empty()) {
    s.view = parse_view(rectangle, "--view");
    if (s.camera != CameraMode::fixed)
      throw Error::input("--view: applies only to --camera fixed (the " + f.camera + " camera chooses its own view)");
  } else if (s.camera == CameraMode::fixed) {
    throw Error::input("--camera fixed: needs --view xmin,ymin,xmax,ymax (metres)");
  }
  s.theme = f.theme;
  if (f.title_option->count() > 0) s.title = f.title;
  apply_show_hide(s.elements, f.show, f.hide);
  static constexpr std::array<std::string_view, 2> kMechanismKinds{"joint", "applied"};
  if (!f.arrow_scale.empty())
    s.arrow_scale =
        parse_arrow_scale_request(f.arrow_scale, "--arrow-scale",
                                  f.mechanism.chosen() ? std::span<const std::string_view>(kMechanismKinds)
                                                       : std::span<const std::string_view>(kArrowKindNames));
  s.panel = split_commas(f.panel);
  s.angles = parse_angle_unit(f.angles, "--angles");
  if (!f.caption.empty()) s.captions = {{0.0, f.caption}};
  try {
    s.validate();
  } catch (const Error& e) {
    if (e.setting() == "captions") throw e.rephrased("--caption: " + e.detail());
    throw;
  }
  return s;
}

/// The case's equations as `linkage solve --case N` prints them, for --show equations.
EquationsText shown_equations(const sym::System& system, int case_id) {
  CaseEquations e = case_equations(system, static_cast<CaseId>(case_id));
  return {std::move(e.heading), std::move(e.lines)};
}

/// The clip the flags describe, checked before any work.
Clip resolve_clip(const RenderFlags& f) {
  Clip clip;
  clip.settings = resolve_settings(f);
  if (!f.frames.empty()) clip.frames = fs::path(f.frames);
  // --out defaults to linkage.mp4 unless only a PNG sequence was asked for.
  if (f.out_option->count() > 0 || !clip.frames) clip.out = fs::path(f.out);
  clip.theme = load_theme(clip.settings.theme, assets_dir(LINKAGE_ASSETS_DIR), "theme");
  clip.simulation = resolve_simulation_flags(f.simulation, clip.settings.duration);
  clip.inputs = resolve_inputs(f.inputs);
  if (clip.settings.elements.has(Element::equations))
    clip.settings.equations =
        shown_equations(sym::System(chosen_mechanism(f.mechanism, f.inputs)), clip.simulation.case_id);
  resolve_homework_overlays(f.overlays, clip);
  clip.validate();  // the output's checks first, then what only the flags can say
  const bool still = clip.is_still();
  if (f.at_option->count() > 0 && !still)
    throw Error::input("--at: applies to a still (--out FILE.png, .svg or .pdf); a clip shows 0 .. --duration");
  if (still && !clip.frames && f.duration_option->count() > 0 && !f.quiet)
    std::fprintf(stderr, "linkage: note: --duration applies to a clip; a still shows the time --at (default 0)\n");
  if (!f.quiet) note_ignored_simulation_flags(f.simulation, clip.simulation);
  return clip;
}

void print_stats(const RenderStats& s) {
  const nlohmann::json json = {
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

/// The homework's picture flags have no meaning for a mechanism: an error, not ignored.
/// Only --show equations applies to both.
void reject_homework_flags(const RenderFlags& f) {
  for (const std::string& list : f.show)
    for (const std::string& item : split_commas(list))
      if (item != "equations")
        throw Error::input("--show: '" + item +
                           "' applies to the homework only; with --mechanism --show takes only equations (the picture "
                           "is fixed and the camera fits the whole motion, or follows a floating mechanism)");
  const std::pair<CLI::Option*, const char*> flags[] = {
      {f.hide_option, "--hide"}, {f.camera_option, "--camera"}, {f.view_option, "--view"}};
  for (const auto& [option, flag] : flags)
    if (option->count() > 0)
      throw Error::input(std::string(flag) +
                         ": applies to the homework only; with --mechanism the picture is fixed and the camera "
                         "fits the whole motion (or follows a floating mechanism)");
}

/// Any mechanism (--mechanism): its own scene and camera, the same outputs and checks.
ClipResult render_mechanism(const RenderFlags& f, const ClipProgress& progress) {
  reject_homework_flags(f);
  const sym::System system(chosen_mechanism(f.mechanism, f.inputs));
  MechanismClip clip;
  clip.settings = resolve_settings(f);
  if (f.title_option->count() == 0) clip.settings.title = system.mechanism().title;
  if (!f.frames.empty()) clip.frames = fs::path(f.frames);
  if (f.out_option->count() > 0 || !clip.frames) clip.out = fs::path(f.out);
  clip.theme = load_theme(clip.settings.theme, assets_dir(LINKAGE_ASSETS_DIR), "theme");
  clip.simulation = resolve_simulation_flags(f.simulation, clip.settings.duration);
  clip.trails = f.trails;
  std::unique_ptr<sym::System> compared;  // the compared run's own, when --compare sets a value
  resolve_overlay_flags(f.overlays, f.mechanism, f.inputs, f.simulation, clip, compared);
  if (clip.settings.elements.has(Element::equations))
    clip.settings.equations = shown_equations(system, clip.simulation.case_id);
  clip.validate(system);
  const bool still = clip.is_still();
  if (f.at_option->count() > 0 && !still)
    throw Error::input("--at: applies to a still (--out FILE.png); a clip shows 0 .. --duration");
  const sym::ClosedState closed = sym::checked_initial_state(system);
  if (clip.compare && clip.compare->system == nullptr) clip.compare->initial = closed.state;
  if (!f.quiet) {
    if (still && !clip.frames && f.duration_option->count() > 0)
      std::fprintf(stderr, "linkage: note: --duration applies to a clip; a still shows the time --at (default 0)\n");
    // Only whether the case keeps any constraint matters to the notes: Case 1 keeps every
    // joint, Cases 2 and 3 the joints that close loops.
    int kept = 0;
    for (const sym::JointSystem& joint : system.joints())
      if (clip.simulation.case_id == 1 || !joint.in_tree) ++kept;
    note_ignored_simulation_flags(f.simulation, clip.simulation, kept);
    if (!closed.note.empty()) std::fprintf(stderr, "linkage: note: %s\n", closed.note.c_str());
  }
  return produce_mechanism_clip(system, closed.state, clip, progress);
}

void run_render(const RenderFlags& flags) {
  if (!flags.mechanism.chosen()) {
    if (!flags.trails.empty()) throw Error::input("--trail: applies only with --mechanism");
    if (!flags.mechanism.settings.empty())
      throw Error::input("--set: applies only with --mechanism; the homework takes its own flags");
  }
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
  const ClipResult result =
      flags.mechanism.chosen() ? render_mechanism(flags, report) : produce_clip(resolve_clip(flags), report);
  if (progress) progress->finish();
  if (!flags.quiet)
    for (const std::string& note : result.notes) std::fprintf(stderr, "linkage: %s\n", note.c_str());
  for (const std::string& warning : result.warnings) std::fprintf(stderr, "linkage: warning: %s\n", warning.c_str());
  if (flags.stats) print_stats(result.stats);
}

}  // namespace

void register_render(CLI::App& app) {
  auto f = std::make_shared<RenderFlags>();
  CLI::App* sub = app.add_subcommand("render", "Draw the motion: an MP4 clip, a PNG sequence, or a PNG/SVG/PDF still");
  const std::string output = "Output";
  f->out_option = sub->add_option("--out", f->out,
                                  "Output file: .mp4 (H.264), .gif or .webm (VP9) clip, .png (still), .svg or .pdf "
                                  "(vector still); "
                                  "written atomically (default linkage.mp4, or none with --frames alone)")
                      ->type_name("FILE")
                      ->group(output);
  sub->add_option("--frames", f->frames,
                  "Also (or instead) write the clip as DIR/frame_00000.png ... (DIR is made with its parents)")
      ->type_name("DIR")
      ->group(output);
  std::string presets;
  for (const Quality& q : kQualities)
    presets += (presets.empty() ? "" : ", ") + std::string(q.name) + " " + std::to_string(q.width) + "x" +
               std::to_string(q.height) + "@" + std::to_string(q.fps);
  sub->add_option("--quality", f->quality, "Size and frame rate preset: " + presets + " (default medium)")
      ->type_name("NAME")
      ->group(output);
  sub->add_option("--size", f->size, "Frame size WIDTHxHEIGHT in pixels, even, at most 7680x4320 (overrides --quality)")
      ->type_name("WxH")
      ->group(output);
  sub->add_option("--fps", f->fps, "Frames per second, 1 .. 240 (overrides --quality)")->type_name("N")->group(output);
  f->duration_option =
      sub->add_option("--duration", f->duration,
                      "Simulated time the clip shows, s (default 10); the video lasts duration / speed "
                      "and has round(duration / speed x fps) frames")
          ->type_name("S")
          ->group(output);
  sub->add_option("--speed", f->speed, "Simulated seconds per second of video (default 1; below 1 is slow motion)")
      ->type_name("X")
      ->group(output);
  f->at_option = sub->add_option("--at", f->at, "Time a still shows, s (default 0)")->type_name("S")->group(output);
  sub->add_flag("--quiet", f->quiet, "No progress or notes on stderr")->group(output);
  sub->add_flag("--stats", f->stats, "Print counters and per-stage times as JSON on stdout")->group(output);

  const std::string look = "Picture";
  f->show_option = sub->add_option("--show", f->show,
                                   "Elements to show (comma-separated): " + element_name_list() +
                                       "; equations draws the --case's equations under the motion as `linkage "
                                       "solve` prints them (the only element --mechanism takes)")
                       ->type_name("LIST")
                       ->group(look);
  f->hide_option = sub->add_option("--hide", f->hide, "Elements to hide; default shows all but velocity and axes")
                       ->type_name("LIST")
                       ->group(look);
  f->camera_option = sub->add_option("--camera", f->camera,
                                     "follow (keeps the falling centre of mass in view; default), fixed (--view), "
                                     "or fit (the whole motion)")
                         ->type_name("MODE")
                         ->group(look);
  f->view_option =
      sub->add_option("--view", f->view,
                      "World rectangle xmin,ymin,xmax,ymax in metres for the fixed camera, or fbd: the free-body "
                      "view (the blocks drawn apart at the pin, each with its forces)")
          ->type_name("X0,Y0,X1,Y1|fbd")
          ->group(look);
  sub->add_option("--theme", f->theme, "Colours: " + theme_name_list() + " (default light; palettes in assets/themes)")
      ->type_name("NAME")
      ->group(look);
  f->title_option =
      sub->add_option("--title", f->title, "Title line (default \"" + RenderSettings{}.title + "\"; \"\" for none)")
          ->type_name("TEXT")
          ->group(look);
  sub->add_option("--arrow-scale", f->arrow_scale,
                  "Arrow lengths: each kind its own scale (default); common (every force one scale, so the pin "
                  "force reads against gravity; common=N_PER_CM sets it); KIND=N_PER_CM,... fixes kinds (pin, "
                  "gravity, velocity; with --mechanism joint, applied). Arrows too short to see are drawn dashed "
                  "at a least length, labelled with their value")
      ->type_name("SPEC")
      ->group(look);
  sub->add_option("--panel", f->panel,
                  "Plot these quantities beside the motion, with a cursor at the frame's time: --panel theta1,theta2 "
                  "(the names a lesson's plot step takes; with --mechanism its columns, e.g. 2.theta,B.force_x)")
      ->type_name("LIST")
      ->group(look);
  sub->add_option("--caption", f->caption, "Words shown under the picture in every frame (wrapped)")
      ->type_name("TEXT")
      ->group(look);
  sub->add_option("--trail", f->trails,
                  "With --mechanism: draw the path of a body's point over the last 2 s, repeatable: --trail 3.B")
      ->type_name("BODY.POINT")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->group(look);
  add_angle_option(sub, f->angles, "the --panel's angles and angular rates (axis in deg, deg/s)");
  sub->get_option("--angles")->group(look);
  add_overlay_options(sub, f->overlays, look);
  add_simulation_flags(sub, f->simulation);
  add_input_options(sub, f->inputs);
  add_mechanism_options(sub, f->mechanism);
  add_runner(sub, [f] { run_render(*f); });
}

}  // namespace linkage::cli
