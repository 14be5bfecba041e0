#pragma once
// A video file from Frames, in-process through the FFmpeg libraries, in one of three
// formats. MP4: libswscale turns Cairo's premultiplied B,G,R,A pixels (opaque) into
// yuv420p (BT.709, limited range), libavcodec encodes H.264 (libx264, or another H.264
// encoder, or MPEG-4 part 2 as a last resort) and libavformat writes an MP4 with the
// index (moov) before the media (mdat), so a browser starts playing before the whole
// file has arrived. WebM: the same yuv420p encoded VP9 (libvpx-vp9, constant quality).
// GIF: libavfilter's palettegen/paletteuse give each frame its own 256-colour palette
// (ordered dithering, so still areas do not shimmer), encoded by FFmpeg's GIF encoder,
// looping forever. Frames should be opaque: alpha is ignored, so a translucent pixel
// shows its colour over black.
//
// Frame k is shown at k / fps seconds for 1 / fps seconds; n frames last exactly
// n / fps seconds. The same frames give byte-identical files: fixed encoder thread
// count and bit-exact muxer/encoder metadata (no version strings or dates).
//
// The file is written to a temporary name beside the target and renamed by finish();
// an error, Ctrl-C or destruction before finish() removes it and leaves an earlier
// file at the target untouched.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "core/frame.hpp"

namespace linkage {

enum class VideoCodec {
  automatic,  // H.264 if any encoder for it opens, else MPEG-4 part 2 with a note
  h264,       // H.264 only; Error::failure if no encoder opens
  mpeg4       // MPEG-4 part 2 (plays in video players, not in every browser)
};

enum class VideoFormat { mp4, gif, webm };

/// "MP4", "GIF" or "WebM".
[[nodiscard]] const char* name(VideoFormat format);

struct VideoOptions {
  VideoFormat format = VideoFormat::mp4;
  int width = 1280;                // even, 2 .. 8192 (yuv420p halves the chroma resolution)
  int height = 720;                // even, 2 .. 8192
  int fps = 30;                    // 1 .. 240
  int crf = 20;                    // x264 constant rate factor, 0 (lossless) .. 51; ~18-23 looks clean
  std::string preset = "medium";   // x264 speed/size trade-off: ultrafast .. veryslow
  std::string tune = "animation";  // x264 tuning for flat colours and sharp edges; "" for none
  int threads = 2;                 // encoder threads; fixed (not "auto") so output is the same on every machine
  int keyframe_seconds = 2;        // a keyframe at least this often, for seeking in a player
  VideoCodec codec = VideoCodec::automatic;  // MP4 only
  std::string setting = "out";               // the setting errors are about
};

/// Time spent per stage, summed over the frames written so far.
struct EncodeStats {
  std::int64_t frames = 0;     // frames passed to write()
  std::int64_t packets = 0;    // compressed packets muxed
  std::int64_t bytes = 0;      // size of the finished file
  double convert_seconds = 0;  // libswscale: BGRA -> yuv420p (GIF: libavfilter's palette)
  double encode_seconds = 0;   // libavcodec + libavformat, including the final flush
  double finish_seconds = 0;   // trailer, faststart rewrite, rename
};

class VideoWriter {
 public:
  /// Validates the options (Error::invalid about `options.setting` and the range), checks
  /// that the target's folder exists and is writable (Error::input), then opens the
  /// encoder and the temporary file (Error::failure with FFmpeg's message). Nothing is
  /// left on disk when this throws.
  VideoWriter(const std::filesystem::path& target, const VideoOptions& options);
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  /// Without finish(): removes the temporary file.
  ~VideoWriter();

  /// Encodes the next frame (width x height as in the options; Error::failure otherwise).
  /// Not thread-safe: call from one thread at a time (e.g. a FramePipeline consumer).
  void write(const Frame& frame);
  /// Flushes the encoder's delayed frames, writes the index first (faststart), closes
  /// and renames the file over the target. At least one frame must have been written.
  void finish();

  /// The encoder in use, e.g. "libx264", "mpeg4", "libvpx-vp9" or "gif".
  [[nodiscard]] const std::string& encoder_name() const;
  /// The MP4's codec actually used: h264 or mpeg4.
  [[nodiscard]] VideoCodec codec() const;
  /// Empty, or a one-line note for the user (e.g. the MPEG-4 fallback and why).
  [[nodiscard]] const std::string& note() const;
  [[nodiscard]] const EncodeStats& stats() const;

  /// Throws Error::input (naming `origin`) unless the options are valid; the constructor
  /// calls this first. Exposed so a command can validate before any work starts.
  static void validate(const VideoOptions& options);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// True when an H.264 encoder (libx264 or another) is available in this FFmpeg build.
[[nodiscard]] bool h264_encoder_available();
/// True when libvpx-vp9 (the WebM encoder) is available in this FFmpeg build.
[[nodiscard]] bool vp9_encoder_available();

}  // namespace linkage
