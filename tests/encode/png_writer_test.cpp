#include "encode/png_writer.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "encode/encode_test_support.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {
using test::expect_error;
using test::TempDir;

constexpr int width = 64, height = 48;

// An opaque frame where every pixel differs from its neighbours (so a wrong row,
// column or channel order shows), seeded by `k`.
Frame gradient_frame(int k) {
  Frame frame(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint32_t r = static_cast<std::uint32_t>(4 * x + k) & 0xffU;
      const std::uint32_t g = static_cast<std::uint32_t>(5 * y + 3 * k) & 0xffU;
      const std::uint32_t b = static_cast<std::uint32_t>(x * y + 7 * k) & 0xffU;
      const std::uint32_t word = 0xff000000U | r << 16 | g << 8 | b;
      std::memcpy(frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride + 4 * x, &word, 4);
    }
  return frame;
}

// Asserts that a decoded PNG holds exactly the frame's (opaque) pixels.
void expect_same_pixels(const test::DecodedPng& png, const Frame& frame) {
  ASSERT_EQ(png.width, static_cast<std::uint32_t>(frame.width));
  ASSERT_EQ(png.height, static_cast<std::uint32_t>(frame.height));
  int mismatches = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const std::uint32_t word = frame.pixel(x, y);
      const auto* rgba = png.rgba.data() + 4 * (static_cast<std::size_t>(y) * png.width + static_cast<std::size_t>(x));
      const bool same = rgba[0] == ((word >> 16) & 0xffU) && rgba[1] == ((word >> 8) & 0xffU) &&
                        rgba[2] == (word & 0xffU) && rgba[3] == (word >> 24);
      if (!same && ++mismatches <= 3) ADD_FAILURE() << "pixel (" << x << ", " << y << ") differs";
    }
  EXPECT_EQ(mismatches, 0);
}

TEST(PngWriter, StillRoundTripsExactlyAsRgb) {
  const TempDir dir;
  const Frame frame = gradient_frame(0);
  write_png(frame, dir / "still.png", "--out");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"still.png"});
  const test::DecodedPng png = test::decode_png(dir / "still.png");
  EXPECT_EQ(png.color_type, SPNG_COLOR_TYPE_TRUECOLOR);
  EXPECT_EQ(png.bit_depth, 8);
  expect_same_pixels(png, frame);
}

TEST(PngWriter, AlphaIsUnpremultiplied) {
  const TempDir dir;
  Frame frame(2, 1);
  // Cairo stores half-transparent (alpha 128) pure red as premultiplied red 128.
  const std::uint32_t half_red = 0x80800000U, clear = 0x00000000U;
  std::memcpy(frame.pixels.data(), &half_red, 4);
  std::memcpy(frame.pixels.data() + 4, &clear, 4);
  write_png(frame, dir / "alpha.png", "--out", PngOptions{.alpha = true});
  const test::DecodedPng png = test::decode_png(dir / "alpha.png");
  EXPECT_EQ(png.color_type, SPNG_COLOR_TYPE_TRUECOLOR_ALPHA);
  EXPECT_EQ(std::vector<int>(png.rgba.begin(), png.rgba.end()), (std::vector<int>{255, 0, 0, 128, 0, 0, 0, 0}));
}

TEST(PngWriter, IdenticalFramesGiveIdenticalBytes) {
  const TempDir dir;
  write_png(gradient_frame(3), dir / "a.png", "--out");
  write_png(gradient_frame(3), dir / "b.png", "--out");
  EXPECT_TRUE(test::file_bytes(dir / "a.png") == test::file_bytes(dir / "b.png"));
  write_png(gradient_frame(4), dir / "c.png", "--out");
  EXPECT_FALSE(test::file_bytes(dir / "a.png") == test::file_bytes(dir / "c.png"));
}

