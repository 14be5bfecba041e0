#include "bench/render_bench.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <thread>

#include "bench/accuracy_report.hpp"
#include "bench/frame_store.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "encode/frame_pipeline.hpp"
#include "encode/png_writer.hpp"
#include "encode/video_writer.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip_request.hpp"
#include "render/cairo_util.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"

namespace linkage::bench {
namespace fs = std::filesystem;
namespace {
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// CPU time of the whole process (every thread: drawing, the encoder's, x264's), s.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Size {
  int width, height;
};

/// A hidden folder inside the output folder for the MP4s and PNGs being timed; removed
/// with everything in it when the run ends, however it ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(const fs::path& parent) {
    static std::atomic<unsigned> counter{0};
    path_ = parent / (".bench-render.tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::error_code ec;
    if (!fs::create_directory(path_, ec))
      throw Error::failure("--out: cannot create '" + path_.string() + "': " + (ec ? ec.message() : "exists"));
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string size_name(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

bool same_bytes(const fs::path& a, const fs::path& b) {
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  if (!fa || !fb) return false;
  return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(fb), std::istreambuf_iterator<char>());
}

std::int64_t folder_bytes(const fs::path& folder) {
  std::int64_t total = 0;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file()) total += static_cast<std::int64_t>(entry.file_size());
  return total;
}

/// Counts frames for the progress line across every pass.
struct Tally {
  Progress& progress;
  long done = 0;
  void frame() {
    throw_if_interrupted();
    progress.update(++done);
  }
};

/// One run of the render pipeline into `target`, timed wall to wall.
MovieRow run_pipeline(const BenchClip& bench, const fs::path& target, Tally& tally) {
  MechanismClip clip = bench.clip;
  clip.out = target;
  MovieRow row;
  const double cpu_start = process_cpu_seconds();
  const auto start = Clock::now();
  const ClipResult result =
      produce_mechanism_clip(*bench.system, bench.initial, clip, [&](ClipStage stage, long /*done*/, long /*total*/) {
        if (stage == ClipStage::draw) tally.frame();
      });
  row.wall_seconds = seconds_since(start);
  row.cpu_seconds = process_cpu_seconds() - cpu_start;
  row.frames = result.stats.frames_drawn;
  row.simulate_seconds = result.stats.simulate_seconds;
  row.draw_seconds = result.stats.draw_seconds;
  row.convert_seconds = result.stats.convert_seconds;
  row.encode_seconds = result.stats.encode_seconds;
  row.draw_waited_seconds = result.draw_waited_seconds;
  row.encoder_idle_seconds = result.encoder_idle_seconds;
  row.bytes = result.video_bytes;
  row.encoder = result.encoder;
  return row;
}

struct AloneRun {
  double wall_seconds = 0, cpu_seconds = 0, unpack_seconds = 0;
};

/// The stored frames through the same pipeline and encoder settings.
AloneRun run_encode_alone(const MechanismClip& clip, const FrameStore& store, const fs::path& target, Tally& tally) {
  AloneRun run;
  const double cpu_start = process_cpu_seconds();
  const auto start = Clock::now();
  VideoWriter video(target, clip_video_options(clip.settings));
  FramePipeline pipeline(clip.settings.width, clip.settings.height, [&](const Frame& frame) { video.write(frame); });
  for (std::size_t k = 0; k < store.size(); ++k) {
    Frame& frame = pipeline.acquire();
    const auto unpack_start = Clock::now();
    store.unpack(k, frame);
    run.unpack_seconds += seconds_since(unpack_start);
    pipeline.submit();
    tally.frame();
  }
  pipeline.finish();
  video.finish();
  run.wall_seconds = seconds_since(start);
  run.cpu_seconds = process_cpu_seconds() - cpu_start;
  return run;
}

/// Draws every frame of the clip once, as the pipeline draws them, and keeps them.
FrameStore predraw(const BenchClip& bench, Tally& tally) {
  const MechanismClip& clip = bench.clip;
  ClipResult unused;
  MechanismClipFrames frames(*bench.system, bench.initial, clip, unused);
  FrameStore store(clip.settings.width, clip.settings.height);
  Frame frame(clip.settings.width, clip.settings.height);
  for (long k = 0; k < frames.count(); ++k) {
    frames.draw(static_cast<std::size_t>(k), frame);
    store.add(frame);
    tally.frame();
  }
  return store;
}

MovieRow measure_movie(const BenchClip& bench, const FrameStore& store, const ScratchFolder& scratch, int repeats,
                       Tally& tally) {
  const MechanismClip& clip = bench.clip;
  const std::string name = bench.name + "_" + size_name(clip.settings.width, clip.settings.height);
  const fs::path piped = scratch / ("pipeline_" + name + ".mp4"), alone = scratch / ("alone_" + name + ".mp4");
  MovieRow best;
  AloneRun best_alone;
  for (int r = 0; r < repeats; ++r) {
    const MovieRow row = run_pipeline(bench, piped, tally);
    if (r == 0 || row.wall_seconds < best.wall_seconds) best = row;
    const AloneRun run = run_encode_alone(clip, store, alone, tally);
    if (r == 0 || run.wall_seconds < best_alone.wall_seconds) best_alone = run;
  }
  best.clip = bench.name;
  best.width = clip.settings.width;
  best.height = clip.settings.height;
  best.fps = clip.settings.fps;
  best.alone_wall_seconds = best_alone.wall_seconds;
  best.alone_cpu_seconds = best_alone.cpu_seconds;
  best.alone_unpack_seconds = best_alone.unpack_seconds;
  best.stored_bytes = store.bytes();
  best.same_output = same_bytes(piped, alone);
  fs::remove(piped);
  fs::remove(alone);
  return best;
}

/// Frame numbers spread evenly over the clip.
std::vector<std::size_t> spread(std::size_t available, std::size_t wanted) {
  std::vector<std::size_t> picks;
  const std::size_t n = std::min(available, wanted);
  for (std::size_t k = 0; k < n; ++k) picks.push_back(k * available / n);
  return picks;
}

PngRow measure_png(const FrameStore& store, const std::string& clip, int width, int height, std::size_t frames,
                   const ScratchFolder& scratch, Tally& tally) {
  PngRow row;
  row.clip = clip;
  row.width = width;
  row.height = height;
  const std::vector<std::size_t> picks = spread(store.size(), frames);
  row.frames = static_cast<long>(picks.size());
  Frame frame(width, height);
  const std::string name = clip + "_" + size_name(width, height);

  const fs::path ours_folder = scratch / ("ours_" + name);
  fs::create_directory(ours_folder);
  {
    const auto start = Clock::now();
    PngSequenceWriter writer(ours_folder, width, height, "out", PngOptions{}, 2, row.frames);
    for (const std::size_t k : picks) {
      const auto unpack_start = Clock::now();
      store.unpack(k, frame);
      row.unpack_seconds += seconds_since(unpack_start);
      writer.write(frame);
      tally.frame();
    }
    writer.finish();
    row.ours_seconds = seconds_since(start);
    row.ours_convert_seconds = writer.stats().convert_seconds;
    row.ours_compress_seconds = writer.stats().encode_seconds;
  }
  row.ours_bytes = folder_bytes(ours_folder);

  // Cairo's writer on an RGB24 view of the same pixels: 8-bit RGB files, as ours.
  const fs::path cairo_folder = scratch / ("cairo_" + name);
  fs::create_directory(cairo_folder);
  {
    const cairo::SurfacePtr surface(
        cairo_image_surface_create_for_data(frame.pixels.data(), CAIRO_FORMAT_RGB24, width, height, frame.stride));
    cairo::check(surface.get(), "cannot wrap a frame in a Cairo surface");
    std::array<char, 32> file{};
    const auto start = Clock::now();
    for (std::size_t i = 0; i < picks.size(); ++i) {
      cairo_surface_flush(surface.get());
      store.unpack(picks[i], frame);
      cairo_surface_mark_dirty(surface.get());
      std::snprintf(file.data(), file.size(), "frame_%05zu.png", i);
      AtomicFile target(cairo_folder / file.data(), "out", true);
      const cairo_status_t status = cairo_surface_write_to_png(surface.get(), target.temp_path().c_str());
      if (status != CAIRO_STATUS_SUCCESS)
        throw Error::failure("cairo_surface_write_to_png: " + std::string(cairo_status_to_string(status)));
      target.commit();
      tally.frame();
    }
    row.cairo_seconds = seconds_since(start);
  }
  row.cairo_bytes = folder_bytes(cairo_folder);
  fs::remove_all(ours_folder);
  fs::remove_all(cairo_folder);
  return row;
}

}  // namespace

