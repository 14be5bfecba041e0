#include "bench/frame_store.hpp"

#include <cstring>
#include <string>

#include "core/error.hpp"

namespace linkage::bench {
namespace {

void require_size(const Frame& frame, int width, int height) {
  if (frame.width != width || frame.height != height || frame.stride != 4 * width)
    throw Error::failure("frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         " given to a frame store of " + std::to_string(width) + "x" + std::to_string(height));
}

}  // namespace

FrameStore::FrameStore(int width, int height) : width_(width), height_(height) {}

void FrameStore::add(const Frame& frame) {
  require_size(frame, width_, height_);
  starts_.push_back(runs_.size());
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  const std::uint8_t* in = frame.pixels.data();
  Run run{0, 0};
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint32_t word = 0;
    std::memcpy(&word, in + 4 * i, sizeof word);
    if (run.length > 0 && word == run.pixel) {
      ++run.length;
      continue;
    }
    if (run.length > 0) runs_.push_back(run);
    run = {1, word};
  }
  if (run.length > 0) runs_.push_back(run);
}

void FrameStore::unpack(std::size_t index, Frame& frame) const {
  require_size(frame, width_, height_);
  if (index >= starts_.size())
    throw Error::failure("frame " + std::to_string(index) + " is not in the store of " + std::to_string(size()));
  const std::size_t end = index + 1 < starts_.size() ? starts_[index + 1] : runs_.size();
  std::uint8_t* out = frame.pixels.data();
  for (std::size_t r = starts_[index]; r < end; ++r) {
    const Run run = runs_[r];
    for (std::uint32_t i = 0; i < run.length; ++i, out += 4) std::memcpy(out, &run.pixel, sizeof run.pixel);
  }
}

}  // namespace linkage::bench
