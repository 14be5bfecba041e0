#include "encode/frame_pipeline.hpp"

#include <string>

#include "core/error.hpp"
#include "encode/slot_queue.hpp"

namespace linkage {

FramePipeline::FramePipeline(int width, int height, std::function<void(const Frame&)> consume, std::size_t buffers)
    : consume_(std::move(consume)) {
  if (width <= 0 || height <= 0)
    throw Error::input("frame size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  if (buffers < 2) throw Error::failure("FramePipeline needs at least 2 buffers to overlap drawing and encoding");
  frames_.reserve(buffers);
  for (std::size_t i = 0; i < buffers; ++i) frames_.emplace_back(width, height);
  // One encoder thread keeps frames in order.
  queue_ = std::make_unique<SlotQueue>(buffers, 1, [this](std::size_t slot) {
    consume_(frames_[slot]);
    consumed_.fetch_add(1, std::memory_order_relaxed);
  });
}

FramePipeline::~FramePipeline() = default;

Frame& FramePipeline::acquire() {
  if (acquired_) throw Error::failure("FramePipeline::acquire() called twice without submit()");
  current_ = queue_->acquire();
  acquired_ = true;
  return frames_[current_];
}

void FramePipeline::submit() {
  if (!acquired_) throw Error::failure("FramePipeline::submit() called without acquire()");
  acquired_ = false;
  queue_->submit(current_);
}

void FramePipeline::finish() { queue_->finish(); }

PipelineStats FramePipeline::stats() const {
  const QueueWaits waits = queue_->waits();
  return {consumed_.load(std::memory_order_relaxed), waits.producer_wait_seconds, waits.worker_idle_seconds};
}

}  // namespace linkage
