#pragma once
// Drawing and encoding overlap: the render thread draws into one of a few Frame
// buffers while an encoder thread consumes the previous ones. The buffers are
// allocated once; a bounded queue between the two threads keeps memory fixed and lets
// the faster side wait for the slower one.
//
//   FramePipeline pipeline(width, height, [&](const Frame& f) { video.write(f); });
//   for (k = 0; k < frames; ++k) {
//     Frame& frame = pipeline.acquire();   // a free buffer (blocks while all are queued)
//     draw(frame, k);
//     pipeline.submit();                   // queued for the encoder thread
//   }
//   pipeline.finish();                     // waits for the encoder; rethrows its errors
//   video.finish();
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/frame.hpp"

namespace linkage {

class SlotQueue;

/// Where the time of a pipelined run went.
struct PipelineStats {
  std::int64_t frames = 0;           // frames consumed
  double producer_wait_seconds = 0;  // the render thread waited for a free buffer
  double consumer_idle_seconds = 0;  // the encoder thread waited for a frame
};

class FramePipeline {
 public:
  /// `consume` runs on the encoder thread once per submitted frame, in submission order.
  /// `buffers` (>= 2) frames of width x height are allocated now and reused.
  FramePipeline(int width, int height, std::function<void(const Frame&)> consume, std::size_t buffers = 3);
  FramePipeline(const FramePipeline&) = delete;
  FramePipeline& operator=(const FramePipeline&) = delete;
  /// Without finish(): cancels, dropping queued frames, and joins the encoder thread.
  ~FramePipeline();

  /// A free buffer to draw the next frame into; its previous contents are stale. Blocks
  /// while every buffer is queued. Rethrows an exception of `consume`; throws
  /// Error::interrupted() after Ctrl-C. Call submit() before the next acquire().
  [[nodiscard]] Frame& acquire();
  /// Queues the frame from the last acquire() for the encoder thread.
  void submit();
  /// Waits until every submitted frame is consumed and stops the encoder thread;
  /// rethrows an exception of `consume` or throws Error::interrupted().
  void finish();

  /// Every buffer (stable addresses for the pipeline's life): acquire() returns one of
  /// these, so a caller may prepare e.g. one Cairo surface per buffer up front.
  [[nodiscard]] std::span<Frame> buffers() { return frames_; }
  [[nodiscard]] PipelineStats stats() const;

 private:
  std::vector<Frame> frames_;
  std::function<void(const Frame&)> consume_;
  std::atomic<std::int64_t> consumed_{0};
  std::size_t current_ = 0;
  bool acquired_ = false;
  std::unique_ptr<SlotQueue> queue_;
};

}  // namespace linkage
