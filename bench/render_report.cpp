// Files and terminal lines of `linkage bench render`: render.csv (one row per format and
// size), render.md (the targets first, then the tables).
#include <cmath>
#include <sstream>

#include "bench/accuracy_report.hpp"
#include "bench/render_bench.hpp"
#include "core/atomic_file.hpp"
#include "core/number_format.hpp"

namespace linkage::bench {
namespace {

std::string sig(double v, int digits = 3) { return std::isfinite(v) ? format_significant(v, digits) : "-"; }
std::string ms_per_frame(double seconds, long frames) { return sig(1e3 * seconds / static_cast<double>(frames)); }
std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

struct Verdict {
  std::string measured, met;
};

Verdict pipeline_verdict(const RenderBenchResult& result, const std::string& clip) {
  const MovieRow* row = target_movie(result, clip);
  if (row == nullptr) return {"not measured (--quick)", ""};
  const double ratio = judged_ratio(*row, result);
  const std::string measured =
      result.busy() ? sig(ratio) + "x by CPU time (wall " + sig(row->ratio()) + "x; busy machine)" : sig(ratio) + "x";
  return {measured, ratio <= kMaxPipelineRatio ? "met" : "MISSED"};
}

Verdict png_verdict(const RenderBenchResult& result, const std::string& clip) {
  const PngRow* row = target_png(result, clip);
  if (row == nullptr) return {"not measured (--quick)", ""};
  return {sig(row->ratio()) + "x", row->ratio() >= kMinPngRatio ? "met" : "MISSED"};
}

std::string render_csv(const RenderBenchResult& result) {
  std::ostringstream out;
  out << "format,clip,width,height,fps,frames,wall_s,frames_per_s,simulate_s,draw_s,convert_s,encode_s,draw_waited_s,"
         "encoder_idle_s,baseline,baseline_wall_s,baseline_frames_per_s,ratio,cpu_s,baseline_cpu_s,cpu_ratio,unpack_s,"
         "bytes_per_frame,baseline_bytes_per_frame,same_output,stored_bytes,repeats\n";
  for (const MovieRow& m : result.movies) {
    const double per_frame = static_cast<double>(m.bytes) / static_cast<double>(m.frames);
    out << "mp4," << m.clip << ',' << m.width << ',' << m.height << ',' << m.fps << ',' << m.frames << ','
        << csv_number(m.wall_seconds) << ',' << csv_number(m.fps_achieved()) << ',' << csv_number(m.simulate_seconds)
        << ',' << csv_number(m.draw_seconds) << ',' << csv_number(m.convert_seconds) << ','
        << csv_number(m.encode_seconds) << ',' << csv_number(m.draw_waited_seconds) << ','
        << csv_number(m.encoder_idle_seconds) << ",encode alone," << csv_number(m.alone_wall_seconds) << ','
        << csv_number(m.alone_fps()) << ',' << csv_number(m.ratio()) << ',' << csv_number(m.cpu_seconds) << ','
        << csv_number(m.alone_cpu_seconds) << ',' << csv_number(m.cpu_ratio()) << ','
        << csv_number(m.alone_unpack_seconds) << ',' << csv_number(per_frame) << ',' << csv_number(per_frame) << ','
        << (m.same_output ? "yes" : "no") << ',' << m.stored_bytes << ',' << result.repeats << '\n';
  }
  for (const PngRow& p : result.pngs) {
    const auto frames = static_cast<double>(p.frames);
    out << "png," << p.clip << ',' << p.width << ',' << p.height << ",," << p.frames << ','
        << csv_number(p.ours_seconds) << ',' << csv_number(p.ours_fps()) << ",,," << csv_number(p.ours_convert_seconds)
        << ',' << csv_number(p.ours_compress_seconds) << ",,,cairo," << csv_number(p.cairo_seconds) << ','
        << csv_number(p.cairo_fps()) << ',' << csv_number(p.ratio()) << ",,,," << csv_number(p.unpack_seconds) << ','
        << csv_number(static_cast<double>(p.ours_bytes) / frames) << ','
        << csv_number(static_cast<double>(p.cairo_bytes) / frames) << ",,,1\n";
  }
  return out.str();
}

std::string render_markdown(const RenderBenchOptions& options, const RenderBenchResult& result) {
  const MovieRow& first = result.movies.front();
  std::ostringstream md;
  md << "# Rendering throughput\n\n"
     << "Reproduce with `linkage bench render --out " << options.out.string() << (options.quick ? " --quick" : "")
     << "`. Machine: " << result.cores << " cores, 1-minute load average " << sig(result.load_average, 2)
     << " at the start and " << sig(result.load_average_end, 2) << " at the end"
     << (result.busy() ? " (busy: other processes wanted more than every core, so the MP4 target is judged by CPU "
                         "time, below)"
                       : "")
     << ". Each comparison ran its two sides alternately " << result.repeats
     << (result.repeats == 1 ? " time" : " times") << "; the fastest run of each side counts.\n\n"
     << "The clips are what `linkage render` makes by default, through the one path every mechanism takes "
        "(MechanismScene, the mechanism painter): *two-blocks* is the homework (`linkage render` without "
        "--mechanism), *four-bar* is `--mechanism four-bar`; each with its file's title and trails, Case 3, DOP853 at "
        "rtol = atol = 1e-10, every default element, the default camera and the light theme, "
     << sig(static_cast<double>(first.frames) / first.fps) << " s at " << first.fps << " fps. MP4: " << first.encoder
     << ", preset medium, tune animation, CRF 20, 2 encoder threads, yuv420p (the settings of `linkage render`).\n\n"
     << "## Targets\n\n| clip | target | measured | goal | |\n| --- | --- | --- | --- | --- |\n";
  for (const char* clip : kRenderClips) {
    const Verdict piped = pipeline_verdict(result, clip);
    md << "| " << clip << " | MP4 " << size_text(kTargetWidth, kTargetHeight)
       << ": the whole pipeline's time / encoding the same frames alone | " << piped.measured
       << " | <= " << sig(kMaxPipelineRatio) << "x | " << piped.met << " |\n";
  }
  for (const char* clip : kRenderClips) {
    const Verdict png = png_verdict(result, clip);
    md << "| " << clip << " | PNG sequence " << size_text(kTargetWidth, kTargetHeight)
       << ": our frames per second / Cairo's writer's | " << png.measured << " | >= " << sig(kMinPngRatio) << "x | "
       << png.met << " |\n";
  }
  md << "\n";
  if (const MovieRow* row = target_movie(result, kRenderClips.front()); row != nullptr && result.busy())
    md << "The machine was busy, so wall times measured the other processes as much as ours and the MP4 target is "
          "judged by the CPU ratio: the encoder waited for a drawing only "
       << sig(row->encoder_idle_seconds, 2) << " s of the pipeline's " << sig(row->wall_seconds)
       << " s, so drawing can slow the pipeline only by the CPU it takes from the encoder, and on an idle machine "
          "the wall ratio stays within about the CPU ratio. The PNG target is judged by wall time: our writer is "
          "parallel by design, which CPU time cannot credit.\n\n";

  md << "## MP4\n\n"
     << "The pipeline is `linkage render --out clip.mp4`: simulate, then draw on one thread while the encoder thread "
        "converts (libswscale) and encodes (libx264, itself on 2 threads), through a queue of 3 frame buffers. "
        "Stage times are per frame; drawing overlaps the encoder, so they add up to more than the wall time. "
        "*Drawing waited* is time the drawing thread found every buffer queued (the encoder is the bottleneck); "
        "*encoder idle* is time the encoder waited for a drawn frame. *Encode alone* feeds the same frames, drawn "
        "beforehand and kept in memory (run-length coded), through the same queue to the same encoder settings; "
        "*same file* says the two MP4s are byte-identical. *CPU ratio* is the process CPU time (all threads) of the "
        "pipeline over that of encoding alone: the work drawing adds, which another process's load hardly "
        "changes, while the wall-time ratio moves with it.\n\n"
     << "| clip | size | frames | simulate (s) | draw (ms/frame) | convert (ms/frame) | encode (ms/frame) | drawing "
        "waited "
        "(s) "
        "| encoder idle (s) | pipeline (s) | pipeline fps | encode alone (s) | encode alone fps | ratio | CPU ratio | "
        "kB/frame | same file | stored MB |\n"
     << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
        "| --- | ---: |\n";
  for (const MovieRow& m : result.movies)
    md << "| " << m.clip << " | " << size_text(m.width, m.height) << " | " << m.frames << " | "
       << sig(m.simulate_seconds, 2) << " | " << ms_per_frame(m.draw_seconds, m.frames) << " | "
       << ms_per_frame(m.convert_seconds, m.frames) << " | " << ms_per_frame(m.encode_seconds, m.frames) << " | "
       << sig(m.draw_waited_seconds, 2) << " | " << sig(m.encoder_idle_seconds, 2) << " | " << sig(m.wall_seconds)
       << " | " << sig(m.fps_achieved()) << " | " << sig(m.alone_wall_seconds) << " | " << sig(m.alone_fps()) << " | "
       << sig(m.ratio()) << "x | " << sig(m.cpu_ratio()) << "x | "
       << sig(static_cast<double>(m.bytes) / static_cast<double>(m.frames) / 1e3, 2) << " | "
       << (m.same_output ? "yes" : "NO") << " | " << sig(static_cast<double>(m.stored_bytes) / 1e6, 2) << " |\n";

  md << "\n## PNG sequence\n\n"
     << "Frames spread evenly over the same clip. Ours is `linkage render --frames`' writer: libspng at zlib level 1 "
        "with no row filter, the BGRA -> RGB conversion on the calling thread and compression on 2 worker threads. "
        "Cairo's is `cairo_surface_write_to_png` on an RGB24 surface of the same pixels, so both write 8-bit RGB. "
        "Both write each file under a temporary name and rename it. Both wall times include unpacking the stored "
        "frames (the last column), which makes the ratio a little smaller than the writers' own.\n\n"
     << "| clip | size | frames | ours (s) | ours fps | ours kB/frame | Cairo (s) | Cairo fps | Cairo kB/frame | ratio "
        "| "
        "unpacking (ms/frame) |\n"
     << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const PngRow& p : result.pngs) {
    const auto frames = static_cast<double>(p.frames);
    md << "| " << p.clip << " | " << size_text(p.width, p.height) << " | " << p.frames << " | " << sig(p.ours_seconds)
       << " | " << sig(p.ours_fps()) << " | " << sig(static_cast<double>(p.ours_bytes) / frames / 1e3) << " | "
       << sig(p.cairo_seconds) << " | " << sig(p.cairo_fps()) << " | "
       << sig(static_cast<double>(p.cairo_bytes) / frames / 1e3) << " | " << sig(p.ratio()) << "x | "
       << ms_per_frame(p.unpack_seconds, p.frames) << " |\n";
  }
  return md.str();
}

}  // namespace

