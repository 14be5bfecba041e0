#include "pipeline/clip.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <string_view>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "model/kinematics.hpp"
#include "pipeline/encode_frames.hpp"
#include "pipeline/panel_data.hpp"
#include "render/frame_layout.hpp"
#include "scene/motion.hpp"

namespace linkage {
namespace fs = std::filesystem;

namespace {

// Pieces joined (report's concat is not among this module's dependencies).
[[maybe_unused]] std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (const std::string_view piece : pieces) out.append(piece);
  return out;
}

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

// A trajectory file's block states at `times`: x2, y2 from the pin unless the file has them.
std::vector<BodyState> table_states(const TrajectoryTable& table, const Params& p, const std::vector<double>& times) {
  const auto column = [&](const char* name) { return table.find(name); };
  const auto x1 = column("x1"), y1 = column("y1"), theta1 = column("theta1"), theta2 = column("theta2");
  const auto x2 = column("x2"), y2 = column("y2");
  std::vector<BodyState> states;
  for (const double t : times) {
    State s;
    s.x1 = table.at(*x1, t);
    s.y1 = table.at(*y1, t);
    s.theta1 = table.at(*theta1, t);
    s.theta2 = table.at(*theta2, t);
    s.x1_dot = s.y1_dot = s.theta1_dot = s.theta2_dot = 0;
    BodyState b = body_state(p, s);
    if (x2 && y2) {
      b.x2 = table.at(*x2, t);
      b.y2 = table.at(*y2, t);
    }
    states.push_back(b);
  }
  return states;
}

std::vector<BodyState> simulated_states(const Params& p, const State& initial, const SimulationOptions& options,
                                        const std::vector<double>& times, ClipResult& result,
                                        const std::string& warning_prefix) {
  Simulation simulation(p, initial, options);
  const Motion motion = timed(result.stats.simulate_seconds, [&] { return sample_motion(simulation, times, false); });
  result.stats.samples += static_cast<std::int64_t>(times.size());
  if (!warning_prefix.empty()) {
    const std::string warning = result_warning(options, p, simulation.stats());
    if (!warning.empty()) result.warnings.push_back(warning_prefix + warning);
  }
  std::vector<BodyState> states;
  for (const MotionSample& sample : motion.samples) states.push_back(sample.state);
  return states;
}

// The legend's words for the other runs.
ClipOverlays overlay_words(const Clip& clip, std::vector<OverlayRun> runs) {
  ClipOverlays overlays;
  overlays.runs = std::move(runs);
  if (clip.ensemble >= 2) {
    overlays.ensemble_name = concat({"ensemble: ", std::to_string(clip.ensemble), " runs"});
    overlays.ensemble_note = concat({"\u03b8\u2081 + 0 .. ", format_significant(clip.spread, 3), " rad"});
  }
  if (clip.compare) overlays.compare_note = clip.compare->label;
  return overlays;
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
  ClipRenderer renderer(clip.inputs.params(), motion, layout.scene_settings(), clip.theme, run_label(clip.simulation),
                        overlay_words(clip, homework_overlays(clip, clip.simulation, times, result)));

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
  ClipRenderer renderer(clip.inputs.params(), motion, layout.scene_settings(), clip.theme, run_label(clip.simulation),
                        overlay_words(clip, homework_overlays(clip, options, times, result)));
  const std::size_t last = times.size() - 1;
  write_still(
      layout, last, s.at, s, *clip.out, [&](Frame& scene) { renderer.draw(last, scene); },
      [&](cairo_t* scene) { renderer.draw_vector(last, scene); }, result);
  add_drawing(result.stats, renderer);
}

}  // namespace

const std::vector<std::string>& homework_pose_columns() {
  static const std::vector<std::string> names{"t", "x1", "y1", "theta1", "theta2"};
  return names;
}

TrajectoryTable read_homework_trajectory(const std::filesystem::path& file, const std::string& origin, double end) {
  const std::string purpose = concat({origin, ", to draw the homework's two blocks,"});
  // Which columns it has decides which the rows are checked against.
  std::ifstream in(file, std::ios::binary);
  std::string header;
  while (in && header.find_first_not_of(" \t\r") == std::string::npos && std::getline(in, header)) {
  }
  const std::vector<std::string> mechanism{"t", "1.x", "1.y", "1.theta", "2.theta"};
  const bool as_mechanism = header.find("1.theta") != std::string::npos && header.find("theta1") == std::string::npos;
  TrajectoryTable table = read_trajectory_csv(
      file, as_mechanism ? mechanism : homework_pose_columns(),
      as_mechanism ? concat({origin, ", to draw the homework's two blocks from two-blocks' columns,"}) : purpose, 0.0,
      end);
  for (std::string& name : table.names)
    for (const InputKey& key : kInputKeys)
      if (!key.mechanism_key.empty() && name == key.mechanism_key && key.state != nullptr) name = key.key;
  for (std::string& name : table.names) {  // block 2's centre, not an input
    if (name == "2.x") name = "x2";
    if (name == "2.y") name = "y2";
  }
  return table;
}