TEST(PngWriter, StillIntoMissingFolderIsAClearInputError) {
  const TempDir dir;
  expect_error([&] { write_png(gradient_frame(0), dir / "nowhere" / "still.png", "--out"); }, ExitCode::bad_input,
               "--out: folder '" + (dir / "nowhere").string() + "' does not exist");
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngSequenceWriter, WritesExactlyTheNumberedFramesInParallel) {
  const TempDir dir;
  constexpr int frames = 25;
  {
    PngSequenceWriter writer(dir.path(), width, height, "--frames", {}, 2);
    Frame frame(width, height);  // one buffer reused for every frame, as a renderer does
    for (int k = 0; k < frames; ++k) {
      frame = gradient_frame(k);
      writer.write(frame);
    }
    writer.finish();
    EXPECT_EQ(writer.stats().frames, frames);
    EXPECT_GT(writer.stats().encode_seconds, 0.0);
  }
  std::vector<std::string> expected;
  for (int k = 0; k < frames; ++k)
    expected.push_back("frame_000" + std::string(k < 10 ? "0" : "") + std::to_string(k) + ".png");
  EXPECT_EQ(dir.entries(), expected);
  for (int k : {0, 1, 12, frames - 1})
    expect_same_pixels(test::decode_png(dir / expected[static_cast<std::size_t>(k)]), gradient_frame(k));
}

TEST(PngSequenceWriter, SequenceFilesMatchTheStillWriterByteForByte) {
  const TempDir dir;
  std::filesystem::create_directory(dir / "seq");
  PngSequenceWriter writer(dir / "seq", width, height, "--frames");
  writer.write(gradient_frame(7));
  writer.finish();
  write_png(gradient_frame(7), dir / "still.png", "--out");
  EXPECT_TRUE(test::file_bytes(dir / "seq" / "frame_00000.png") == test::file_bytes(dir / "still.png"));
}

TEST(PngSequenceWriter, NamesWidenOnlyWhenFramesWouldNotSort) {
  const TempDir dir;
  EXPECT_EQ(PngSequenceWriter(dir.path(), 2, 2, "--frames").file_name(42), "frame_00042.png");
  EXPECT_EQ(PngSequenceWriter(dir.path(), 2, 2, "--frames", {}, 1, 100000).file_name(42), "frame_00042.png");
  EXPECT_EQ(PngSequenceWriter(dir.path(), 2, 2, "--frames", {}, 1, 100001).file_name(42), "frame_000042.png");
  EXPECT_TRUE(dir.entries().empty());  // unfinished empty sequences leave nothing
}

TEST(PngSequenceWriter, DestructionWithoutFinishLeavesEarlierFramesUntouched) {
  const TempDir dir;
  test::write_text(dir / "frame_00000.png", "earlier frame");
  {
    PngSequenceWriter writer(dir.path(), width, height, "--frames");
    for (int k = 0; k < 6; ++k) writer.write(gradient_frame(k));
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame_00000.png"});
  EXPECT_EQ(test::read_text(dir / "frame_00000.png"), "earlier frame");
}

TEST(PngSequenceWriter, MissingFolderOrWrongFrameSizeIsReported) {
  const TempDir dir;
  expect_error([&] { PngSequenceWriter writer(dir / "frames", width, height, "--frames"); }, ExitCode::bad_input,
               "--frames: folder '" + (dir / "frames").string() + "' does not exist");
  test::write_text(dir / "file", "");
  expect_error([&] { PngSequenceWriter writer(dir / "file", width, height, "--frames"); }, ExitCode::bad_input,
               "is not a folder");
  {
    PngSequenceWriter writer(dir.path(), width, height, "--frames");
    expect_error([&] { writer.write(Frame(width, height + 2)); }, ExitCode::failure,
                 "frame of 64x50 given to a 64x48 PNG sequence");
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});
}

