#include "encode/video_writer.hpp"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/opt.h>
#include <libavutil/pixfmt.h>
}

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <string_view>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "encode/av_support.hpp"

namespace linkage {
namespace {
using Clock = std::chrono::steady_clock;

constexpr int max_dimension = 8192;
constexpr std::array<std::string_view, 10> x264_presets = {"ultrafast", "superfast", "veryfast", "faster",   "fast",
                                                           "medium",    "slow",      "slower",   "veryslow", "placebo"};
constexpr std::array<std::string_view, 8> x264_tunes = {"film", "animation", "grain",      "stillimage",
                                                        "psnr", "ssim",      "fastdecode", "zerolatency"};
// MPEG-4 part 2 quantiser (1 best .. 31 worst) for the fallback encoder.
constexpr int mpeg4_quantiser = 3;
// libvpx-vp9 constant quality (0 best .. 63 worst): Google's suggestion for 720p is
// 32; line art on flat colours stays sharp a little lower.
constexpr int vp9_crf = 30;
// GIF frame delays are whole hundredths of a second and browsers play delays under
// 0.02 s at 0.1 s, so a GIF above 50 frames per second would play slowly.
constexpr int gif_max_fps = 50;
// One palette per frame from that frame's colours, ordered (Bayer) dithering: error
// diffusion would make still areas flicker from frame to frame.
constexpr const char* gif_filters =
    "split[a][b];[a]palettegen=max_colors=256:reserve_transparent=0:stats_mode=single[p];"
    "[b][p]paletteuse=new=1:dither=bayer:bayer_scale=4";

struct FilterGraphDeleter {
  void operator()(AVFilterGraph* p) const { avfilter_graph_free(&p); }
};
struct InOutDeleter {
  void operator()(AVFilterInOut* p) const { avfilter_inout_free(&p); }
};
using FilterGraphPtr = std::unique_ptr<AVFilterGraph, FilterGraphDeleter>;
using InOutPtr = std::unique_ptr<AVFilterInOut, InOutDeleter>;

const char* muxer_name(VideoFormat format) {
  return format == VideoFormat::gif ? "gif" : format == VideoFormat::webm ? "webm" : "mp4";
}

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  std::string text;
  for (const auto name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

template <std::size_t N>
bool contains(const std::array<std::string_view, N>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Encoders to try, best first: libx264, FFmpeg's default H.264 encoder, MPEG-4 part 2.
std::vector<const AVCodec*> candidate_encoders(VideoCodec wanted) {
  std::vector<const AVCodec*> candidates;
  auto add = [&](const AVCodec* codec) {
    if (codec != nullptr && std::find(candidates.begin(), candidates.end(), codec) == candidates.end())
      candidates.push_back(codec);
  };
  if (wanted != VideoCodec::mpeg4) {
    add(avcodec_find_encoder_by_name("libx264"));
    add(avcodec_find_encoder(AV_CODEC_ID_H264));
  }
  if (wanted != VideoCodec::h264) add(avcodec_find_encoder(AV_CODEC_ID_MPEG4));
  return candidates;
}

// Sets the encoder's quality options; every setting is checked.
void configure_quality(AVCodecContext& context, const AVCodec& codec, const VideoOptions& options) {
  const std::string name = codec.name;
  if (name == "libvpx-vp9") {
    context.bit_rate = 0;  // with crf: constant quality, no bit-rate cap
    av::check(av_opt_set_int(context.priv_data, "crf", vp9_crf, 0), "libvpx-vp9 crf");
    av::check(av_opt_set(context.priv_data, "deadline", "good", 0), "libvpx-vp9 deadline");
    av::check(av_opt_set_int(context.priv_data, "cpu-used", 4, 0), "libvpx-vp9 cpu-used");
    av::check(av_opt_set_int(context.priv_data, "row-mt", 1, 0), "libvpx-vp9 row-mt");
  } else if (codec.id == AV_CODEC_ID_GIF) {
    // Lossless on its palette: nothing to set.
  } else if (name == "libx264") {
    av::check(av_opt_set(context.priv_data, "preset", options.preset.c_str(), 0), "libx264 preset");
    if (!options.tune.empty())
      av::check(av_opt_set(context.priv_data, "tune", options.tune.c_str(), 0), "libx264 tune");
    av::check(av_opt_set_double(context.priv_data, "crf", options.crf, 0), "libx264 crf");
  } else if (codec.id == AV_CODEC_ID_MPEG4) {
    context.flags |= AV_CODEC_FLAG_QSCALE;
    context.global_quality = FF_QP2LAMBDA * mpeg4_quantiser;
  } else {
    // Another H.264 encoder (hardware): no CRF, so a bit rate generous for line art.
    context.bit_rate = static_cast<std::int64_t>(options.width) * options.height * options.fps / 8;
  }
}

// A configured and opened encoder context, or nullptr with `why` set.
av::CodecContextPtr open_encoder(const AVCodec& codec, const VideoOptions& options, bool global_header,
                                 std::string& why) {
  av::CodecContextPtr context(avcodec_alloc_context3(&codec));
  if (!context) throw Error::failure("cannot allocate an encoder context (out of memory)");
  context->width = options.width;
  context->height = options.height;
  const bool gif = codec.id == AV_CODEC_ID_GIF;
  context->pix_fmt = gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
  context->time_base = AVRational{1, options.fps};
  context->framerate = AVRational{options.fps, 1};
  context->sample_aspect_ratio = AVRational{1, 1};
  context->gop_size = options.keyframe_seconds * options.fps;
  context->thread_count = options.threads;
  context->flags |= AV_CODEC_FLAG_BITEXACT;
  if (global_header) context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // What the converter produces, stated so players do not guess (HD players assume
  // BT.709, SD players BT.601 when untagged).
  if (!gif) {
    context->color_range = AVCOL_RANGE_MPEG;
    context->colorspace = AVCOL_SPC_BT709;
    context->color_primaries = AVCOL_PRI_BT709;
    context->color_trc = AVCOL_TRC_BT709;
  }
  configure_quality(*context, codec, options);
  const int status = avcodec_open2(context.get(), &codec, nullptr);
  if (status < 0) {
    why = av::error_text(status);
    if (const std::string logged = av::take_logged_error(); !logged.empty()) why += " (" + logged + ")";
    return nullptr;
  }
  return context;
}
}  // namespace

struct VideoWriter::Impl {
  explicit Impl(const std::filesystem::path& target, const VideoOptions& opts)
      : options(opts), file(target, opts.setting, true) {
    if (file.kind() != AtomicFile::Kind::replace)
      throw Error::invalid(opts.setting, std::string("a video is finished by seeking back into the file, so '") +
                                             target.string() +
                                             "' must be a regular file (not standard output, a device or a pipe)");
  }

  VideoOptions options;
  AtomicFile file;  // declared before the AV objects: the file closes before the temp is removed
  av::OutputPtr format;
  av::CodecContextPtr encoder;
  AVStream* stream = nullptr;         // owned by `format`
  av::SwsPtr converter;               // MP4, WebM: BGRA -> yuv420p
  FilterGraphPtr palette;             // GIF: BGRA -> pal8
  AVFilterContext* source = nullptr;  // owned by `palette`
  AVFilterContext* sink = nullptr;    // owned by `palette`
  av::FramePtr filtered;              // a pal8 frame from the sink
  av::FramePtr picture;               // the encoder's input (GIF: the filter graph's)
  av::PacketPtr packet;
  std::string encoder_name;
  std::string note;
  VideoCodec codec = VideoCodec::h264;
  EncodeStats stats;
  bool finished = false;
  bool header_written = false;  // GIF, WebM

  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // FFmpeg 5.1's GIF muxer holds the last packet until its trailer and has no other
  // cleanup: an unfinished GIF (Ctrl-C, an error) still gets its trailer, into the temp
  // file that is removed next, so nothing leaks.
  ~Impl() {
    if (!finished && header_written && options.format == VideoFormat::gif) av_write_trailer(format.get());
  }

  void open();
  void open_encoder_for_format();
  void open_palette_filter();
  void convert(const Frame& frame);
  // GIF: sends `frame` (nullptr flushes) through the palette filters and encodes what comes out.
  void filter_and_encode(const AVFrame* frame);
  // Sends `frame` (nullptr flushes) and muxes every packet the encoder returns.
  void encode(const AVFrame* frame);
};

void VideoWriter::Impl::open() {
  av::install_quiet_log();
  const std::string temp = file.temp_path().string();
  AVFormatContext* raw_format = nullptr;
  const std::string kind = name(options.format);
  av::check(avformat_alloc_output_context2(&raw_format, nullptr, muxer_name(options.format), temp.c_str()),
            "cannot set up the " + kind + " muxer");
  format.reset(raw_format);
  format->flags |= AVFMT_FLAG_BITEXACT;  // no "Lavf" version string in the file
  open_encoder_for_format();

  stream = avformat_new_stream(format.get(), nullptr);
  if (stream == nullptr) throw Error::failure("cannot add a video stream (out of memory)");
  stream->time_base = encoder->time_base;
  stream->avg_frame_rate = encoder->framerate;
  av::check(avcodec_parameters_from_context(stream->codecpar, encoder.get()), "cannot copy the encoder parameters");

  picture.reset(av_frame_alloc());
  packet.reset(av_packet_alloc());
  if (!picture || !packet) throw Error::failure("cannot allocate a video frame (out of memory)");
  picture->width = options.width;
  picture->height = options.height;
  if (options.format == VideoFormat::gif) {
    open_palette_filter();
    picture->format = AV_PIX_FMT_RGB32;
  } else {
    converter.reset(sws_getContext(options.width, options.height, AV_PIX_FMT_RGB32, options.width, options.height,
                                   AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr,
                                   nullptr));
    if (!converter) throw Error::failure("cannot set up the BGRA -> yuv420p converter (libswscale)");
    // Full-range RGB in, BT.709 limited-range YUV out, matching the stream's tags.
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    av::check(sws_setColorspaceDetails(converter.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16),
              "cannot select BT.709 colour conversion");
    picture->format = AV_PIX_FMT_YUV420P;
    picture->color_range = AVCOL_RANGE_MPEG;
    picture->colorspace = AVCOL_SPC_BT709;
  }
  av::check(av_frame_get_buffer(picture.get(), 0), "cannot allocate a video frame");

  av::check(avio_open(&format->pb, temp.c_str(), AVIO_FLAG_WRITE), "cannot create '" + temp + "'");
  if (options.format != VideoFormat::mp4) {
    av::check(avformat_write_header(format.get(), nullptr), "cannot write the " + kind + " header");
    header_written = true;
    return;
  }
  AVDictionary* muxer_options = nullptr;
  av::check(av_dict_set(&muxer_options, "movflags", "+faststart", 0), "cannot set movflags");
  const int header = avformat_write_header(format.get(), &muxer_options);
  const bool unused = av_dict_count(muxer_options) > 0;
  av_dict_free(&muxer_options);
  av::check(header, "cannot write the MP4 header");
  if (unused) throw Error::failure("the MP4 muxer did not accept movflags=+faststart");
}

void VideoWriter::Impl::open_encoder_for_format() {
  const bool global_header = (format->oformat->flags & AVFMT_GLOBALHEADER) != 0;
  if (options.format != VideoFormat::mp4) {
    const bool gif = options.format == VideoFormat::gif;
    const AVCodec* candidate = gif ? avcodec_find_encoder(AV_CODEC_ID_GIF) : avcodec_find_encoder_by_name("libvpx-vp9");
    const std::string wanted = gif ? "GIF" : "VP9 (libvpx-vp9)";
    if (candidate == nullptr) throw Error::failure(options.setting, "no " + wanted + " encoder in this FFmpeg build");
    std::string why;
    encoder = open_encoder(*candidate, options, global_header, why);
    if (!encoder) throw Error::failure(options.setting, "the " + wanted + " encoder could not be opened (" + why + ")");
    encoder_name = candidate->name;
    return;
  }
  std::string failures;
  for (const AVCodec* candidate : candidate_encoders(options.codec)) {
    std::string why;
    encoder = open_encoder(*candidate, options, global_header, why);
    if (encoder) {
      encoder_name = candidate->name;
      codec = candidate->id == AV_CODEC_ID_H264 ? VideoCodec::h264 : VideoCodec::mpeg4;
      break;
    }
    failures += (failures.empty() ? "" : "; ") + std::string(candidate->name) + ": " + why;
  }
  if (!encoder) {
    const char* wanted = options.codec == VideoCodec::mpeg4 ? "MPEG-4" : "H.264";
    throw Error::failure(options.setting,
                         "no " + std::string(wanted) + " encoder could be opened" +
                             (failures.empty() ? " (none in this FFmpeg build)" : " (" + failures + ")"));
  }
  if (codec == VideoCodec::mpeg4 && options.codec == VideoCodec::automatic)
    note = "note: no H.264 encoder in this FFmpeg build" + (failures.empty() ? "" : " (" + failures + ")") +
           "; wrote MPEG-4 part 2, which video players show but some browsers do not";
}

void VideoWriter::Impl::open_palette_filter() {
  palette.reset(avfilter_graph_alloc());
  filtered.reset(av_frame_alloc());
  if (!palette || !filtered) throw Error::failure("cannot allocate the GIF palette filters (out of memory)");
  palette->nb_threads = 1;  // the same palettes on every machine
  const std::string args = "video_size=" + std::to_string(options.width) + "x" + std::to_string(options.height) +
                           ":pix_fmt=" + std::to_string(static_cast<int>(AV_PIX_FMT_RGB32)) + ":time_base=1/" +
                           std::to_string(options.fps) + ":pixel_aspect=1/1";
  av::check(
      avfilter_graph_create_filter(&source, avfilter_get_by_name("buffer"), "in", args.c_str(), nullptr, palette.get()),
      "cannot set up the GIF palette filters (buffer)");
  av::check(
      avfilter_graph_create_filter(&sink, avfilter_get_by_name("buffersink"), "out", nullptr, nullptr, palette.get()),
      "cannot set up the GIF palette filters (buffersink)");
  // graph_parse takes the ends it links: "in" feeds the chain, "out" ends it.
  InOutPtr outputs(avfilter_inout_alloc());
  InOutPtr inputs(avfilter_inout_alloc());
  if (!outputs || !inputs) throw Error::failure("cannot allocate the GIF palette filters (out of memory)");
  outputs->name = av_strdup("in");
  outputs->filter_ctx = source;
  inputs->name = av_strdup("out");
  inputs->filter_ctx = sink;
  AVFilterInOut* in_raw = inputs.release();
  AVFilterInOut* out_raw = outputs.release();
  const int parsed = avfilter_graph_parse_ptr(palette.get(), gif_filters, &in_raw, &out_raw, nullptr);
  inputs.reset(in_raw);
  outputs.reset(out_raw);
  av::check(parsed, "cannot set up the GIF palette filters (palettegen, paletteuse)");
  av::check(avfilter_graph_config(palette.get(), nullptr), "cannot set up the GIF palette filters");
}

void VideoWriter::Impl::convert(const Frame& frame) {
  if (frame.width != options.width || frame.height != options.height)
    throw Error::failure("frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         " given to a " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " video");
  // The encoder may still reference the previous picture's buffer; this copies only then.
  av::check(av_frame_make_writable(picture.get()), "cannot reuse the video frame");
  if (options.format == VideoFormat::gif) {
    const auto row_bytes = static_cast<std::size_t>(4 * frame.width);
    for (int y = 0; y < frame.height; ++y)
      std::memcpy(picture->data[0] + static_cast<std::ptrdiff_t>(y) * picture->linesize[0],
                  frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride, row_bytes);
    return;
  }
  const std::array<const std::uint8_t*, 1> pixels = {frame.pixels.data()};
  const std::array<int, 1> source_stride = {frame.stride};
  const int rows = sws_scale(converter.get(), pixels.data(), source_stride.data(), 0, frame.height, picture->data,
                             picture->linesize);
  if (rows != options.height)
    throw Error::failure("libswscale converted " + std::to_string(rows) + " rows, expected " +
                         std::to_string(options.height));
}

void VideoWriter::Impl::encode(const AVFrame* frame) {
  av::check(avcodec_send_frame(encoder.get(), frame), "cannot encode a frame");
  for (;;) {
    throw_if_interrupted();  // draining a slow encoder's delayed frames takes seconds
    const int status = avcodec_receive_packet(encoder.get(), packet.get());
    if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
    av::check(status, "cannot encode a frame");
    packet->stream_index = stream->index;
    if (packet->duration == 0) packet->duration = 1;  // one frame, in the encoder's 1/fps
    av_packet_rescale_ts(packet.get(), encoder->time_base, stream->time_base);
    ++stats.packets;
    av::check(av_interleaved_write_frame(format.get(), packet.get()), "cannot write to the video file");
  }
}

void VideoWriter::Impl::filter_and_encode(const AVFrame* frame) {
  // KEEP_REF: the filters take their own reference, so `picture` stays ours to reuse.
  av::check(av_buffersrc_add_frame_flags(source, const_cast<AVFrame*>(frame), AV_BUFFERSRC_FLAG_KEEP_REF),
            "cannot pass a frame to the GIF palette filters");
  for (;;) {
    const int status = av_buffersink_get_frame(sink, filtered.get());
    if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
    av::check(status, "cannot build a GIF palette");
    encode(filtered.get());
    av_frame_unref(filtered.get());
  }
}

VideoWriter::VideoWriter(const std::filesystem::path& target, const VideoOptions& options) {
  validate(options);
  impl_ = std::make_unique<Impl>(target, options);
  impl_->open();
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const Frame& frame) {
  Impl& impl = *impl_;
  if (impl.finished) throw Error::failure("VideoWriter::write() after finish()");
  auto start = Clock::now();
  impl.convert(frame);
  impl.stats.convert_seconds += seconds_since(start);
  start = Clock::now();
  impl.picture->pts = impl.stats.frames;  // frame k at k / fps
  if (impl.palette)
    impl.filter_and_encode(impl.picture.get());
  else
    impl.encode(impl.picture.get());
  impl.stats.encode_seconds += seconds_since(start);
  ++impl.stats.frames;
}

void VideoWriter::finish() {
  Impl& impl = *impl_;
  if (impl.finished) return;
  if (impl.stats.frames == 0) throw Error::failure(impl.options.setting, "no frames to write");
  auto start = Clock::now();
  if (impl.palette) impl.filter_and_encode(nullptr);  // the frames the filters still hold
  impl.encode(nullptr);                               // drain the frames the encoder delayed (B-frames, lookahead)
  impl.stats.encode_seconds += seconds_since(start);
  start = Clock::now();
  const std::string kind = name(impl.options.format);
  av::check(av_write_trailer(impl.format.get()), "cannot finish the " + kind + " file");  // MP4: moves moov first
  av::check(avio_closep(&impl.format->pb), "cannot close the " + kind + " file");
  std::error_code ec;
  impl.stats.bytes = static_cast<std::int64_t>(std::filesystem::file_size(impl.file.temp_path(), ec));
  throw_if_interrupted();  // a signal before the file is whole leaves no file
  impl.file.commit();
  impl.finished = true;
  impl.stats.finish_seconds += seconds_since(start);
}

const std::string& VideoWriter::encoder_name() const { return impl_->encoder_name; }
VideoCodec VideoWriter::codec() const { return impl_->codec; }
const std::string& VideoWriter::note() const { return impl_->note; }
const EncodeStats& VideoWriter::stats() const { return impl_->stats; }

void VideoWriter::validate(const VideoOptions& options) {
  const auto size = std::to_string(options.width) + "x" + std::to_string(options.height);
  const auto in_range = [](int v) { return v >= 2 && v <= max_dimension; };
  if (!in_range(options.width) || !in_range(options.height))
    throw Error::invalid(
        options.setting,
        "video size " + size + " is out of range; width and height must be from 2 to " + std::to_string(max_dimension));
  if (options.width % 2 != 0 || options.height % 2 != 0)
    throw Error::invalid(
        options.setting,
        "video size " + size + " must have an even width and height (yuv420p stores colour at half resolution)");
  if (options.fps < 1 || options.fps > 240)
    throw Error::invalid(options.setting, "frame rate " + std::to_string(options.fps) + " must be from 1 to 240");
  if (options.format == VideoFormat::gif && options.fps > gif_max_fps)
    throw Error::invalid(options.setting,
                         std::string("frame rate ") + std::to_string(options.fps) + " is too fast for a GIF: " +
                             "its delays are hundredths of a second and browsers slow shorter ones down, so a GIF " +
                             "takes 1 to " + std::to_string(gif_max_fps) +
                             " frames per second (or write .mp4 or .webm)");
  if (options.crf < 0 || options.crf > 51)
    throw Error::invalid(options.setting, "crf " + std::to_string(options.crf) + " must be from 0 to 51");
  if (!contains(x264_presets, options.preset))
    throw Error::invalid(options.setting,
                         "unknown x264 preset '" + options.preset + "'; valid: " + joined(x264_presets));
  if (!options.tune.empty() && !contains(x264_tunes, options.tune))
    throw Error::invalid(options.setting,
                         "unknown x264 tune '" + options.tune + "'; valid: " + joined(x264_tunes) + ", or empty");
  if (options.threads < 1 || options.threads > 64)
    throw Error::invalid(options.setting,
                         "encoder threads " + std::to_string(options.threads) + " must be from 1 to 64");
  if (options.keyframe_seconds < 1 || options.keyframe_seconds > 60)
    throw Error::invalid(options.setting,
                         "keyframe interval " + std::to_string(options.keyframe_seconds) + " s must be from 1 to 60");
}

const char* name(VideoFormat format) {
  return format == VideoFormat::gif ? "GIF" : format == VideoFormat::webm ? "WebM" : "MP4";
}

bool vp9_encoder_available() { return avcodec_find_encoder_by_name("libvpx-vp9") != nullptr; }

bool h264_encoder_available() {
  return avcodec_find_encoder_by_name("libx264") != nullptr || avcodec_find_encoder(AV_CODEC_ID_H264) != nullptr;
}

}  // namespace linkage
