// `linkage render`: the motion drawn with Cairo into an MP4 (H.264 through the FFmpeg
// libraries), a numbered PNG sequence, or one still (PNG, SVG, PDF). Everything is
// checked before any work starts; outputs appear whole or not at all.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/simulation_flags.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "core/progress.hpp"
#include "encode/frame_pipeline.hpp"
#include "encode/png_writer.hpp"
#include "encode/video_writer.hpp"
#include "integrate/simulation.hpp"
#include "render/clip_renderer.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"
#include "render/vector_still.hpp"
#include "scene/motion.hpp"

namespace linkage::cli {
namespace {
namespace fs = std::filesystem;

struct RenderFlags {
  InputOptions inputs;
  SimulationFlags simulation;
  std::string out = "linkage.mp4", frames, quality = "medium", size, fps, duration, speed, at;
  std::string camera = "follow", view, theme = "light", title;
  std::vector<std::string> show, hide;
  bool quiet = false, stats = false;
  CLI::Option* out_option = nullptr;
  CLI::Option* title_option = nullptr;
  CLI::Option* camera_option = nullptr;
  CLI::Option* at_option = nullptr;
  CLI::Option* duration_option = nullptr;
};

/// Everything a run needs, parsed and checked.
struct RenderJob {
  Inputs inputs;
  SimulationOptions simulation;
  RenderSettings settings;
  Theme theme;
  std::string run;                   // the HUD's "Case 3 · dop853"
  std::optional<fs::path> out;       // the video or the still
  OutputKind out_kind = OutputKind::mp4;
  std::optional<fs::path> frames;    // the PNG sequence's folder
  bool quiet = false;
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
  const bool camera_given = f.camera_option->count() > 0;
  s.camera = camera_given ? parse_camera(f.camera, "--camera") : (f.view.empty() ? CameraMode::follow : CameraMode::fixed);
  if (!f.view.empty()) {
    s.view = parse_view(f.view, "--view");
    if (s.camera != CameraMode::fixed)
      throw Error::input("--view: applies only to --camera fixed (the " + f.camera + " camera chooses its own view)");
  } else if (s.camera == CameraMode::fixed) {
    throw Error::input("--camera fixed: needs --view xmin,ymin,xmax,ymax (metres)");
  }
  s.theme = f.theme;
  if (f.title_option->count() > 0) s.title = f.title;
  apply_show_hide(s.elements, f.show, f.hide);
  s.validate();
  return s;
}

std::string run_text(const SimulationOptions& s) {
  std::string text = "Case " + std::to_string(s.case_id) + " \u00b7 " + std::string(info(s.integrator).name);
  if (s.case_id == 1)  // only Case 1 can drift off the pin, so only there does stabilization matter
    text += s.stabilization == Stabilization::none ? std::string(" \u00b7 no stabilization")
                                                   : " \u00b7 " + std::string(name(s.stabilization));
  return text;
}

VideoOptions video_options(const RenderSettings& s) {
  VideoOptions v;
  v.width = s.width;
  v.height = s.height;
  v.fps = s.fps;
  v.origin = "--out";
  return v;
}

RenderJob resolve_job(const RenderFlags& f) {
  RenderJob job;
  job.settings = resolve_settings(f);
  job.quiet = f.quiet;
  if (!f.frames.empty()) {
    job.frames = fs::path(f.frames);
    require_writable_directory(*job.frames, "--frames");
  }
  // --out defaults to linkage.mp4 unless only a PNG sequence was asked for.
  if (f.out_option->count() > 0 || !job.frames) job.out = fs::path(f.out);
  if (job.out) {
    std::error_code ec;
    if (fs::is_directory(*job.out, ec)) throw Error::input("--out: '" + job.out->string() + "' is a folder, expected a file name");
    job.out_kind = output_kind(*job.out, "--out");
    require_writable_directory(job.out->parent_path(), "--out");
    if (job.out_kind == OutputKind::mp4) VideoWriter::validate(video_options(job.settings));
  }
  const bool still = job.out && is_still(job.out_kind);
  if (f.at_option->count() > 0 && !still)
    throw Error::input("--at: applies to a still (--out FILE.png, .svg or .pdf); a clip shows 0 .. --duration");
  if (still && !job.frames && f.duration_option->count() > 0 && !f.quiet)
    std::fprintf(stderr, "linkage: note: --duration applies to a clip; a still shows the time --at (default 0)\n");
  job.theme = load_theme(job.settings.theme, assets_dir(LINKAGE_ASSETS_DIR), "--theme");
  job.simulation = resolve_simulation_flags(f.simulation, job.settings.duration);
  job.inputs = resolve_inputs(f.inputs);
  if (!f.quiet) note_ignored_simulation_flags(f.simulation, job.simulation);
  job.run = run_text(job.simulation);
  return job;
}

template <typename Work>
auto timed(double& seconds, Work work) {
  const auto start = std::chrono::steady_clock::now();
  auto result = work();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// Samples the motion at `times` with its own simulation of `options`.
Motion simulate(const RenderJob& job, SimulationOptions options, const std::vector<double>& times, RenderStats& stats) {
  Simulation simulation(job.inputs.params(), job.inputs.state(), options);
  Progress progress("simulate", static_cast<long>(times.size()), "samples", job.quiet);
  const bool forces = job.settings.elements.has(Element::pin_force);
  Motion motion = timed(stats.simulate_seconds, [&] {
    return sample_motion(simulation, times, forces, [&](long done) { progress.update(done); });
  });
  progress.finish();
  stats.force_evaluations += simulation.stats().force_evaluations;
  stats.samples += static_cast<std::int64_t>(times.size());
  return motion;
}

void add_drawing(RenderStats& stats, const ClipRenderer& renderer) {
  const RenderStats& drawn = renderer.stats();
  stats.frames_drawn += drawn.frames_drawn;
  stats.static_layer_draws += drawn.static_layer_draws;
  stats.trail_points_drawn += drawn.trail_points_drawn;
  stats.draw_seconds += drawn.draw_seconds;
}

/// The clip: frames drawn on this thread while the encoder (and PNG compression) run on
/// others, through a few reused buffers.
void render_clip(const RenderJob& job, RenderStats& stats) {
  const RenderSettings& s = job.settings;
  const long count = s.frame_count();
  std::vector<double> times(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) times[static_cast<std::size_t>(k)] = s.frame_time(k);
  const Motion motion = simulate(job, job.simulation, times, stats);
  ClipRenderer renderer(job.inputs.params(), motion, s, job.theme, job.run);

  std::optional<VideoWriter> video;
  std::optional<PngSequenceWriter> pngs;
  if (job.out && job.out_kind == OutputKind::mp4) {
    video.emplace(*job.out, video_options(s));
    stats.encoder_opened = true;
  }
  if (job.frames) pngs.emplace(*job.frames, s.width, s.height, "--frames", PngOptions{}, 2, count);
  FramePipeline pipeline(s.width, s.height, [&](const Frame& frame) {
    if (video) video->write(frame);
    if (pngs) pngs->write(frame);
  });
  Progress progress("render", count, "frames", job.quiet);
  for (long k = 0; k < count; ++k) {
    throw_if_interrupted();
    Frame& frame = pipeline.acquire();
    renderer.draw(static_cast<std::size_t>(k), frame);
    pipeline.submit();
    progress.update(k + 1);
  }
  pipeline.finish();
  if (pngs) {
    pngs->finish();
    const PngStats png = pngs->stats();
    stats.png_files_written += png.frames;
    stats.png_seconds += png.convert_seconds + png.encode_seconds;
  }
  if (video) {
    video->finish();
    stats.convert_seconds += video->stats().convert_seconds;
    stats.encode_seconds += video->stats().encode_seconds + video->stats().finish_seconds;
    if (!video->note().empty() && !job.quiet) std::fprintf(stderr, "linkage: note: %s\n", video->note().c_str());
  }
  progress.finish();
  add_drawing(stats, renderer);
}

/// One frame at --at: the trail needs the motion over the seconds before it, sampled as
/// densely as the clip would be; nothing else is sampled.
void render_still(const RenderJob& job, RenderStats& stats) {
  const RenderSettings& s = job.settings;
  std::vector<double> times;
  if (s.elements.has(Element::trail)) {
    const double step = s.speed / s.fps;
    const auto back = static_cast<long>(std::floor(std::min(s.at, SceneOptions{}.trail_seconds) / step));
    for (long j = back; j > 0; --j) times.push_back(s.at - static_cast<double>(j) * step);
  }
  times.push_back(s.at);
  SimulationOptions options = job.simulation;
  options.duration = std::max(s.at, options.dt);
  options.validate();
  const Motion motion = simulate(job, options, times, stats);
  ClipRenderer renderer(job.inputs.params(), motion, s, job.theme, job.run);
  const std::size_t last = times.size() - 1;
  if (job.out_kind == OutputKind::png) {
    Frame frame(s.width, s.height);
    renderer.draw(last, frame);
    write_png(frame, *job.out, "--out");
    ++stats.png_files_written;
  } else {
    write_vector_still(renderer, last, job.out_kind, s.width, s.height, *job.out, "--out");
  }
  add_drawing(stats, renderer);
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
       {{"simulate", s.simulate_seconds}, {"draw", s.draw_seconds}, {"convert", s.convert_seconds},
        {"encode", s.encode_seconds}, {"png", s.png_seconds}}},
  };
  std::printf("%s\n", json.dump(2).c_str());
}

void run_render(const RenderFlags& flags) {
  const RenderJob job = resolve_job(flags);
  RenderStats stats;
  if (job.frames || (job.out && job.out_kind == OutputKind::mp4)) render_clip(job, stats);
  if (job.out && is_still(job.out_kind)) render_still(job, stats);
  if (flags.stats) print_stats(stats);
}

}  // namespace

