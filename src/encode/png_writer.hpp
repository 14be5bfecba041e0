#pragma once
// PNG files from Frames through libspng, tuned for speed: zlib level 1 and no row
// filter, 8-bit RGB (or RGBA with alpha un-premultiplied). Rendered frames are mostly
// flat colour, which deflate's fast matcher handles without filtering; on a 1280x720
// Cairo frame, filter "none" took 11 ms (39 KB), "sub" and "up" 21-26 ms (44 / 19 KB),
// Cairo's own writer 75 ms (9 KB). No dates or text chunks: identical frames give
// identical bytes.
//
// A numbered sequence (frame_00000.png, frame_00001.png, ...) is compressed by a small
// pool of worker threads. Its files are written into a hidden staging folder inside
// the destination and moved into place, each whole, by finish(); an error, Ctrl-C or
// destruction before finish() removes the staging folder, leaving earlier files of the
// same names untouched.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "core/frame.hpp"

namespace linkage {

struct PngOptions {
  bool alpha = false;         // RGBA (un-premultiplied) instead of RGB; rendered frames are opaque
  int compression_level = 1;  // zlib 0 (store) .. 9 (smallest, slowest)
};

/// Writes one frame to `target` atomically. Throws Error::input naming `origin` when
/// the folder does not exist or is not writable, Error::failure when encoding fails.
void write_png(const Frame& frame, const std::filesystem::path& target, const std::string& origin,
               const PngOptions& options = {});

/// Time spent by a PngSequenceWriter, summed over frames (and over workers).
struct PngStats {
  std::int64_t frames = 0;
  double convert_seconds = 0;  // premultiplied BGRA -> RGB(A) rows, on the caller's thread
  double encode_seconds = 0;   // compression and file writes, summed over workers
  double wait_seconds = 0;     // write() blocked because every worker was busy
};

class PngSequenceWriter {
 public:
  /// A sequence of width x height frames into `folder`, which must exist and be writable
  /// (Error::invalid about `origin`, e.g. "frames"). `threads` workers compress in
  /// parallel. `expected_frames` only widens the number in the names beyond 5 digits
  /// when needed (frame_000000.png for a million frames) so they sort.
  PngSequenceWriter(const std::filesystem::path& folder, int width, int height, const std::string& origin,
                    const PngOptions& options = {}, int threads = 2, std::int64_t expected_frames = 0);
  PngSequenceWriter(const PngSequenceWriter&) = delete;
  PngSequenceWriter& operator=(const PngSequenceWriter&) = delete;
  /// Without finish(): stops the workers and removes the staging folder.
  ~PngSequenceWriter();

  /// Converts `frame` now (it may be reused as soon as this returns) and queues it for
  /// compression as the next numbered file. Blocks while every worker is busy.
  /// Rethrows a worker's error; throws Error::interrupted() after Ctrl-C.
  void write(const Frame& frame);
  /// Waits for the workers and moves every file into the folder.
  void finish();

  /// The file name of frame `index` for this sequence, e.g. "frame_00042.png".
  [[nodiscard]] std::string file_name(std::int64_t index) const;
  [[nodiscard]] PngStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace linkage
