#include "pipeline/encode_frames.hpp"

#include "core/atomic_file.hpp"
#include "core/interrupt.hpp"
#include "encode/frame_pipeline.hpp"
#include "encode/png_writer.hpp"
#include "encode/video_writer.hpp"
#include "render/vector_still.hpp"

namespace linkage {

void encode_frames(const std::optional<std::filesystem::path>& video_out,
                   const std::optional<std::filesystem::path>& frames_dir, const RenderSettings& s, long count,
                   const std::function<void(std::size_t, Frame&)>& draw, const ClipProgress& progress,
                   ClipResult& result) {
  RenderStats& stats = result.stats;
  std::optional<VideoWriter> video;
  std::optional<PngSequenceWriter> pngs;
  if (video_out) {
    video.emplace(*video_out, clip_video_options(s, output_kind(*video_out, "out")));
    stats.encoder_opened = true;
  }
  if (frames_dir) {
    ensure_directory(*frames_dir, "frames");
    pngs.emplace(*frames_dir, s.width, s.height, "frames", PngOptions{}, 2, count);
  }
  FramePipeline pipeline(s.width, s.height, [&](const Frame& frame) {
    if (video) video->write(frame);
    if (pngs) pngs->write(frame);
  });
  for (long k = 0; k < count; ++k) {
    throw_if_interrupted();
    Frame& frame = pipeline.acquire();
    draw(static_cast<std::size_t>(k), frame);
    pipeline.submit();
    if (progress) progress(ClipStage::draw, k + 1, count);
  }
  pipeline.finish();
  result.draw_waited_seconds = pipeline.stats().producer_wait_seconds;
  result.encoder_idle_seconds = pipeline.stats().consumer_idle_seconds;
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
    result.video_bytes = video->stats().bytes;
    result.encoder = video->encoder_name();
    if (!video->note().empty()) result.notes.push_back(video->note());
  }
}

void write_still(FrameLayout& layout, std::size_t index, double t, const RenderSettings& settings,
                 const std::filesystem::path& out, const std::function<void(Frame&)>& raster,
                 const std::function<void(cairo_t*)>& vector, ClipResult& result) {
  const OutputKind kind = output_kind(out, "out");
  if (kind == OutputKind::png) {
    Frame frame(settings.width, settings.height);
    layout.draw(index, t, frame, raster);
    write_png(frame, out, "out");
    ++result.stats.png_files_written;
  } else {
    write_vector_still([&](cairo_t* cr) { layout.draw_vector(index, t, cr, vector); }, kind, settings.width,
                       settings.height, out, "out");
  }
}

}  // namespace linkage
