#include "encode/video_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "encode/encode_test_support.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {
using test::expect_error;
using test::TempDir;

constexpr int width = 64, height = 48, fps = 24, frame_count = 36;  // 1.5 s

VideoOptions small_options() {
  VideoOptions options;
  options.width = width;
  options.height = height;
  options.fps = fps;
  return options;
}

// Writes the test clip and returns the writer's stats.
EncodeStats write_clip(const std::filesystem::path& target, const VideoOptions& options = small_options()) {
  VideoWriter writer(target, options);
  Frame frame(options.width, options.height);
  for (int k = 0; k < frame_count; ++k) {
    test::draw_test_frame(frame, k);
    writer.write(frame);
  }
  writer.finish();
  return writer.stats();
}

TEST(VideoWriter, DecodesBackAsH264Yuv420pWithExactFrameCountAndDuration) {
  ASSERT_TRUE(h264_encoder_available());
  const TempDir dir;
  write_clip(dir / "clip.mp4");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});

  const test::DecodedVideo video = test::decode_video(dir / "clip.mp4");
  EXPECT_EQ(video.codec, "h264");
  EXPECT_EQ(video.pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.colorspace, AVCOL_SPC_BT709);
  EXPECT_EQ(video.width, width);
  EXPECT_EQ(video.height, height);
  EXPECT_EQ(video.frame_rate.num, fps);
  EXPECT_EQ(video.frame_rate.den, 1);
  ASSERT_EQ(video.times.size(), static_cast<std::size_t>(frame_count));
  const double duration = static_cast<double>(frame_count) / fps;
  EXPECT_NEAR(video.stream_duration, duration, 1e-9);
  EXPECT_NEAR(video.container_duration, duration, 1e-6);  // AV_TIME_BASE is microseconds
  // Frame k is presented at k / fps (the MP4 time scale is a multiple of fps).
  for (std::size_t k = 0; k < video.times.size(); ++k)
    EXPECT_NEAR(video.times[k], static_cast<double>(k) / fps, 1e-9) << "frame " << k;
}

TEST(VideoWriter, DecodedColoursMatchDrawnColours) {
  const TempDir dir;
  write_clip(dir / "clip.mp4");
  const test::DecodedVideo video = test::decode_video(dir / "clip.mp4");
  ASSERT_EQ(video.rgb.size(), static_cast<std::size_t>(frame_count));
  // 8-bit limited-range YUV and the encoder's quantisation move flat colours by a few levels.
  constexpr int tolerance = 6;
  auto expect_close = [&](test::Rgb got, test::Rgb want, int k, const char* where) {
    EXPECT_NEAR(got.r, want.r, tolerance) << where << " of frame " << k;
    EXPECT_NEAR(got.g, want.g, tolerance) << where << " of frame " << k;
    EXPECT_NEAR(got.b, want.b, tolerance) << where << " of frame " << k;
  };
  for (int k : {0, 1, 17, frame_count - 1}) {
    const auto& rgb = video.rgb[static_cast<std::size_t>(k)];
    expect_close(test::rgb_at(rgb, width, 10, 40), test::background, k, "background");
    const int centre_x = (2 * k) % (width - test::square_side) + test::square_side / 2;
    expect_close(test::rgb_at(rgb, width, centre_x, 8 + test::square_side / 2), test::square_colour, k, "square");
  }
}

TEST(VideoWriter, IndexPrecedesMediaSoBrowsersCanStream) {
  const TempDir dir;
  write_clip(dir / "clip.mp4");
  const std::vector<std::string> atoms = test::top_level_atoms(dir / "clip.mp4");
  const auto moov = std::find(atoms.begin(), atoms.end(), "moov");
  const auto mdat = std::find(atoms.begin(), atoms.end(), "mdat");
  ASSERT_NE(moov, atoms.end());
  ASSERT_NE(mdat, atoms.end());
  EXPECT_LT(moov - atoms.begin(), mdat - atoms.begin());
  EXPECT_EQ(atoms.front(), "ftyp");
}