HomeworkRun homework_compared_run(const std::vector<std::string>& items, const Inputs& inputs,
                                  const SimulationOptions& simulation, const std::string& origin) {
  HomeworkRun run{inputs, simulation, "", nullptr};
  for (const std::string& item : items) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
      throw Error::input(
          concat({origin, ": '", item, "' is not NAME=VALUE; e.g. theta1=0.1000001, L=0.4, integrator=rk4 or case=1"}));
    std::string name = item.substr(0, equals);
    const std::string value = item.substr(equals + 1);
    std::replace(name.begin(), name.end(), '-', '_');  // theta1-dot as the flag spells it
    if (name == "integrator") {
      run.simulation.integrator = parse_integrator(value, origin + " integrator");
    } else if (name == "case") {
      if (value != "1" && value != "2" && value != "3")
        throw Error::input(concat({origin, ": case '", value, "' is not a case; valid: 1, 2, 3"}));
      run.simulation.case_id = value[0] - '0';
    } else if (const InputKey* key = find_input_key(name)) {
      double number = 0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
      if (error != std::errc{} || end != value.data() + value.size() || !std::isfinite(number))
        throw Error::input(concat({origin, ": ", name, " = '", value, "' is not a number"}));
      run.inputs.set(*key, number, origin + " " + name);
    } else {
      const auto near = closest_input_key(name);
      throw Error::input(concat({origin, ": '", name, "' is not an input",
                                 near ? concat({" (did you mean '", *near, "'?)"}) : std::string(),
                                 "; valid: ", input_key_list(), ", integrator, case"}));
    }
    if (!run.label.empty()) run.label += ", ";
    run.label += item;
  }
  run.inputs.validate();
  run.simulation.validate();
  return run;
}

std::vector<State> homework_ensemble_states(const State& state, int n, double spread) {
  std::vector<State> states;
  for (int k = 1; k < n; ++k) {
    State s = state;
    s.theta1 = state.theta1 + spread * static_cast<double>(k) / static_cast<double>(n - 1);
    states.push_back(s);
  }
  return states;
}

std::vector<OverlayRun> homework_overlays(const Clip& clip, const SimulationOptions& options,
                                          const std::vector<double>& times, ClipResult& result) {
  std::vector<OverlayRun> runs;
  const Params& p = clip.inputs.params();
  if (clip.ensemble >= 2) {
    const std::vector<State> states = homework_ensemble_states(clip.inputs.state(), clip.ensemble, clip.spread);
    for (std::size_t i = 0; i < states.size(); ++i) {
      throw_if_interrupted();
      const double ramp = states.size() <= 1 ? 1.0 : static_cast<double>(i) / static_cast<double>(states.size() - 1);
      // The main run's warnings stand for the ensemble's.
      runs.push_back({p, simulated_states(p, states[i], options, times, result, ""), ramp, false});
    }
  }
  if (clip.compare) {
    const Params& q = clip.compare->inputs.params();
    if (clip.compare->table) {
      runs.push_back({q, table_states(*clip.compare->table, q, times), 0.0, true});
    } else {
      SimulationOptions compared = clip.compare->simulation;
      compared.duration = options.duration;
      runs.push_back(
          {q, simulated_states(q, clip.compare->inputs.state(), compared, times, result, "compared run: "), 0.0, true});
    }
  }
  return runs;
}

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
  if (ensemble != 0 && (ensemble < 2 || ensemble > 200))
    throw Error::invalid("ensemble", std::to_string(ensemble) + " runs; expected 2 .. 200");
  if (!(spread > 0 && spread <= kMaxSpread))
    throw Error::invalid("spread", "expected a number in (0, " + format_significant(kMaxSpread, 6) + "] (rad)");
  // Apart at the pin, each block with its loads: other runs' blocks over them would hide
  // the very forces the view is for.
  if (settings.free_body && (ensemble != 0 || compare))
    throw Error::invalid("view",
                         "the free-body view draws the blocks pulled apart with their loads; other runs' "
                         "blocks over it would hide them: overlay with the follow, fit or fixed camera");
  if (compare) {
    compare->inputs.validate();
    if (!compare->table) compare->simulation.validate();
  }
}

ClipResult produce_clip(const Clip& clip, const ClipProgress& progress) {
  clip.validate();
  ClipResult result;
  if (clip.frames || (clip.out && is_video(clip.out_kind()))) produce_motion(clip, progress, result);
  if (clip.is_still()) produce_still(clip, progress, result);
  return result;
}

}  // namespace linkage
