// GIF and WebM (VP9) from VideoWriter, read back through libavformat/libavcodec: every
// frame decoded and compared with the frame that was drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "encode/encode_test_support.hpp"
#include "encode/video_writer.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {
using test::expect_error;
using test::TempDir;

constexpr int width = 64, height = 48, fps = 25, frame_count = 30;  // 1.2 s

// Frame k: a two-way gradient (3072 colours, more than a GIF palette holds) with a
// yellow square moving right by 2 pixels a frame.
test::Rgb source_colour(int k, int x, int y) {
  const int square_x = (2 * k) % (width - test::square_side);
  if (x >= square_x && x < square_x + test::square_side && y >= 8 && y < 8 + test::square_side)
    return test::square_colour;
  return {4 * x, 5 * y, 255 - 2 * x - y};
}

void draw_frame(Frame& frame, int k) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) test::rect(frame, x, y, 1, 1, source_colour(k, x, y));
}

VideoOptions options_for(VideoFormat format) {
  VideoOptions options;
  options.format = format;
  options.width = width;
  options.height = height;
  options.fps = fps;
  return options;
}

void write_clip(const std::filesystem::path& target, VideoFormat format) {
  VideoWriter writer(target, options_for(format));
  Frame frame(width, height);
  for (int k = 0; k < frame_count; ++k) {
    draw_frame(frame, k);
    writer.write(frame);
  }
  writer.finish();
  EXPECT_EQ(writer.stats().frames, frame_count);
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Error8 {
  double worst_block = 0;  // largest |mean difference| of one channel over an 8x8 block
  int worst_pixel = 0;     // largest |difference| of one channel at one pixel
};

// Within a pixel of the square's outline, where 4:2:0 chroma (interpolated when the
// test converts back to RGB) mixes the square's colour with the gradient's.
bool on_square_edge(int k, int x, int y) {
  const int x0 = (2 * k) % (width - test::square_side), x1 = x0 + test::square_side, y0 = 8, y1 = 8 + test::square_side;
  const bool near_x = x >= x0 - 1 && x <= x1, near_y = y >= y0 - 1 && y <= y1;
  return (near_x && (std::abs(y - y0) <= 1 || std::abs(y - y1) <= 1)) ||
         (near_y && (std::abs(x - x0) <= 1 || std::abs(x - x1) <= 1));
}

// Decoded frame k against the drawn one. 8x8 blocks average out dithering (the Bayer
// matrix repeats every 8 pixels) and block-transform coding noise.
Error8 compare(const std::vector<std::uint8_t>& rgb, int k, bool skip_square_edges) {
  Error8 e;
  for (int by = 0; by < height; by += 8)
    for (int bx = 0; bx < width; bx += 8) {
      double sum[3] = {0, 0, 0};
      int n = 0;
      for (int y = by; y < by + 8; ++y)
        for (int x = bx; x < bx + 8; ++x) {
          if (skip_square_edges && on_square_edge(k, x, y)) continue;
          ++n;
          const test::Rgb got = test::rgb_at(rgb, width, x, y);
          const test::Rgb want = source_colour(k, x, y);
          const int d[3] = {got.r - want.r, got.g - want.g, got.b - want.b};
          for (int c = 0; c < 3; ++c) {
            sum[c] += d[c];
            e.worst_pixel = std::max(e.worst_pixel, std::abs(d[c]));
          }
        }
      for (const double s : sum) e.worst_block = std::max(e.worst_block, std::fabs(s / std::max(n, 1)));
    }
  return e;
}

TEST(VideoFormats, GifDecodesFrameForFrameWithItsPaletteCloseToTheDrawing) {
  const TempDir dir;
  write_clip(dir / "clip.gif", VideoFormat::gif);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.gif"});
  EXPECT_EQ(bytes_of(dir / "clip.gif").substr(0, 6), "GIF89a");

  const test::DecodedVideo video = test::decode_video(dir / "clip.gif");
  EXPECT_EQ(video.codec, "gif");
  EXPECT_EQ(video.width, width);
  EXPECT_EQ(video.height, height);
  ASSERT_EQ(video.rgb.size(), static_cast<std::size_t>(frame_count));
  // GIF delays are hundredths of a second: 1/25 s is exactly 4.
  for (std::size_t k = 0; k < video.times.size(); ++k)
    EXPECT_NEAR(video.times[k], static_cast<double>(k) / fps, 1e-9) << "frame " << k;
  for (int k = 0; k < frame_count; ++k) {
    const Error8 e = compare(video.rgb[static_cast<std::size_t>(k)], k, false);
    // 256 colours for a 3072-colour gradient: a pixel is off by about a palette step,
    // a block's average by little (a 3-3-2 fixed palette would be off by ~16).
    EXPECT_LT(e.worst_block, 4.0) << "frame " << k;
    EXPECT_LT(e.worst_pixel, 40) << "frame " << k;
    // The moving square is exact: its colour is in every frame's palette.
    const int centre_x = (2 * k) % (width - test::square_side) + test::square_side / 2;
    const test::Rgb square = test::rgb_at(video.rgb[static_cast<std::size_t>(k)], width, centre_x, 16);
    EXPECT_EQ(square.r, test::square_colour.r) << "frame " << k;
    EXPECT_EQ(square.g, test::square_colour.g) << "frame " << k;
    EXPECT_EQ(square.b, test::square_colour.b) << "frame " << k;
  }
}

TEST(VideoFormats, WebmIsVp9Yuv420pFrameForFrameCloseToTheDrawing) {
  ASSERT_TRUE(vp9_encoder_available());
  const TempDir dir;
  write_clip(dir / "clip.webm", VideoFormat::webm);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.webm"});
  const std::string bytes = bytes_of(dir / "clip.webm");
  EXPECT_EQ(bytes.substr(0, 4), std::string("\x1a\x45\xdf\xa3", 4));  // EBML (Matroska/WebM)

  const test::DecodedVideo video = test::decode_video(dir / "clip.webm");
  EXPECT_EQ(video.codec, "vp9");
  EXPECT_EQ(video.pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.colorspace, AVCOL_SPC_BT709);
  EXPECT_EQ(video.width, width);
  EXPECT_EQ(video.height, height);
  ASSERT_EQ(video.rgb.size(), static_cast<std::size_t>(frame_count));
  // WebM times are milliseconds.
  for (std::size_t k = 0; k < video.times.size(); ++k)
    EXPECT_NEAR(video.times[k], static_cast<double>(k) / fps, 1e-3) << "frame " << k;
  for (int k = 0; k < frame_count; ++k) {
    // Limited-range 4:2:0 and VP9's quantisation at constant quality, on a tiny frame
    // full of colour and motion (measured: up to 12 levels a block, 45 a pixel); a
    // frame from another time would be off by ~200 where the square moved, swapped
    // channels by ~100 across the gradient.
    const Error8 e = compare(video.rgb[static_cast<std::size_t>(k)], k, true);
    EXPECT_LT(e.worst_block, 16.0) << "frame " << k;
    EXPECT_LT(e.worst_pixel, 64) << "frame " << k;
  }
}

TEST(VideoFormats, SameFramesGiveIdenticalBytes) {
  const TempDir dir;
  for (const auto& [format, a, b] :
       {std::tuple{VideoFormat::gif, "a.gif", "b.gif"}, std::tuple{VideoFormat::webm, "a.webm", "b.webm"}}) {
    write_clip(dir / a, format);
    write_clip(dir / b, format);
    EXPECT_EQ(bytes_of(dir / a), bytes_of(dir / b)) << name(format);
  }
}

TEST(VideoFormats, GifAbove50FramesPerSecondIsRefusedBeforeAnythingIsCreated) {
  const TempDir dir;
  VideoOptions options = options_for(VideoFormat::gif);
  options.fps = 50;
  VideoWriter::validate(options);
  options.fps = 60;
  expect_error([&] { VideoWriter writer(dir / "clip.gif", options); }, ExitCode::bad_input,
               "frame rate 60 is too fast for a GIF");
  EXPECT_TRUE(dir.entries().empty());
  options.format = VideoFormat::webm;
  VideoWriter::validate(options);  // WebM (and MP4) take 60
}

TEST(VideoFormats, DestructionWithoutFinishLeavesNothing) {
  const TempDir dir;
  for (const VideoFormat format : {VideoFormat::gif, VideoFormat::webm}) {
    VideoWriter writer(dir / (format == VideoFormat::gif ? "clip.gif" : "clip.webm"), options_for(format));
    Frame frame(width, height);
    draw_frame(frame, 0);
    writer.write(frame);
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace linkage
