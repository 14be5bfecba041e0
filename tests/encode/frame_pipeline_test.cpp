#include "encode/frame_pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "encode/encode_test_support.hpp"
#include "encode/png_writer.hpp"
#include "encode/video_writer.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

// Frame k carries k in its first pixel's blue and green bytes.
void stamp(Frame& frame, int k) {
  frame.pixels[0] = static_cast<std::uint8_t>(k & 0xff);
  frame.pixels[1] = static_cast<std::uint8_t>(k >> 8);
}
int stamped(const Frame& frame) { return frame.pixels[0] | frame.pixels[1] << 8; }

bool in_pool(FramePipeline& pipeline, const Frame& frame) {
  for (const Frame& buffer : pipeline.buffers())
    if (&buffer == &frame) return true;
  return false;
}

TEST(FramePipeline, ConsumesEveryFrameInOrderFromTheFixedBuffers) {
  std::vector<int> seen;  // written by the encoder thread, read after finish()
  FramePipeline pipeline(
      8, 6, [&](const Frame& frame) { seen.push_back(stamped(frame)); }, 3);
  ASSERT_EQ(pipeline.buffers().size(), 3U);
  constexpr int frames = 200;
  for (int k = 0; k < frames; ++k) {
    Frame& frame = pipeline.acquire();
    ASSERT_TRUE(in_pool(pipeline, frame)) << "frame " << k << " is not one of the preallocated buffers";
    ASSERT_EQ(frame.width, 8);
    ASSERT_EQ(frame.height, 6);
    stamp(frame, k);
    pipeline.submit();
  }
  pipeline.finish();
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(frames));
  for (int k = 0; k < frames; ++k) EXPECT_EQ(seen[static_cast<std::size_t>(k)], k);
  EXPECT_EQ(pipeline.stats().frames, frames);
}

// A fake encoder that holds frame k until the drawing thread has begun asking for frame
// k + buffers: so the drawing thread must get that far while the encoder is busy (the two
// overlap), and the frames it holds meanwhile show how far ahead it may run. No clock
// decides anything; the wait's time limit only turns a hang into a failure.
TEST(FramePipeline, DrawingRunsAheadOfTheEncoderByTheBufferCountAndNoFurther) {
  constexpr int buffers = 3, frames = 12;
  std::mutex mutex;
  std::condition_variable changed;
  int asked = 0;    // acquire() calls begun by the drawing thread
  int encoded = 0;  // frames the encoder has finished
  std::vector<int> order;
  FramePipeline pipeline(
      4, 4,
      [&](const Frame& frame) {
        const int k = stamped(frame);
        std::unique_lock lock(mutex);
        order.push_back(k);
        const int awaited = std::min(k + buffers + 1, frames);
        EXPECT_TRUE(changed.wait_for(lock, std::chrono::seconds(30), [&] { return asked >= awaited; }))
            << "while frame " << k << " was encoding, the drawing thread asked for only " << asked << " frames";
        ++encoded;
      },
      buffers);
  int most_in_flight = 0;  // frames acquired and not yet encoded, seen when acquire() returns
  for (int k = 0; k < frames; ++k) {
    {
      const std::lock_guard lock(mutex);
      asked = k + 1;
    }
    changed.notify_all();
    Frame& frame = pipeline.acquire();
    {
      // Each frame in flight holds a buffer until the encoder is done with it.
      const std::lock_guard lock(mutex);
      most_in_flight = std::max(most_in_flight, k + 1 - encoded);
    }
    stamp(frame, k);
    pipeline.submit();
  }
  pipeline.finish();
  EXPECT_EQ(most_in_flight, buffers);
  ASSERT_EQ(order.size(), static_cast<std::size_t>(frames));
  for (int k = 0; k < frames; ++k) EXPECT_EQ(order[static_cast<std::size_t>(k)], k);
}

TEST(FramePipeline, ConsumerErrorReachesTheProducer) {
  std::atomic<int> consumed{0};
  FramePipeline pipeline(4, 4, [&](const Frame& frame) {
    if (stamped(frame) == 3) throw Error::failure("disk full at frame 3");
    consumed.fetch_add(1);
  });
  try {
    for (int k = 0; k < 1000; ++k) {
      stamp(pipeline.acquire(), k);
      pipeline.submit();
    }
    pipeline.finish();
    FAIL() << "the consumer's error was lost";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ExitCode::failure);
    EXPECT_STREQ(error.what(), "disk full at frame 3");
  }
  EXPECT_EQ(consumed.load(), 3);  // nothing after the failure was consumed
}

