#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

#include "core/error.hpp"

namespace linkage {
namespace {
// Lock-free atomic: safe to set in a signal handler and to read from worker threads.
std::atomic<int> g_interrupted{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_sigint(int /*signal*/) { g_interrupted.store(1, std::memory_order_relaxed); }
}  // namespace

void install_interrupt_handler() { std::signal(SIGINT, on_sigint); }

bool interrupt_requested() noexcept { return g_interrupted.load(std::memory_order_relaxed) != 0; }

void throw_if_interrupted() {
  if (interrupt_requested()) throw Error::interrupted();
}

}  // namespace linkage
