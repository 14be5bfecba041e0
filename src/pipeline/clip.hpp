#pragma once
// The one render pipeline: simulate, build the scene, draw, encode. A clip is a value
// (the inputs, the simulation settings, the scene settings, the outputs); producing it is
// one call. `linkage render`, a lesson's render steps and `linkage bench render` all call
// produce_clip(), so the benchmark times exactly what users run.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "encode/video_writer.hpp"
#include "integrate/simulation.hpp"
#include "model/inputs.hpp"
#include "render/clip_renderer.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"

namespace linkage {

struct Clip {
  Inputs inputs;  // parameters and initial state
  SimulationOptions simulation;
  RenderSettings settings;
  Theme theme;
  /// The video (.mp4, .gif, .webm) or the still (.png, .svg, .pdf), if any.
  std::optional<std::filesystem::path> out;
  /// A numbered PNG sequence's folder (made with its parents), if any.
  std::optional<std::filesystem::path> frames;

  /// The kind of `out` (from its extension).
  [[nodiscard]] OutputKind out_kind() const;
  [[nodiscard]] bool is_still() const;
  /// Checks that the parts fit together, before any work. Errors are typed, about the
  /// setting at fault ("out", "frames", "at", "size", ...), for the caller to phrase.
  void validate() const;
};

/// The encoder settings of a clip's video of `kind` (.mp4, .gif or .webm).
[[nodiscard]] VideoOptions clip_video_options(const RenderSettings& settings, OutputKind kind = OutputKind::mp4);

/// The HUD's second line, e.g. "Case 3 · dop853".
[[nodiscard]] std::string run_label(const SimulationOptions& options);

enum class ClipStage { simulate, draw };
[[nodiscard]] std::string_view name(ClipStage stage);

/// Called as work advances: `done` of `total` units of `stage` (samples, frames).
using ClipProgress = std::function<void(ClipStage stage, long done, long total)>;

struct ClipResult {
  RenderStats stats;
  double draw_waited_seconds = 0;     // the drawing thread waited for a free buffer
  double encoder_idle_seconds = 0;    // the encoder thread waited for a drawn frame
  std::int64_t video_bytes = 0;       // size of the MP4
  std::string encoder;                // e.g. "libx264"
  std::vector<std::string> notes;     // for the user (e.g. the encoder chosen instead)
  std::vector<std::string> warnings;  // the simulation's numbers are meaningless (result_warning)
};

/// Produces every output of `clip` (validated first). Polls for terminating signals;
/// outputs appear whole or not at all.
ClipResult produce_clip(const Clip& clip, const ClipProgress& progress = {});

}  // namespace linkage
