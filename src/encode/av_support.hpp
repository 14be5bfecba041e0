#pragma once
// Small helpers for the FFmpeg C API: owning pointers for its objects, and return
// codes turned into linkage::Error with FFmpeg's own words (av_strerror) plus the last
// error the library logged.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libswscale/swscale.h>
}

#include <memory>
#include <string>
#include <string_view>

namespace linkage::av {

struct CodecContextDeleter {
  void operator()(AVCodecContext* p) const { avcodec_free_context(&p); }
};
struct FrameDeleter {
  void operator()(AVFrame* p) const { av_frame_free(&p); }
};
struct PacketDeleter {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct SwsDeleter {
  void operator()(SwsContext* p) const { sws_freeContext(p); }
};
/// An output context: closes its file (if open) and frees it.
struct OutputDeleter {
  void operator()(AVFormatContext* p) const;
};
/// An input context from avformat_open_input.
struct InputDeleter {
  void operator()(AVFormatContext* p) const { avformat_close_input(&p); }
};

using CodecContextPtr = std::unique_ptr<AVCodecContext, CodecContextDeleter>;
using FramePtr = std::unique_ptr<AVFrame, FrameDeleter>;
using PacketPtr = std::unique_ptr<AVPacket, PacketDeleter>;
using SwsPtr = std::unique_ptr<SwsContext, SwsDeleter>;
using OutputPtr = std::unique_ptr<AVFormatContext, OutputDeleter>;
using InputPtr = std::unique_ptr<AVFormatContext, InputDeleter>;

/// FFmpeg's text for an error code, e.g. "Invalid argument".
[[nodiscard]] std::string error_text(int code);

/// Routes FFmpeg's log to a quiet handler that keeps the last error line (per thread)
/// for error messages instead of printing encoder chatter on stderr. Idempotent.
void install_quiet_log();
/// The last error FFmpeg logged on this thread ("" if none), then forgets it.
[[nodiscard]] std::string take_logged_error();

/// Returns `code` when it is not negative; otherwise throws Error::failure
/// "<what>: <av_strerror text> (<logged error>)".
int check(int code, std::string_view what);

}  // namespace linkage::av
