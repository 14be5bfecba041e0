#pragma once
// The one render pipeline: simulate, build the scene, draw, encode. A clip is a value
// (the inputs, the simulation settings, the scene settings, the outputs); producing it is
// one call. `linkage render`, a lesson's render steps and `linkage bench render` all call
// produce_clip(), so the benchmark times exactly what users run.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "encode/video_writer.hpp"
#include "integrate/simulation.hpp"
#include "model/inputs.hpp"
#include "pipeline/clip_result.hpp"
#include "pipeline/trajectory_csv.hpp"
#include "render/clip_renderer.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"

namespace linkage {

/// A second run of the homework drawn over the main one (--compare): its own inputs and
/// simulation settings, or a trajectory file's poses.
struct HomeworkRun {
  Inputs inputs;
  SimulationOptions simulation;
  std::string label;                               // the legend's note: "integrator=rk4", "run.csv"
  std::shared_ptr<const TrajectoryTable> table{};  // drawn instead of simulating
};

/// The columns a homework trajectory file needs (x2, y2 are used when present).
[[nodiscard]] const std::vector<std::string>& homework_pose_columns();

/// A trajectory file of the homework's run, covering 0 .. `end` s: the homework's columns
/// (homework_pose_columns), or the two-blocks mechanism's (1.x, 1.y, 1.theta, 2.theta;
/// 2.x, 2.y when present), renamed to the homework's. Error::input as
/// read_trajectory_csv, naming `origin`.
[[nodiscard]] TrajectoryTable read_homework_trajectory(const std::filesystem::path& file, const std::string& origin,
                                                       double end);

/// The compared run of NAME=VALUE items: integrator=NAME, case=N, or an input's name
/// (theta1=0.1000001, L=0.4) over `inputs` and `simulation`. Error::input naming `origin`,
/// the item and what is valid.
[[nodiscard]] HomeworkRun homework_compared_run(const std::vector<std::string>& items, const Inputs& inputs,
                                                const SimulationOptions& simulation, const std::string& origin);

/// The ensemble's other initial states: theta1 moved by spread k / (n - 1), k = 1 .. n - 1.
[[nodiscard]] std::vector<State> homework_ensemble_states(const State& state, int n, double spread);

struct Clip {
  Inputs inputs;  // parameters and initial state
  SimulationOptions simulation;
  RenderSettings settings;
  Theme theme;
  /// The video (.mp4, .gif, .webm) or the still (.png, .svg, .pdf), if any.
  std::optional<std::filesystem::path> out;
  /// A numbered PNG sequence's folder (made with its parents), if any.
  std::optional<std::filesystem::path> frames;
  /// Other runs drawn as outlines over the main one: 0 or 2 .. 200 runs (the main one
  /// among them) with theta1 up to `spread` apart, and a compared run.
  int ensemble = 0;
  double spread = 1e-6;
  std::optional<HomeworkRun> compare;

  /// The kind of `out` (from its extension).
  [[nodiscard]] OutputKind out_kind() const;
  [[nodiscard]] bool is_still() const;
  /// Checks that the parts fit together, before any work. Errors are typed, about the
  /// setting at fault ("out", "frames", "at", "size", ...), for the caller to phrase.
  void validate() const;
};

/// The other runs' block states at `times` (the ensemble's, then the compared run's),
/// as the renderer draws them; the compared run's warnings go to `result`.
[[nodiscard]] std::vector<OverlayRun> homework_overlays(const Clip& clip, const SimulationOptions& options,
                                                        const std::vector<double>& times, ClipResult& result);

/// Produces every output of `clip` (validated first). Polls for terminating signals;
/// outputs appear whole or not at all.
ClipResult produce_clip(const Clip& clip, const ClipProgress& progress = {});

}  // namespace linkage
