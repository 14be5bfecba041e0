#pragma once
// A fixed set of buffer slots cycling between one producer and a few worker threads:
// the producer acquires a free slot, fills it and submits it; a worker takes submitted
// slots in order, processes them and frees them. The number of slots bounds the
// memory and how far the producer may run ahead; nothing is allocated per slot use.
//
// Errors: the first exception a worker throws stops all workers and is rethrown to the
// producer by its next acquire(), submit() or finish(). Ctrl-C (core/interrupt.hpp)
// stops workers before their next slot and makes the producer's calls throw
// Error::interrupted(). Destroying the queue without finish() cancels: queued slots are
// dropped, the workers are joined.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace linkage {

/// Seconds spent waiting on each side of a SlotQueue.
struct QueueWaits {
  double producer_wait_seconds = 0;  // acquire() blocked: every slot busy (the workers are the bottleneck)
  double worker_idle_seconds = 0;    // workers blocked with nothing to do, summed over workers
};

class SlotQueue {
 public:
  /// `work(slot)` runs on one of `workers` threads for each submitted slot; slots are
  /// numbered 0 .. slots - 1. With one worker, slots are processed in submission order.
  SlotQueue(std::size_t slots, int workers, std::function<void(std::size_t slot)> work);
  SlotQueue(const SlotQueue&) = delete;
  SlotQueue& operator=(const SlotQueue&) = delete;
  /// Cancels unfinished work and joins the workers.
  ~SlotQueue();

  /// A free slot for the producer to fill; blocks while all are busy.
  [[nodiscard]] std::size_t acquire();
  /// Hands a filled slot (from acquire()) to the workers.
  void submit(std::size_t slot);
  /// Waits until every submitted slot is processed and joins the workers; rethrows a
  /// worker's exception. Further calls do nothing.
  void finish();

  [[nodiscard]] QueueWaits waits() const;

 private:
  void worker_loop();
  // Rethrows a worker's error, or cancels and throws Error::interrupted() after Ctrl-C.
  void throw_if_stopped_locked();

  std::function<void(std::size_t)> work_;
  mutable std::mutex mutex_;
  std::condition_variable slot_freed_;
  std::condition_variable slot_ready_;
  // Two rings of slot numbers, each sized to the slot count so pushes never allocate.
  std::vector<std::size_t> free_, ready_;
  std::size_t free_head_ = 0, free_count_ = 0, ready_head_ = 0, ready_count_ = 0;
  bool closing_ = false;  // finish(): workers exit once the ready ring is empty
  bool cancelled_ = false;
  bool finished_ = false;
  std::exception_ptr error_;
  QueueWaits waits_;
  std::vector<std::thread> threads_;
};

}  // namespace linkage