TEST(VideoWriter, IdenticalFramesGiveIdenticalBytes) {
  const TempDir dir;
  write_clip(dir / "a.mp4");
  write_clip(dir / "b.mp4");
  const std::vector<char> a = test::file_bytes(dir / "a.mp4");
  EXPECT_GT(a.size(), 1000U);
  EXPECT_TRUE(a == test::file_bytes(dir / "b.mp4"));
}

TEST(VideoWriter, StatsCountFramesStagesAndBytes) {
  const TempDir dir;
  const EncodeStats stats = write_clip(dir / "clip.mp4");
  EXPECT_EQ(stats.frames, frame_count);
  EXPECT_EQ(stats.packets, frame_count);  // one packet per frame, delayed ones included
  EXPECT_EQ(stats.bytes, static_cast<std::int64_t>(std::filesystem::file_size(dir / "clip.mp4")));
  EXPECT_GT(stats.convert_seconds, 0.0);
  EXPECT_GT(stats.encode_seconds, 0.0);
  EXPECT_GT(stats.finish_seconds, 0.0);
}

TEST(VideoWriter, Mpeg4WhenAskedForDecodesWithTheSameFrames) {
  const TempDir dir;
  VideoOptions options = small_options();
  options.codec = VideoCodec::mpeg4;
  {
    VideoWriter writer(dir / "clip.mp4", options);
    EXPECT_EQ(writer.codec(), VideoCodec::mpeg4);
    EXPECT_EQ(writer.encoder_name(), "mpeg4");
    EXPECT_EQ(writer.note(), "");  // asked for, so not a fallback
    Frame frame(width, height);
    for (int k = 0; k < frame_count; ++k) {
      test::draw_test_frame(frame, k);
      writer.write(frame);
    }
    writer.finish();
  }
  const test::DecodedVideo video = test::decode_video(dir / "clip.mp4");
  EXPECT_EQ(video.codec, "mpeg4");
  EXPECT_EQ(video.pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.times.size(), static_cast<std::size_t>(frame_count));
  EXPECT_NEAR(video.stream_duration, static_cast<double>(frame_count) / fps, 1e-9);
}

TEST(VideoWriter, AutomaticChoiceIsLibx264WithoutNote) {
  const TempDir dir;
  VideoWriter writer(dir / "clip.mp4", small_options());
  EXPECT_EQ(writer.codec(), VideoCodec::h264);
  EXPECT_EQ(writer.encoder_name(), "libx264");
  EXPECT_EQ(writer.note(), "");
}

TEST(VideoWriter, OddSizeIsRejectedBeforeAnythingIsCreated) {
  const TempDir dir;
  VideoOptions options = small_options();
  options.width = 65;
  expect_error([&] { VideoWriter writer(dir / "clip.mp4", options); }, ExitCode::bad_input, "65x48");
  expect_error([&] { VideoWriter writer(dir / "clip.mp4", options); }, ExitCode::bad_input, "even");
  options.width = 0;
  expect_error([&] { VideoWriter writer(dir / "clip.mp4", options); }, ExitCode::bad_input, "from 2 to 8192");
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VideoWriter, BadOptionsNameTheValueAndRange) {
  const TempDir dir;
  VideoOptions options = small_options();
  options.fps = 0;
  expect_error([&] { VideoWriter::validate(options); }, ExitCode::bad_input, "frame rate 0 must be from 1 to 240");
  options = small_options();
  options.crf = 52;
  expect_error([&] { VideoWriter::validate(options); }, ExitCode::bad_input, "crf 52 must be from 0 to 51");
  options = small_options();
  options.preset = "quick";
  expect_error([&] { VideoWriter::validate(options); }, ExitCode::bad_input, "unknown x264 preset 'quick'");
  options = small_options();
  options.tune = "cartoon";
  expect_error([&] { VideoWriter::validate(options); }, ExitCode::bad_input, "unknown x264 tune 'cartoon'");
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VideoWriter, DestructionWithoutFinishLeavesEarlierFileUntouched) {
  const TempDir dir;
  test::write_text(dir / "clip.mp4", "earlier clip");
  {
    VideoWriter writer(dir / "clip.mp4", small_options());
    Frame frame(width, height);
    for (int k = 0; k < 5; ++k) {
      test::draw_test_frame(frame, k);
      writer.write(frame);
    }
    EXPECT_EQ(dir.entries().size(), 2U);  // the target and the temporary beside it
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});
  EXPECT_EQ(test::read_text(dir / "clip.mp4"), "earlier clip");
}

