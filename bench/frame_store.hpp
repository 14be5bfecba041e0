#pragma once
// Drawn frames kept in memory, run-length coded, so a benchmark can feed an encoder the
// very frames a render drew without drawing them again. Rendered frames are mostly flat
// colour: a 1280x720 frame (3.7 MB raw) codes to a few hundred kB, so 300 frames at
// 1080p fit in well under the 2.5 GB they would take raw. Unpacking writes runs of
// identical 32-bit pixels, about as fast as a memset.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/frame.hpp"

namespace linkage::bench {

class FrameStore {
 public:
  /// Frames of width x height (4 bytes a pixel, stride 4 x width, as core::Frame makes them).
  FrameStore(int width, int height);

  /// Appends a copy of `frame` (Error::failure if its size differs).
  void add(const Frame& frame);
  /// Writes frame `index` into `frame` (same size), byte for byte as it was added.
  void unpack(std::size_t index, Frame& frame) const;

  [[nodiscard]] std::size_t size() const { return starts_.size(); }
  /// Bytes the coded frames take.
  [[nodiscard]] std::size_t bytes() const { return runs_.size() * sizeof(Run); }

 private:
  struct Run {
    std::uint32_t length;
    std::uint32_t pixel;  // native-endian word, as in the frame
  };
  int width_, height_;
  std::vector<Run> runs_;            // every frame's runs, one after another
  std::vector<std::size_t> starts_;  // index of each frame's first run
};

}  // namespace linkage::bench