TEST(PngSequenceWriter, WorkerFailureReachesTheCaller) {
  const TempDir dir;
  PngSequenceWriter writer(dir.path(), width, height, "--frames");
  writer.write(gradient_frame(0));
  // Remove the staging folder under the workers' feet: the next files cannot be created.
  while (!dir.entries().empty()) {
    std::error_code ec;  // a worker may still be adding frame 0: retry until the folder is gone
    for (const auto& name : dir.entries()) std::filesystem::remove_all(dir / name, ec);
  }
  expect_error(
      [&] {
        for (int k = 1; k < 50; ++k) writer.write(gradient_frame(k));
        writer.finish();
      },
      ExitCode::failure, "cannot create");
}

// --- write failures: the system's reason, the file the user named ------------------------

/// Files of this process may not grow past `bytes` while it lives: writes beyond fail
/// with EFBIG ("File too large") the way a full disk fails them with ENOSPC, without a
/// full disk (and SIGXFSZ, which would end the process, is ignored meanwhile).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) : old_handler_(std::signal(SIGXFSZ, SIG_IGN)) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit saved_{};
  void (*old_handler_)(int);
};

/// A frame of noise: its PNG (~ 200 KB) overflows any stdio buffer, so the write fails in
/// libspng's own write, not only at the final flush.
Frame noise_frame(int w, int h) {
  Frame frame(w, h);
  std::uint32_t state = 12345;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      state = state * 1664525U + 1013904223U;
      const std::uint32_t word = 0xff000000U | (state >> 8);
      std::memcpy(frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride + 4 * x, &word, 4);
    }
  return frame;
}

// A failed write says why in the system's words and names the file asked for: not
// libspng's "stream error", not the temporary it was written to. And leaves nothing.
TEST(PngWriter, AFailedWriteGivesTheSystemsReasonAndTheTarget) {
  const TempDir dir;
  const std::string reason = std::strerror(EFBIG);
  struct Case {
    Frame frame;
    rlim_t limit;
  };
  // ~200 KB: fails inside libspng's writes; ~70 bytes: buffered, fails at the final flush
  for (const Case& c : {Case{noise_frame(256, 256), 1000}, Case{Frame(16, 16), 32}}) {
    std::string message;
    {
      const FileSizeLimit limit(c.limit);
      try {
        write_png(c.frame, dir / "still.png", "out");
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::failure);
        message = e.what();
      }
    }
    EXPECT_EQ(message, "cannot write '" + (dir / "still.png").string() + "': " + reason);
    EXPECT_TRUE(dir.entries().empty()) << "no file, no temporary";
  }
}

// A full disk, through a link to /dev/full (written directly: it is a device, and is
// left as it was): "No space left on device", naming the link given.
TEST(PngWriter, AFullDiskSaysSo) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const TempDir dir;
  std::filesystem::create_symlink("/dev/full", dir / "full.png");
  expect_error([&] { write_png(noise_frame(256, 256), dir / "full.png", "out"); }, ExitCode::failure,
               "cannot write '" + (dir / "full.png").string() + "': " + std::strerror(ENOSPC));
  expect_error([&] { write_png(gradient_frame(0), dir / "full.png", "out"); }, ExitCode::failure,
               "cannot write '" + (dir / "full.png").string() + "': " + std::strerror(ENOSPC));
}

// A numbered frame that cannot be written is named as it would have been in the folder,
// not in the hidden staging folder.
TEST(PngSequenceWriter, AFailedWriteNamesTheFrameInTheFolder) {
  const TempDir dir;
  std::string message;
  {
    const FileSizeLimit limit(1000);
    try {
      PngSequenceWriter writer(dir.path(), 256, 256, "frames");
      writer.write(noise_frame(256, 256));
      writer.finish();
    } catch (const Error& e) {
      message = e.what();
    }
  }
  EXPECT_EQ(message, "cannot write '" + (dir / "frame_00000.png").string() + "': " + std::strerror(EFBIG));
  EXPECT_TRUE(dir.entries().empty()) << "the staging folder is gone";
}

}  // namespace
}  // namespace linkage
