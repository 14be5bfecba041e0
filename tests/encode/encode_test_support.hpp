#pragma once
// Test helpers for the encoders: synthetic frames, an MP4 decoded back through
// libavformat/libavcodec (independent of the writer's code path), PNG decoding with
// libspng, and the MP4's top-level atoms.
#include <gtest/gtest.h>
#include <spng.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/frame.hpp"
#include "encode/av_support.hpp"

namespace linkage::test {

struct Rgb {
  int r = 0, g = 0, b = 0;
};

/// Paints an opaque w x h rectangle with top-left corner (x0, y0).
inline void rect(Frame& frame, int x0, int y0, int w, int h, Rgb colour) {
  const std::uint32_t word = 0xff000000U | static_cast<std::uint32_t>(colour.r) << 16 |
                             static_cast<std::uint32_t>(colour.g) << 8 | static_cast<std::uint32_t>(colour.b);
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x)
      std::memcpy(frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride + 4 * x, &word, 4);
}

inline constexpr Rgb background{32, 64, 192};
inline constexpr Rgb square_colour{240, 200, 40};
inline constexpr int square_side = 16;

/// Frame k of a test clip: a blue background with a yellow square moving right by 2
/// pixels a frame (even positions, so chroma blocks are not split).
inline void draw_test_frame(Frame& frame, int k) {
  rect(frame, 0, 0, frame.width, frame.height, background);
  rect(frame, (2 * k) % (frame.width - square_side), 8, square_side, square_side, square_colour);
}

/// Expects `call()` to throw linkage::Error with `code` and a message containing `text`.
template <typename Call>
void expect_error(Call call, ExitCode code, const std::string& text) {
  try {
    call();
    ADD_FAILURE() << "expected an error containing '" << text << "'";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), code) << error.what();
    EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
  }
}

/// An MP4 read back through libavformat and libavcodec.
struct DecodedVideo {
  std::string codec;  // decoder's codec name, e.g. "h264"
  AVPixelFormat pixel_format = AV_PIX_FMT_NONE;
  AVColorSpace colorspace = AVCOL_SPC_UNSPECIFIED;
  int width = 0, height = 0;
  AVRational frame_rate{0, 1};                 // stream's average frame rate
  double stream_duration = 0;                  // s, from the stream header
  double container_duration = 0;               // s, from the container
  std::vector<double> times;                   // s, presentation time of each decoded frame
  std::vector<std::vector<std::uint8_t>> rgb;  // each frame as packed RGB24 (BT.709 limited range in)
};

inline DecodedVideo decode_video(const std::filesystem::path& path) {
  av::install_quiet_log();
  AVFormatContext* raw = nullptr;
  av::check(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), "open " + path.string());
  const av::InputPtr input(raw);
  av::check(avformat_find_stream_info(input.get(), nullptr), "stream info");
  const AVCodec* codec = nullptr;
  const int index = av::check(av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0), "video stream");
  const AVStream* stream = input->streams[index];
  const av::CodecContextPtr decoder(avcodec_alloc_context3(codec));
  av::check(avcodec_parameters_to_context(decoder.get(), stream->codecpar), "decoder parameters");
  decoder->thread_count = 1;
  av::check(avcodec_open2(decoder.get(), codec, nullptr), "open decoder");

  DecodedVideo video;
  video.codec = codec->name;
  video.pixel_format = static_cast<AVPixelFormat>(stream->codecpar->format);
  video.colorspace = stream->codecpar->color_space;
  video.width = stream->codecpar->width;
  video.height = stream->codecpar->height;
  video.frame_rate = stream->avg_frame_rate;
  video.stream_duration = static_cast<double>(stream->duration) * av_q2d(stream->time_base);
  video.container_duration = static_cast<double>(input->duration) / AV_TIME_BASE;

  const av::PacketPtr packet(av_packet_alloc());
  const av::FramePtr frame(av_frame_alloc());
  av::SwsPtr to_rgb;
  auto receive_all = [&] {
    for (;;) {
      const int status = avcodec_receive_frame(decoder.get(), frame.get());
      if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
      av::check(status, "decode");
      video.times.push_back(static_cast<double>(frame->best_effort_timestamp) * av_q2d(stream->time_base));
      if (!to_rgb) {
        to_rgb.reset(sws_getContext(frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
                                    frame->width, frame->height, AV_PIX_FMT_RGB24, SWS_BILINEAR | SWS_ACCURATE_RND,
                                    nullptr, nullptr, nullptr));
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        av::check(sws_setColorspaceDetails(to_rgb.get(), bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16), "colorspace");
      }
      std::vector<std::uint8_t> rgb(static_cast<std::size_t>(3 * frame->width * frame->height));
      std::array<std::uint8_t*, 1> planes = {rgb.data()};
      const std::array<int, 1> strides = {3 * frame->width};
      sws_scale(to_rgb.get(), frame->data, frame->linesize, 0, frame->height, planes.data(), strides.data());
      video.rgb.push_back(std::move(rgb));
      av_frame_unref(frame.get());
    }
  };
  while (av_read_frame(input.get(), packet.get()) >= 0) {
    if (packet->stream_index == index) av::check(avcodec_send_packet(decoder.get(), packet.get()), "send packet");
    av_packet_unref(packet.get());
    receive_all();
  }
  av::check(avcodec_send_packet(decoder.get(), nullptr), "flush decoder");
  receive_all();
  return video;
}

