#include "encode/slot_queue.hpp"

#include <chrono>

#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace linkage {
namespace {
using Clock = std::chrono::steady_clock;

// A signal handler cannot notify a condition variable, so producer waits wake up this
// often to look at the Ctrl-C flag.
constexpr std::chrono::milliseconds interrupt_poll{50};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void push(std::vector<std::size_t>& ring, std::size_t head, std::size_t& count, std::size_t slot) {
  ring[(head + count) % ring.size()] = slot;
  ++count;
}

std::size_t pop(const std::vector<std::size_t>& ring, std::size_t& head, std::size_t& count) {
  const std::size_t slot = ring[head];
  head = (head + 1) % ring.size();
  --count;
  return slot;
}
}  // namespace

SlotQueue::SlotQueue(std::size_t slots, int workers, std::function<void(std::size_t)> work)
    : work_(std::move(work)), free_(slots), ready_(slots) {
  if (slots == 0 || workers < 1) throw Error::failure("SlotQueue needs at least one slot and one worker");
  for (std::size_t slot = 0; slot < slots; ++slot) push(free_, free_head_, free_count_, slot);
  threads_.reserve(static_cast<std::size_t>(workers));
  try {
    for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { worker_loop(); });
  } catch (...) {
    {
      const std::lock_guard lock(mutex_);
      cancelled_ = true;
    }
    slot_ready_.notify_all();
    for (auto& thread : threads_) thread.join();
    throw;
  }
}

SlotQueue::~SlotQueue() {
  {
    const std::lock_guard lock(mutex_);
    cancelled_ = true;
  }
  slot_ready_.notify_all();
  for (auto& thread : threads_)
    if (thread.joinable()) thread.join();
}

void SlotQueue::throw_if_stopped_locked() {
  if (error_) std::rethrow_exception(error_);
  if (interrupt_requested()) {
    cancelled_ = true;
    slot_ready_.notify_all();
    throw interrupted_error();
  }
}

std::size_t SlotQueue::acquire() {
  std::unique_lock lock(mutex_);
  const auto start = Clock::now();
  while (free_count_ == 0 && !error_ && !interrupt_requested()) slot_freed_.wait_for(lock, interrupt_poll);
  waits_.producer_wait_seconds += seconds_since(start);
  throw_if_stopped_locked();
  return pop(free_, free_head_, free_count_);
}

void SlotQueue::submit(std::size_t slot) {
  {
    const std::lock_guard lock(mutex_);
    throw_if_stopped_locked();
    push(ready_, ready_head_, ready_count_, slot);
  }
  slot_ready_.notify_one();
}

void SlotQueue::finish() {
  if (finished_) return;
  {
    const std::lock_guard lock(mutex_);
    closing_ = true;
  }
  slot_ready_.notify_all();
  // Workers drain the ready ring and exit; after Ctrl-C they stop before their next slot.
  for (auto& thread : threads_) thread.join();
  finished_ = true;
  const std::lock_guard lock(mutex_);
  throw_if_stopped_locked();
}

QueueWaits SlotQueue::waits() const {
  const std::lock_guard lock(mutex_);
  return waits_;
}

void SlotQueue::worker_loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    const auto start = Clock::now();
    slot_ready_.wait(lock, [this] { return ready_count_ > 0 || closing_ || cancelled_ || error_; });
    waits_.worker_idle_seconds += seconds_since(start);
    if (cancelled_ || error_) return;
    if (ready_count_ == 0) return;  // closing and drained
    if (interrupt_requested()) {
      error_ = std::make_exception_ptr(interrupted_error());
      slot_ready_.notify_all();
      slot_freed_.notify_all();
      return;
    }
    const std::size_t slot = pop(ready_, ready_head_, ready_count_);
    lock.unlock();
    std::exception_ptr failure;
    try {
      work_(slot);
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    if (failure && !error_) {
      error_ = failure;
      slot_ready_.notify_all();  // the other workers stop too
    }
    push(free_, free_head_, free_count_, slot);
    slot_freed_.notify_one();
  }
}

}  // namespace linkage