// Destroyed without finish() while the encoder is in the middle of frame 0 with two more
// queued: the destructor waits for that frame (it joins the encoder thread) and the
// encoder is not called after it returns. (Whether the queued frames are dropped depends
// on whether the release below or the destructor's cancel comes first, which this test
// leaves open rather than decide it by the clock.)
TEST(FramePipeline, DestructionWithoutFinishWaitsForTheFrameBeingEncoded) {
  std::mutex mutex;
  std::condition_variable changed;
  bool encoding = false, released = false;
  int started = 0, encoded = 0;
  auto pipeline = std::make_unique<FramePipeline>(4, 4, [&](const Frame&) {
    std::unique_lock lock(mutex);
    ++started;
    encoding = true;
    changed.notify_all();
    changed.wait(lock, [&] { return released; });
    ++encoded;
  });
  for (int k = 0; k < 3; ++k) {
    (void)pipeline->acquire();
    pipeline->submit();
  }
  {
    std::unique_lock lock(mutex);
    if (!changed.wait_for(lock, std::chrono::seconds(30), [&] { return encoding; })) {
      released = true;  // so the destructor is not left waiting
      FAIL() << "the encoder never started frame 0";
    }
  }
  std::thread destroyer([&] { pipeline.reset(); });
  {
    const std::lock_guard lock(mutex);
    EXPECT_EQ(encoded, 0);
    released = true;
  }
  changed.notify_all();
  destroyer.join();
  const std::lock_guard lock(mutex);
  EXPECT_GE(encoded, 1);        // frame 0 finished before the destructor returned
  EXPECT_EQ(started, encoded);  // and the encoder thread is not still in a frame
}

TEST(FramePipeline, MisuseIsReported) {
  FramePipeline pipeline(4, 4, [](const Frame&) {});
  EXPECT_THROW(pipeline.submit(), Error);
  (void)pipeline.acquire();
  EXPECT_THROW((void)pipeline.acquire(), Error);
  pipeline.submit();
  pipeline.finish();
  EXPECT_THROW(FramePipeline(
                   4, 4, [](const Frame&) {}, 1),
               Error);
}

TEST(FramePipeline, FeedsVideoAndPngSequenceTogether) {
  const test::TempDir dir;
  constexpr int width = 64, height = 48, frames = 20;
  VideoOptions options;
  options.width = width;
  options.height = height;
  options.fps = 10;
  VideoWriter video(dir / "clip.mp4", options);
  std::filesystem::create_directory(dir / "frames");
  PngSequenceWriter png(dir / "frames", width, height, "--frames");
  FramePipeline pipeline(width, height, [&](const Frame& frame) {
    video.write(frame);
    png.write(frame);
  });
  for (int k = 0; k < frames; ++k) {
    test::draw_test_frame(pipeline.acquire(), k);
    pipeline.submit();
  }
  pipeline.finish();
  video.finish();
  png.finish();
  EXPECT_EQ(test::decode_video(dir / "clip.mp4").times.size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(test::entries(dir / "frames").size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(video.stats().frames, frames);
  EXPECT_EQ(png.stats().frames, frames);
}

// Ctrl-C sets a process-wide flag that nothing clears, so it runs in a forked child:
// the child exits 130 only if the pipeline threw Error::interrupted and no file is left.
TEST(FramePipelineDeathTest, CtrlCStopsTheRunAndLeavesNoFiles) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const test::TempDir dir;
  const auto run = [&] {
    install_interrupt_handler();
    int code = 1;
    try {
      VideoOptions options;
      options.width = 64;
      options.height = 48;
      VideoWriter video(dir / "clip.mp4", options);
      PngSequenceWriter png(dir.path(), 64, 48, "--frames");
      FramePipeline pipeline(64, 48, [&](const Frame& frame) {
        video.write(frame);
        png.write(frame);
      });
      for (int k = 0; k < 1000; ++k) {
        test::draw_test_frame(pipeline.acquire(), k % 16);
        pipeline.submit();
        if (k == 10) std::raise(SIGINT);
      }
      pipeline.finish();
    } catch (const Error& error) {
      if (error.code() == ExitCode::interrupted) code = 130;
    }
    if (!std::filesystem::is_empty(dir.path())) code = 2;
    std::filesystem::remove_all(dir.path());  // exit() skips the TempDir's destructor
    std::exit(code);
  };
  EXPECT_EXIT(run(), testing::ExitedWithCode(130), "");
}

}  // namespace
}  // namespace linkage
