// One frame drawn: the pipeline's own drawing (MechanismClipFrames) of the clip `linkage
// render` makes by default for the homework (two-blocks) and for the four-bar, 1280x720,
// cycling through its 300 frames. One frame encoded: H.264 (the tool's MP4 settings)
// and PNG (the tool's fast setting), 1280x720, on a synthetic frame that changes every
// iteration (a moving gradient with an edge), so the encoder does real work.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "bench/render_bench.hpp"
#include "core/frame.hpp"
#include "encode/png_writer.hpp"
#include "encode/video_writer.hpp"

namespace linkage::bench {
namespace {

void paint(Frame& frame, int k) {
  for (int y = 0; y < frame.height; ++y) {
    std::uint8_t* row = frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride;
    for (int x = 0; x < frame.width; ++x) {
      const bool block = (x - 4 * k) % 400 < 120 && y > 200 && y < 500;
      row[4 * x + 0] = static_cast<std::uint8_t>(block ? 40 : (x + k) & 0xff);
      row[4 * x + 1] = static_cast<std::uint8_t>(block ? 90 : (y + 2 * k) & 0xff);
      row[4 * x + 2] = static_cast<std::uint8_t>(block ? 200 : 128);
      row[4 * x + 3] = 0xff;
    }
  }
}

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("linkage-micro-" + std::to_string(::getpid()) + "-" + name);
}

void BM_DrawFrame(benchmark::State& state, const char* mechanism) {
  const BenchClip clip = default_clip(mechanism, 1280, 720, 30, 10.0);
  ClipResult unused;
  MechanismClipFrames frames(*clip.system, clip.initial, clip.clip, unused);
  Frame frame(clip.clip.settings.width, clip.clip.settings.height);
  std::size_t k = 0;
  for (auto _ : state) {
    frames.draw(k, frame);
    benchmark::DoNotOptimize(frame.pixels.data());
    k = (k + 1) % static_cast<std::size_t>(frames.count());
  }
}
BENCHMARK_CAPTURE(BM_DrawFrame, two_blocks, "two-blocks")
    ->Name("render/frame_1280x720/two-blocks")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DrawFrame, four_bar, "four-bar")
    ->Name("render/frame_1280x720/four-bar")
    ->Unit(benchmark::kMillisecond);

void BM_EncodeH264Frame(benchmark::State& state) {
  VideoOptions options;  // 1280x720, 30 fps, the tool's defaults
  const std::filesystem::path target = scratch("frame.mp4");
  Frame frame(options.width, options.height);
  {
    VideoWriter video(target, options);
    int k = 0;
    for (auto _ : state) {
      state.PauseTiming();
      paint(frame, k++);
      state.ResumeTiming();
      video.write(frame);
    }
    video.finish();  // flushes the encoder's look-ahead: counted once, outside the loop
  }
  std::filesystem::remove(target);
}
BENCHMARK(BM_EncodeH264Frame)->Name("encode/h264_frame_1280x720")->Unit(benchmark::kMillisecond);

void BM_WritePngFrame(benchmark::State& state) {
  const std::filesystem::path target = scratch("frame.png");
  Frame frame(1280, 720);
  int k = 0;
  for (auto _ : state) {
    state.PauseTiming();
    paint(frame, k++);
    state.ResumeTiming();
    write_png(frame, target, "micro");
  }
  std::filesystem::remove(target);
}
BENCHMARK(BM_WritePngFrame)->Name("encode/png_frame_1280x720")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkage::bench
