#pragma once
// `linkage bench render`: rendering throughput, measured the way `linkage render` works,
// on the homework's default clip (what `linkage render --out clip.mp4` draws without
// --mechanism: two-blocks.toml as shipped) and the four-bar's (`--mechanism four-bar`),
// both through the one path (pipeline/mechanism_clip).
//
//   MP4, per clip and size (854x480, 1280x720, 1920x1080; 10 s of motion at 30 fps):
//     pipeline      produce_mechanism_clip(), the very call `linkage render --out
//                   clip.mp4` makes: simulate, draw on this thread while the encoder
//                   thread converts (libswscale) and encodes (libavcodec) through
//                   FramePipeline; timed wall to wall, with the time of each stage;
//     encode alone  the same frames, drawn beforehand (MechanismClipFrames, the pipeline's
//                   own drawing) and kept in memory (FrameStore), fed through the same
//                   FramePipeline to the same encoder settings: the encoder's own speed.
//                   The two MP4s must be byte-identical, which proves the frames are the same.
//     Target: pipeline / encode alone <= 1.2 at 1280x720, for each clip.
//   PNG sequence, per clip and size, on evenly spaced frames of the same clip: our
//     PngSequenceWriter (libspng, zlib level 1, two workers) against Cairo's
//     cairo_surface_write_to_png, both writing 8-bit RGB. Target: ours >= 3x Cairo's
//     frames per second at 1280x720.
// The two modes of each comparison run alternately, `repeats` times; the fastest run of
// each counts (another process can only slow a run down).
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/mechanism_clip.hpp"

namespace linkage::bench {

/// The clips measured: the homework's (`linkage render` without --mechanism) and the four-bar's.
inline constexpr std::array<const char*, 2> kRenderClips{"two-blocks", "four-bar"};

/// A shipped mechanism's clip as `linkage render --mechanism NAME --out clip.mp4 --size
/// WxH --fps N --duration S` makes it (the file's title and trails, the default elements
/// and camera, the light theme; Case 3, DOP853), with no output set. `assets` as for
/// load_theme (empty: the palettes built into the binary).
struct BenchClip {
  std::string name;
  std::shared_ptr<const sym::System> system;
  GiNaC::exmap initial;  // loops closed
  MechanismClip clip;
};
[[nodiscard]] BenchClip default_clip(const std::string& mechanism, int width, int height, int fps, double duration,
                                     const std::filesystem::path& assets = {});

struct RenderBenchOptions {
  std::filesystem::path out{"bench-render"};
  std::filesystem::path assets;  // theme folder (empty: built-in palettes)
  bool quick = false;            // two small sizes, 2 s, one repeat: checks the report (CI)
  bool quiet = false;
};

/// One clip and size of MP4: the pipeline's fastest run and encoding alone's fastest run.
struct MovieRow {
  std::string clip;  // the mechanism: "two-blocks", "four-bar"
  int width = 0, height = 0, fps = 0;
  long frames = 0;
  double wall_seconds = 0;      // the whole pipeline, simulation to finished file
  double simulate_seconds = 0;  // stages of that run; drawing runs alongside the
  double draw_seconds = 0;      // encoder thread, so they add up to more than the wall
  double convert_seconds = 0;
  double encode_seconds = 0;        // libavcodec + muxing + finishing the file
  double draw_waited_seconds = 0;   // the drawing thread waited for a free buffer
  double encoder_idle_seconds = 0;  // the encoder thread waited for a drawn frame
  double cpu_seconds = 0;           // process CPU time of the pipeline run, all threads
  double alone_wall_seconds = 0;    // encoding the stored frames alone
  double alone_cpu_seconds = 0;     // process CPU time of that run
  double alone_unpack_seconds = 0;  // of which unpacking the stored frames
  std::size_t stored_bytes = 0;     // the run-length coded frames kept for encoding alone
  std::int64_t bytes = 0;           // size of the MP4
  bool same_output = false;         // both runs wrote byte-identical files
  std::string encoder;              // e.g. "libx264"
  [[nodiscard]] double fps_achieved() const { return static_cast<double>(frames) / wall_seconds; }
  [[nodiscard]] double alone_fps() const { return static_cast<double>(frames) / alone_wall_seconds; }
  [[nodiscard]] double ratio() const { return wall_seconds / alone_wall_seconds; }
  /// The work drawing adds: on a busy machine the wall ratio is noisy, this much less.
  [[nodiscard]] double cpu_ratio() const { return cpu_seconds / alone_cpu_seconds; }
};

/// One clip and size of PNG sequence: ours against Cairo's writer on the same frames.
struct PngRow {
  std::string clip;
  int width = 0, height = 0;
  long frames = 0;
  double ours_seconds = 0;           // wall, including unpacking the stored frames
  double ours_convert_seconds = 0;   // BGRA -> RGB rows on the calling thread
  double ours_compress_seconds = 0;  // summed over the workers
  double cairo_seconds = 0;          // wall, including unpacking the stored frames
  double unpack_seconds = 0;         // unpacking, per run (the same in both)
  std::int64_t ours_bytes = 0, cairo_bytes = 0;
  [[nodiscard]] double ours_fps() const { return static_cast<double>(frames) / ours_seconds; }
  [[nodiscard]] double cairo_fps() const { return static_cast<double>(frames) / cairo_seconds; }
  [[nodiscard]] double ratio() const { return ours_fps() / cairo_fps(); }
};

struct RenderBenchResult {
  std::vector<MovieRow> movies;
  std::vector<PngRow> pngs;
  int repeats = 1;
  unsigned cores = 1;
  double load_average = 0;      // 1-minute, at the start
  double load_average_end = 0;  // and at the end
  /// Other processes wanted more than every core: wall times then measure them too.
  [[nodiscard]] bool busy() const { return std::max(load_average, load_average_end) > static_cast<double>(cores); }
  std::vector<std::filesystem::path> files;
};

/// The size the targets are judged at.
inline constexpr int kTargetWidth = 1280, kTargetHeight = 720;
inline constexpr double kMaxPipelineRatio = 1.2, kMinPngRatio = 3.0;

/// Runs every measurement and writes render.csv and render.md into options.out.
[[nodiscard]] RenderBenchResult run_render_bench(const RenderBenchOptions& options);
/// Writes render.csv and render.md into options.out (atomically) and lists them in result.files.
void write_render_report(const RenderBenchOptions& options, RenderBenchResult& result);

/// The MP4 target's measure: the wall-time ratio, or on a busy machine the CPU ratio.
/// With the encoder never waiting for a drawing, drawing can slow the pipeline only by
/// the CPU it takes from the encoder, so on an idle machine the wall ratio stays within
/// about the CPU ratio; a busy machine's wall times mostly measure the other processes.
[[nodiscard]] double judged_ratio(const MovieRow& row, const RenderBenchResult& result);

/// The clip's row measured at 1280x720, if any (--quick has none).
[[nodiscard]] const MovieRow* target_movie(const RenderBenchResult& result, const std::string& clip);
[[nodiscard]] const PngRow* target_png(const RenderBenchResult& result, const std::string& clip);

/// One-line findings for the terminal.
[[nodiscard]] std::vector<std::string> render_bench_lines(const RenderBenchResult& result);

}  // namespace linkage::bench
