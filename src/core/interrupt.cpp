#include "core/interrupt.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "core/error.hpp"

namespace linkage {
namespace {
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Lock-free atomic: safe to set in a signal handler and to read from worker threads.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

int g_null_input = -1;  // /dev/null, opened before any handler runs

std::atomic<EndAtOnceOnSignal*> g_end_at_once{nullptr};

extern "C" void on_signal(int signal) {
  int none = 0;
  if (g_signal.compare_exchange_strong(none, signal, std::memory_order_relaxed)) {
    // A prompt about to read standard input would miss a signal that came just before
    // its read() and wait forever; with stdin at /dev/null that read ends at once. The
    // program is ending, so nothing else needs stdin.
    if (g_null_input >= 0) ::dup2(g_null_input, STDIN_FILENO);
    return;
  }
  // A second signal: the user insists, or the work does not poll. End now.
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}
}  // namespace

void install_interrupt_handler() {
  if (g_null_input < 0) g_null_input = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocked read returns with EINTR
  for (int signal : kSignals) sigaction(signal, &action, nullptr);
}

bool interrupt_requested() noexcept { return g_signal.load(std::memory_order_relaxed) != 0; }

int interrupt_signal() noexcept { return g_signal.load(std::memory_order_relaxed); }

Error interrupted_error() { return Error::interrupted(interrupt_signal() != 0 ? interrupt_signal() : SIGINT); }

void throw_if_interrupted() {
  if (!interrupt_requested()) return;
  // The first thread here ends the process; none unwinds meanwhile.
  if (EndAtOnceOnSignal* end = g_end_at_once.exchange(nullptr)) {
    if (end->last_words_) end->last_words_();
    const Error error = interrupted_error();
    std::fprintf(stderr, "linkage: error: %s\n", error.what());
    std::fflush(stderr);
    std::_Exit(error.exit_status());
  }
  throw interrupted_error();
}

void file_begun() noexcept { g_end_at_once.store(nullptr); }

void end_by_default_on_signal() noexcept {
  for (int signal : kSignals) std::signal(signal, SIG_DFL);
  if (const int received = g_signal.load(std::memory_order_relaxed); received != 0) std::raise(received);
}

EndAtOnceOnSignal::EndAtOnceOnSignal(std::function<void()> last_words) : last_words_(std::move(last_words)) {
  g_end_at_once.store(this);
}

EndAtOnceOnSignal::~EndAtOnceOnSignal() {
  EndAtOnceOnSignal* self = this;
  g_end_at_once.compare_exchange_strong(self, nullptr);
}

std::string Error::signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "signal " + std::to_string(signal);
  }
}

}  // namespace linkage
