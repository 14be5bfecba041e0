#pragma once
// What every clip shares, whichever mechanism it draws: the encoder settings of its video,
// the HUD's run line, the progress callback and the result of producing it.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "encode/video_writer.hpp"
#include "integrate/simulation_options.hpp"
#include "render/render_stats.hpp"
#include "render/settings.hpp"

namespace linkage {

/// The largest ensemble spread, rad or m: far past any spread that shows chaos, and
/// far below where the states would leave double precision (1e308 overflowed).
inline constexpr double kMaxSpread = 1e3;

/// The encoder settings of a clip's video of `kind` (.mp4, .gif or .webm).
[[nodiscard]] VideoOptions clip_video_options(const RenderSettings& settings, OutputKind kind = OutputKind::mp4);

/// The HUD's second line, e.g. "Case 3 · dop853", or "Case 3 · kinematic analysis" when the
/// drivers fixed the motion (nothing integrated).
[[nodiscard]] std::string run_label(const SimulationOptions& options, bool kinematic = false);

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
  std::string evaluator;              // what computed the equations (MechanismStats::evaluator)
  std::vector<std::string> notes;     // for the user (e.g. the encoder chosen instead)
  std::vector<std::string> warnings;  // the simulation's numbers are meaningless (result_warning)
};

}  // namespace linkage
