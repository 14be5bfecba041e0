#include "encode/video_writer.hpp"

extern "C" {
#include <libavutil/opt.h>
#include <libavutil/pixfmt.h>
}

#include <algorithm>
#include <array>
#include <chrono>
#include <string_view>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
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
  if (name == "libx264") {
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
  context->pix_fmt = AV_PIX_FMT_YUV420P;
  context->time_base = AVRational{1, options.fps};
  context->framerate = AVRational{options.fps, 1};
  context->sample_aspect_ratio = AVRational{1, 1};
  context->gop_size = options.keyframe_seconds * options.fps;
  context->thread_count = options.threads;
  context->flags |= AV_CODEC_FLAG_BITEXACT;
  if (global_header) context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // What the converter produces, stated so players do not guess (HD players assume
  // BT.709, SD players BT.601 when untagged).
  context->color_range = AVCOL_RANGE_MPEG;
  context->colorspace = AVCOL_SPC_BT709;
  context->color_primaries = AVCOL_PRI_BT709;
  context->color_trc = AVCOL_TRC_BT709;
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
      throw Error::invalid(opts.setting, "an MP4 is finished by seeking back into the file, so '" + target.string() +
                                             "' must be a regular file (not standard output, a device or a pipe)");
  }

  VideoOptions options;
  AtomicFile file;  // declared before the AV objects: the file closes before the temp is removed
  av::OutputPtr format;
  av::CodecContextPtr encoder;
  AVStream* stream = nullptr;  // owned by `format`
  av::SwsPtr converter;
  av::FramePtr picture;
  av::PacketPtr packet;
  std::string encoder_name;
  std::string note;
  VideoCodec codec = VideoCodec::h264;
  EncodeStats stats;
  bool finished = false;

  void open();
  void convert(const Frame& frame);
  // Sends `frame` (nullptr flushes) and muxes every packet the encoder returns.
  void encode(const AVFrame* frame);
};

void VideoWriter::Impl::open() {
  av::install_quiet_log();
  const std::string temp = file.temp_path().string();
  AVFormatContext* raw_format = nullptr;
  av::check(avformat_alloc_output_context2(&raw_format, nullptr, "mp4", temp.c_str()), "cannot set up the MP4 muxer");
  format.reset(raw_format);
  format->flags |= AVFMT_FLAG_BITEXACT;  // no "Lavf" version string in the file

  std::string failures;
  for (const AVCodec* candidate : candidate_encoders(options.codec)) {
    std::string why;
    encoder = open_encoder(*candidate, options, (format->oformat->flags & AVFMT_GLOBALHEADER) != 0, why);
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

  stream = avformat_new_stream(format.get(), nullptr);
  if (stream == nullptr) throw Error::failure("cannot add a video stream (out of memory)");
  stream->time_base = encoder->time_base;
  stream->avg_frame_rate = encoder->framerate;
  av::check(avcodec_parameters_from_context(stream->codecpar, encoder.get()), "cannot copy the encoder parameters");

  converter.reset(sws_getContext(options.width, options.height, AV_PIX_FMT_RGB32, options.width, options.height,
                                 AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr,
                                 nullptr));
  if (!converter) throw Error::failure("cannot set up the BGRA -> yuv420p converter (libswscale)");
  // Full-range RGB in, BT.709 limited-range YUV out, matching the stream's tags.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  av::check(sws_setColorspaceDetails(converter.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16),
            "cannot select BT.709 colour conversion");

  picture.reset(av_frame_alloc());
  packet.reset(av_packet_alloc());
  if (!picture || !packet) throw Error::failure("cannot allocate a video frame (out of memory)");
  picture->format = AV_PIX_FMT_YUV420P;
  picture->width = options.width;
  picture->height = options.height;
  picture->color_range = AVCOL_RANGE_MPEG;
  picture->colorspace = AVCOL_SPC_BT709;
  av::check(av_frame_get_buffer(picture.get(), 0), "cannot allocate a video frame");

  av::check(avio_open(&format->pb, temp.c_str(), AVIO_FLAG_WRITE), "cannot create '" + temp + "'");
  AVDictionary* muxer_options = nullptr;
  av::check(av_dict_set(&muxer_options, "movflags", "+faststart", 0), "cannot set movflags");
  const int header = avformat_write_header(format.get(), &muxer_options);
  const bool unused = av_dict_count(muxer_options) > 0;
  av_dict_free(&muxer_options);
  av::check(header, "cannot write the MP4 header");
  if (unused) throw Error::failure("the MP4 muxer did not accept movflags=+faststart");
}

void VideoWriter::Impl::convert(const Frame& frame) {
  if (frame.width != options.width || frame.height != options.height)
    throw Error::failure("frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         " given to a " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " video");
  // The encoder may still reference the previous picture's buffer; this copies only then.
  av::check(av_frame_make_writable(picture.get()), "cannot reuse the video frame");
  const std::array<const std::uint8_t*, 1> source = {frame.pixels.data()};
  const std::array<int, 1> source_stride = {frame.stride};
  const int rows = sws_scale(converter.get(), source.data(), source_stride.data(), 0, frame.height, picture->data,
                             picture->linesize);
  if (rows != options.height)
    throw Error::failure("libswscale converted " + std::to_string(rows) + " rows, expected " +
                         std::to_string(options.height));
}

void VideoWriter::Impl::encode(const AVFrame* frame) {
  av::check(avcodec_send_frame(encoder.get(), frame), "cannot encode a frame");
  for (;;) {
    const int status = avcodec_receive_packet(encoder.get(), packet.get());
    if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
    av::check(status, "cannot encode a frame");
    packet->stream_index = stream->index;
    if (packet->duration == 0) packet->duration = 1;  // one frame, in the encoder's 1/fps
    av_packet_rescale_ts(packet.get(), encoder->time_base, stream->time_base);
    ++stats.packets;
    av::check(av_interleaved_write_frame(format.get(), packet.get()), "cannot write to the MP4 file");
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
  impl.encode(impl.picture.get());
  impl.stats.encode_seconds += seconds_since(start);
  ++impl.stats.frames;
}

void VideoWriter::finish() {
  Impl& impl = *impl_;
  if (impl.finished) return;
  if (impl.stats.frames == 0) throw Error::failure(impl.options.setting, "no frames to write");
  auto start = Clock::now();
  impl.encode(nullptr);  // drain the frames the encoder delayed (B-frames, lookahead)
  impl.stats.encode_seconds += seconds_since(start);
  start = Clock::now();
  av::check(av_write_trailer(impl.format.get()), "cannot finish the MP4 file");  // moves moov first
  av::check(avio_closep(&impl.format->pb), "cannot close the MP4 file");
  std::error_code ec;
  impl.stats.bytes = static_cast<std::int64_t>(std::filesystem::file_size(impl.file.temp_path(), ec));
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

bool h264_encoder_available() {
  return avcodec_find_encoder_by_name("libx264") != nullptr || avcodec_find_encoder(AV_CODEC_ID_H264) != nullptr;
}

}  // namespace linkage
