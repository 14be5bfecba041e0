#pragma once
// Helpers for the render tests: PNG files through libspng and pixel colours.
#include <spng.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "render/theme.hpp"

namespace linkage::test {

/// 8-bit colour of a frame pixel (frames are opaque, so premultiplication is moot).
struct Rgb8 {
  int r = 0, g = 0, b = 0;
};
inline Rgb8 rgb_at(const Frame& frame, int x, int y) {
  const std::uint32_t v = frame.pixel(x, y);
  return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff)};
}
inline Rgb8 rgb8(const Rgba& c) {
  return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255))};
}
/// Largest channel difference.
inline int colour_distance(const Rgb8& a, const Rgb8& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

/// Writes a frame as 8-bit RGB PNG (for goldens and for looking at test output).
inline void write_png_file(const Frame& frame, const std::filesystem::path& path) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(3 * frame.width * frame.height));
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const Rgb8 c = rgb_at(frame, x, y);
      const auto at = static_cast<std::size_t>(3 * (y * frame.width + x));
      rgb[at] = static_cast<std::uint8_t>(c.r);
      rgb[at + 1] = static_cast<std::uint8_t>(c.g);
      rgb[at + 2] = static_cast<std::uint8_t>(c.b);
    }
  const std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> context(spng_ctx_new(SPNG_CTX_ENCODER), &spng_ctx_free);
  spng_set_option(context.get(), SPNG_ENCODE_TO_BUFFER, 1);
  spng_ihdr header{};
  header.width = static_cast<std::uint32_t>(frame.width);
  header.height = static_cast<std::uint32_t>(frame.height);
  header.bit_depth = 8;
  header.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  spng_set_ihdr(context.get(), &header);
  if (spng_encode_image(context.get(), rgb.data(), rgb.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE) != 0)
    throw std::runtime_error("cannot encode " + path.string());
  int error = 0;
  std::size_t size = 0;
  void* png = spng_get_png_buffer(context.get(), &size, &error);
  if (png == nullptr) throw std::runtime_error("cannot encode " + path.string());
  std::ofstream(path, std::ios::binary).write(static_cast<const char*>(png), static_cast<std::streamsize>(size));
  std::free(png);
}

/// Reads an 8-bit PNG into an opaque frame.
inline Frame read_png_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> context(spng_ctx_new(0), &spng_ctx_free);
  spng_set_png_buffer(context.get(), bytes.data(), bytes.size());
  spng_ihdr header{};
  if (spng_get_ihdr(context.get(), &header) != 0) throw std::runtime_error("not a PNG: " + path.string());
  std::vector<std::uint8_t> rgba(4ull * header.width * header.height);
  if (spng_decode_image(context.get(), rgba.data(), rgba.size(), SPNG_FMT_RGBA8, 0) != 0)
    throw std::runtime_error("cannot decode " + path.string());
  Frame frame(static_cast<int>(header.width), static_cast<int>(header.height));
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    frame.pixels[i] = rgba[i + 2];
    frame.pixels[i + 1] = rgba[i + 1];
    frame.pixels[i + 2] = rgba[i];
    frame.pixels[i + 3] = rgba[i + 3];
  }
  return frame;
}

/// Where a test may leave pictures to look at: $LINKAGE_RENDER_OUT, if set.
inline std::filesystem::path picture_folder() {
  const char* folder = std::getenv("LINKAGE_RENDER_OUT");
  return folder == nullptr ? std::filesystem::path() : std::filesystem::path(folder);
}

}  // namespace linkage::test
