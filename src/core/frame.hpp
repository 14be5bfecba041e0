#pragma once
// A frame of pixels as Cairo draws it and the encoders read it: CAIRO_FORMAT_RGB24 /
// ARGB32 layout, 4 bytes a pixel, native-endian 0xAARRGGBB words (B, G, R, A in memory
// on x86). Allocated once per run and reused for every frame.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace linkage {

struct Frame {
  int width = 0;
  int height = 0;
  int stride = 0;  // bytes per row, >= 4 * width
  std::vector<std::uint8_t> pixels;

  Frame() = default;
  Frame(int w, int h)
      : width(w), height(h), stride(4 * w), pixels(static_cast<std::size_t>(4 * w) * static_cast<std::size_t>(h)) {}

  [[nodiscard]] std::uint32_t pixel(int x, int y) const {
    const auto* row = pixels.data() + static_cast<std::ptrdiff_t>(y) * stride;
    std::uint32_t value = 0;
    for (int byte = 3; byte >= 0; --byte) value = (value << 8) | row[4 * x + byte];
    return value;
  }
};

}  // namespace linkage