// Issue 22: a signal while finish() drains the frames the encoder delayed (seconds for a
// long clip at 720p) was ignored: the clip was finished and the run ended with exit 0. In a
// child process (the interrupt flag, once set, stays set), which checks its own folder.
TEST(VideoWriterDeathTest, ASignalBeforeFinishLeavesTheEarlierFile) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto finish_after_a_signal = [] {
    install_interrupt_handler();
    const TempDir dir;
    test::write_text(dir / "clip.mp4", "earlier clip");
    int status = 1;
    try {
      VideoWriter writer(dir / "clip.mp4", small_options());
      Frame frame(width, height);
      for (int k = 0; k < frame_count; ++k) {
        test::draw_test_frame(frame, k);
        writer.write(frame);
      }
      std::raise(SIGTERM);
      writer.finish();
      status = 2;  // finished in spite of the signal
    } catch (const Error& e) {
      if (e.exit_status() == 128 + SIGTERM && dir.entries() == std::vector<std::string>{"clip.mp4"} &&
          test::read_text(dir / "clip.mp4") == "earlier clip")
        status = 0;
    }
    std::_Exit(status);
  };
  EXPECT_EXIT(finish_after_a_signal(), ::testing::ExitedWithCode(0), "");
}

TEST(VideoWriter, FinishReplacesEarlierFile) {
  const TempDir dir;
  test::write_text(dir / "clip.mp4", "earlier clip");
  write_clip(dir / "clip.mp4");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});
  EXPECT_EQ(test::decode_video(dir / "clip.mp4").times.size(), static_cast<std::size_t>(frame_count));
}

TEST(VideoWriter, WrongFrameSizeOrNoFramesFailAndLeaveNothing) {
  const TempDir dir;
  {
    VideoWriter writer(dir / "clip.mp4", small_options());
    const Frame wrong(32, 48);
    expect_error([&] { writer.write(wrong); }, ExitCode::failure, "frame of 32x48 given to a 64x48 video");
  }
  {
    VideoWriter writer(dir / "clip.mp4", small_options());
    expect_error([&] { writer.finish(); }, ExitCode::failure, "no frames");
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VideoWriter, MissingFolderOrFileInPathIsAClearInputError) {
  const TempDir dir;
  expect_error([&] { VideoWriter writer(dir / "no-such-folder" / "clip.mp4", small_options()); }, ExitCode::bad_input,
               "out: folder '" + (dir / "no-such-folder").string() + "' does not exist");
  test::write_text(dir / "plain-file", "");
  expect_error([&] { VideoWriter writer(dir / "plain-file" / "clip.mp4", small_options()); }, ExitCode::bad_input,
               "is not a folder");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain-file"});
}

TEST(VideoWriter, ReadOnlyFolderIsAClearInputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only folders";
  const TempDir dir;
  std::filesystem::create_directory(dir / "read-only");
  std::filesystem::permissions(dir / "read-only",
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  expect_error([&] { VideoWriter writer(dir / "read-only" / "clip.mp4", small_options()); }, ExitCode::bad_input,
               "is not writable");
}

}  // namespace
}  // namespace linkage