BenchClip default_clip(const std::string& mechanism, int width, int height, int fps, double duration,
                       const fs::path& assets) {
  BenchClip made;
  made.name = mechanism;
  RenderSettings base;
  base.duration = duration;
  RenderTarget target;
  target.still = false;
  const RenderRequest request = resolve_render_options(
      {{"size", std::to_string(width) + "x" + std::to_string(height)}, {"fps", std::to_string(fps)}}, target, base);
  SimulationOptions simulation;
  simulation.duration = request.settings.duration;
  simulation.validate();
  // As the render command: the initial state worked out as solve does, the case derived once.
  const MechanismSolution checked =
      work_out_mechanism(load_mechanism(mechanism), {static_cast<CaseId>(simulation.case_id)});
  made.system = checked.system;
  made.initial = checked.state;
  ClipPlan plan;
  plan.out = "clip.mp4";  // checked as an MP4; each run sets its own
  plan.assets = assets;
  plan.equations = case_equations_as<EquationsText>;
  CheckedMechanismClip clip = mechanism_clip(request, *made.system, made.initial, simulation, plan);
  made.clip = std::move(clip.clip);
  made.clip.out.reset();
  made.clip.derived = checked.cases.front().system;
  return made;
}

RenderBenchResult run_render_bench(const RenderBenchOptions& options) {
  prepare_output_folder(options.out, "out");
  RenderBenchResult result;
  result.cores = std::max(1u, std::thread::hardware_concurrency());
  std::ifstream("/proc/loadavg") >> result.load_average;
  const std::vector<Size> sizes = options.quick ? std::vector<Size>{{320, 180}, {640, 360}}
                                                : std::vector<Size>{{854, 480}, {1280, 720}, {1920, 1080}};
  const double duration = options.quick ? 2.0 : 10.0;
  const int fps = 30;
  result.repeats = options.quick ? 1 : 3;
  const std::size_t png_frames = options.quick ? 10 : 60;

  std::vector<BenchClip> clips;
  long total = 0;
  for (const Size& s : sizes)
    for (const char* name : kRenderClips) {
      clips.push_back(default_clip(name, s.width, s.height, fps, duration, options.assets));
      const long count = clips.back().clip.settings.frame_count();
      total += count * (1 + 2 * result.repeats) + 2 * std::min<long>(count, static_cast<long>(png_frames));
    }
  Progress progress("bench render", total, "frames", options.quiet);
  Tally tally{progress};
  {
    const ScratchFolder scratch(options.out);
    for (const BenchClip& clip : clips) {
      const FrameStore store = predraw(clip, tally);
      result.movies.push_back(measure_movie(clip, store, scratch, result.repeats, tally));
      const RenderSettings& s = clip.clip.settings;
      result.pngs.push_back(measure_png(store, clip.name, s.width, s.height, png_frames, scratch, tally));
    }
  }
  progress.finish();
  std::ifstream("/proc/loadavg") >> result.load_average_end;
  write_render_report(options, result);
  return result;
}

double judged_ratio(const MovieRow& row, const RenderBenchResult& result) {
  return result.busy() ? row.cpu_ratio() : row.ratio();
}

const MovieRow* target_movie(const RenderBenchResult& result, const std::string& clip) {
  for (const MovieRow& row : result.movies)
    if (row.clip == clip && row.width == kTargetWidth && row.height == kTargetHeight) return &row;
  return nullptr;
}

const PngRow* target_png(const RenderBenchResult& result, const std::string& clip) {
  for (const PngRow& row : result.pngs)
    if (row.clip == clip && row.width == kTargetWidth && row.height == kTargetHeight) return &row;
  return nullptr;
}

}  // namespace linkage::bench