/// The colour at (x, y) of a packed RGB24 image `width` pixels wide.
inline Rgb rgb_at(const std::vector<std::uint8_t>& rgb, int width, int x, int y) {
  const auto at = static_cast<std::size_t>(3 * (y * width + x));
  return {rgb[at], rgb[at + 1], rgb[at + 2]};
}

/// Names of the top-level boxes of an ISO media file, in file order ("ftyp", "moov", ...).
inline std::vector<std::string> top_level_atoms(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto be = [&](std::size_t at, int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value = value << 8 | bytes[at + static_cast<std::size_t>(i)];
    return value;
  };
  std::vector<std::string> atoms;
  std::size_t at = 0;
  while (at + 8 <= bytes.size()) {
    std::uint64_t size = be(at, 4);
    atoms.emplace_back(bytes.begin() + static_cast<std::ptrdiff_t>(at) + 4,
                       bytes.begin() + static_cast<std::ptrdiff_t>(at) + 8);
    if (size == 1) size = be(at + 8, 8);  // 64-bit size follows the type
    if (size == 0) break;                 // extends to the end of the file
    if (size < 8) throw std::runtime_error("malformed box size in " + path.string());
    at += static_cast<std::size_t>(size);
  }
  return atoms;
}

/// A PNG decoded by libspng.
struct DecodedPng {
  std::uint32_t width = 0, height = 0;
  std::uint8_t color_type = 0, bit_depth = 0;
  std::vector<std::uint8_t> rgba;  // 8-bit RGBA, however the file stores it
};

inline DecodedPng decode_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> context(spng_ctx_new(0), &spng_ctx_free);
  auto ok = [&](int status, const char* what) {
    if (status != 0)
      throw std::runtime_error(std::string(what) + ": " + spng_strerror(status) + " in " + path.string());
  };
  ok(spng_set_png_buffer(context.get(), bytes.data(), bytes.size()), "buffer");
  spng_ihdr header{};
  ok(spng_get_ihdr(context.get(), &header), "header");
  DecodedPng png;
  png.width = header.width;
  png.height = header.height;
  png.color_type = header.color_type;
  png.bit_depth = header.bit_depth;
  std::size_t size = 0;
  ok(spng_decoded_image_size(context.get(), SPNG_FMT_RGBA8, &size), "size");
  png.rgba.resize(size);
  ok(spng_decode_image(context.get(), png.rgba.data(), size, SPNG_FMT_RGBA8, 0), "decode");
  return png;
}

/// Names of the entries of a folder, sorted.
inline std::vector<std::string> entries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// The bytes of a file.
inline std::vector<char> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace linkage::test
