#include "pipeline/clip.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "encode/png_writer.hpp"
#include "pipeline/encode_frames.hpp"
#include "pipeline/panel_data.hpp"
#include "render/frame_layout.hpp"
#include "render/vector_still.hpp"
#include "scene/motion.hpp"

namespace linkage {
namespace fs = std::filesystem;

namespace {

template <typename Work>
auto timed(double& seconds, Work work) {
  const auto start = std::chrono::steady_clock::now();
  auto result = work();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// Samples the motion at `times` with its own simulation of `options`; warns when the
/// run's numbers are meaningless.
Motion simulate(const Clip& clip, const SimulationOptions& options, const std::vector<double>& times,
                const ClipProgress& progress, ClipResult& result, PanelData& panel) {
  RenderStats& stats = result.stats;
  Simulation simulation(clip.inputs.params(), clip.inputs.state(), options);
  const bool forces = clip.settings.elements.has(Element::pin_force);
  const long total = static_cast<long>(times.size());
  Motion motion = timed(stats.simulate_seconds, [&] {
    return sample_motion(simulation, times, forces, [&](long done) {
      if (progress) progress(ClipStage::simulate, done, total);
    });
  });
  if (!clip.settings.panel.empty())
    panel = timed(stats.simulate_seconds, [&] {
      return homework_panel(clip.settings.panel, simulation, motion, clip.inputs.params(),
                            body_state(clip.inputs.params(), clip.inputs.state()), times.back());
    });
  stats.force_evaluations += simulation.stats().force_evaluations;
  stats.samples += static_cast<std::int64_t>(times.size());
  const std::string warning = result_warning(options, clip.inputs.params(), simulation.stats());
  if (!warning.empty() && std::find(result.warnings.begin(), result.warnings.end(), warning) == result.warnings.end())
    result.warnings.push_back(warning);
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
void produce_motion(const Clip& clip, const ClipProgress& progress, ClipResult& result) {
  const RenderSettings& s = clip.settings;
  const long count = s.frame_count();
  std::vector<double> times(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) times[static_cast<std::size_t>(k)] = s.frame_time(k);
  RenderStats& stats = result.stats;
  PanelData panel;
  const Motion motion = simulate(clip, clip.simulation, times, progress, result, panel);
  panel.t_end = s.duration;
  FrameLayout layout(s, clip.theme, std::move(panel));
  ClipRenderer renderer(clip.inputs.params(), motion, layout.scene_settings(), clip.theme, run_label(clip.simulation));

  encode_frames(
      clip.out && is_video(clip.out_kind()) ? clip.out : std::nullopt, clip.frames, s, count,
      [&](std::size_t k, Frame& frame) {
        layout.draw(k, times[k], frame, [&](Frame& scene) { renderer.draw(k, scene); });
      },
      progress, result);
  add_drawing(stats, renderer);
}

/// One frame at `at`: the trail needs the motion over the seconds before it (a panel
/// all of it), sampled as densely as the clip would be; nothing else is sampled.
void produce_still(const Clip& clip, const ClipProgress& progress, ClipResult& result) {
  const RenderSettings& s = clip.settings;
  const bool look_back = s.elements.has(Element::trail) || !s.panel.empty();
  const std::vector<double> times =
      s.still_times(look_back ? (s.panel.empty() ? std::min(s.at, SceneOptions{}.trail_seconds) : s.at) : 0.0);
  SimulationOptions options = clip.simulation;
  options.duration = std::max(s.at, options.dt);
  options.validate();
  PanelData panel;
  const Motion motion = simulate(clip, options, times, progress, result, panel);
  FrameLayout layout(s, clip.theme, std::move(panel));
  ClipRenderer renderer(clip.inputs.params(), motion, layout.scene_settings(), clip.theme, run_label(clip.simulation));
  const std::size_t last = times.size() - 1;
  if (clip.out_kind() == OutputKind::png) {
    Frame frame(s.width, s.height);
    layout.draw(last, s.at, frame, [&](Frame& scene) { renderer.draw(last, scene); });
    write_png(frame, *clip.out, "out");
    ++result.stats.png_files_written;
  } else {
    write_vector_still(
        [&](cairo_t* cr) {
          layout.draw_vector(last, s.at, cr, [&](cairo_t* scene) { renderer.draw_vector(last, scene); });
        },
        clip.out_kind(), s.width, s.height, *clip.out, "out");
  }
  add_drawing(result.stats, renderer);
}

}  // namespace

OutputKind Clip::out_kind() const { return out ? output_kind(*out, "out") : OutputKind::mp4; }

bool Clip::is_still() const { return out && linkage::is_still(out_kind()); }

void Clip::validate() const {
  if (!out && !frames) throw Error::invalid("out", "a clip needs an output file or a frames folder");
  std::error_code ec;
  if (out && fs::is_directory(*out, ec))
    throw Error::invalid("out", "'" + out->string() + "' is a folder, expected a file name");
  settings.validate();
  if (!settings.panel.empty()) validate_homework_panel(settings.panel);
  inputs.validate();
  simulation.validate();
  if (out) {
    if (is_video(out_kind())) VideoWriter::validate(clip_video_options(settings, out_kind()));
    if (*out != "-") require_writable_directory(out->parent_path(), "out");
  }
  if (frames && fs::exists(*frames, ec) && !fs::is_directory(*frames, ec))
    throw Error::invalid("frames", "'" + frames->string() + "' exists and is not a folder");
}

VideoOptions clip_video_options(const RenderSettings& s, OutputKind kind) {
  VideoOptions v;
  v.format = kind == OutputKind::gif    ? VideoFormat::gif
             : kind == OutputKind::webm ? VideoFormat::webm
                                        : VideoFormat::mp4;
  v.width = s.width;
  v.height = s.height;
  v.fps = s.fps;
  v.setting = "out";
  return v;
}

std::string run_label(const SimulationOptions& s) {
  std::string text = "Case " + std::to_string(s.case_id) + " \u00b7 " + std::string(info(s.integrator).name);
  if (s.case_id == 1)  // only Case 1 can drift off the pin, so only there does stabilization matter
    text += s.stabilization == Stabilization::none ? std::string(" \u00b7 no stabilization")
                                                   : " \u00b7 " + std::string(name(s.stabilization));
  return text;
}

std::string_view name(ClipStage stage) { return stage == ClipStage::simulate ? "simulate" : "render"; }

ClipResult produce_clip(const Clip& clip, const ClipProgress& progress) {
  clip.validate();
  ClipResult result;
  if (clip.frames || (clip.out && is_video(clip.out_kind()))) produce_motion(clip, progress, result);
  if (clip.is_still()) produce_still(clip, progress, result);
  return result;
}

}  // namespace linkage
