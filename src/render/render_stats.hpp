#pragma once
// A render's counters and timings, filled by whoever draws, simulates and encodes.
#include <cstdint>

namespace linkage {

/// Counters and timings of a render, per stage. The painter fills the drawing fields;
/// whoever runs the simulation and the encoder fills the others.
struct RenderStats {
  std::int64_t frames_drawn = 0;
  std::int64_t static_layer_draws = 0;  // background+grid+axes, title, legend, scale bar: once each per run
  std::int64_t trail_points_drawn = 0;  // 0 when the trail is hidden
  std::int64_t force_evaluations = 0;   // pin-force solves (Simulation::stats)
  std::int64_t samples = 0;             // states taken from the simulation
  bool encoder_opened = false;          // an MP4 encoder was opened
  std::int64_t png_files_written = 0;
  double simulate_seconds = 0;  // sampling the motion (integration, pin forces)
  double draw_seconds = 0;      // Cairo drawing into frames
  double convert_seconds = 0;   // colour conversion for the encoder (libswscale)
  double encode_seconds = 0;    // video encoding and muxing
  double png_seconds = 0;       // PNG compression and writing
};

}  // namespace linkage