void write_render_report(const RenderBenchOptions& options, RenderBenchResult& result) {
  write_file_atomically(options.out / "render.csv", render_csv(result), "out");
  result.files.push_back(options.out / "render.csv");
  write_file_atomically(options.out / "render.md", render_markdown(options, result), "out");
  result.files.push_back(options.out / "render.md");
}

std::vector<std::string> render_bench_lines(const RenderBenchResult& result) {
  std::vector<std::string> lines;
  for (const MovieRow& m : result.movies)
    lines.push_back("MP4 " + m.clip + " " + size_text(m.width, m.height) + ": " + std::to_string(m.frames) +
                    " frames, pipeline " + sig(m.fps_achieved()) + " fps (draw " +
                    ms_per_frame(m.draw_seconds, m.frames) + ", convert " + ms_per_frame(m.convert_seconds, m.frames) +
                    ", encode " + ms_per_frame(m.encode_seconds, m.frames) + " ms/frame), encode alone " +
                    sig(m.alone_fps()) + " fps: ratio " + sig(m.ratio()) + " (CPU " + sig(m.cpu_ratio()) + ")" +
                    (m.same_output ? "" : " (the two files differ!)"));
  for (const PngRow& p : result.pngs)
    lines.push_back("PNG " + p.clip + " " + size_text(p.width, p.height) + ": ours " + sig(p.ours_fps()) +
                    " fps, Cairo's " + sig(p.cairo_fps()) + " fps: " + sig(p.ratio()) + "x");
  for (const char* clip : kRenderClips) {
    const Verdict piped = pipeline_verdict(result, clip);
    lines.push_back("target: MP4 " + std::string(clip) + " " + size_text(kTargetWidth, kTargetHeight) +
                    " pipeline / encode alone " + piped.measured + " (goal <= " + sig(kMaxPipelineRatio) + "x)" +
                    (piped.met.empty() ? "" : " " + piped.met));
  }
  for (const char* clip : kRenderClips) {
    const Verdict png = png_verdict(result, clip);
    lines.push_back("target: PNG " + std::string(clip) + " " + size_text(kTargetWidth, kTargetHeight) +
                    " ours / Cairo " + png.measured + " (goal >= " + sig(kMinPngRatio) + "x)" +
                    (png.met.empty() ? "" : " " + png.met));
  }
  return lines;
}

}  // namespace linkage::bench
