#include "core/interrupt.hpp"

#include <csignal>

#include "core/error.hpp"

namespace linkage {
namespace {
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_sigint(int /*signal*/) { g_interrupted = 1; }
}  // namespace

void install_interrupt_handler() { std::signal(SIGINT, on_sigint); }

bool interrupt_requested() noexcept { return g_interrupted != 0; }

void throw_if_interrupted() {
  if (interrupt_requested()) throw Error::interrupted();
}

}  // namespace linkage