void register_render(CLI::App& app) {
  auto f = std::make_shared<RenderFlags>();
  CLI::App* sub = app.add_subcommand("render", "Draw the motion: an MP4 clip, a PNG sequence, or a PNG/SVG/PDF still");
  const std::string output = "Output";
  f->out_option = sub->add_option("--out", f->out,
                                  "Output file: .mp4 (H.264 video), .png (still), .svg or .pdf (vector still); "
                                  "written atomically (default linkage.mp4, or none with --frames alone)")
                      ->type_name("FILE")
                      ->group(output);
  sub->add_option("--frames", f->frames, "Also (or instead) write the clip as DIR/frame_00000.png ... (DIR must exist)")
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
  f->duration_option = sub->add_option("--duration", f->duration,
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
  sub->add_option("--show", f->show, "Elements to show (comma-separated): " + element_name_list())
      ->type_name("LIST")
      ->group(look);
  sub->add_option("--hide", f->hide, "Elements to hide; default shows all but velocity and axes")
      ->type_name("LIST")
      ->group(look);
  f->camera_option = sub->add_option("--camera", f->camera,
                                     "follow (keeps the falling centre of mass in view; default), fixed (--view), "
                                     "or fit (the whole motion)")
                         ->type_name("MODE")
                         ->group(look);
  sub->add_option("--view", f->view, "World rectangle xmin,ymin,xmax,ymax in metres for the fixed camera")
      ->type_name("X0,Y0,X1,Y1")
      ->group(look);
  sub->add_option("--theme", f->theme, "Colours: " + theme_name_list() + " (default light; palettes in assets/themes)")
      ->type_name("NAME")
      ->group(look);
  f->title_option = sub->add_option("--title", f->title, "Title line (default \"" + RenderSettings{}.title + "\"; \"\" for none)")
                        ->type_name("TEXT")
                        ->group(look);
  add_simulation_flags(sub, f->simulation);
  add_input_options(sub, f->inputs);
  add_runner(sub, [f] { run_render(*f); });
}

}  // namespace linkage::cli
