#pragma once
// Terminating signals (SIGINT, SIGTERM, SIGHUP) during long work: the handler only
// records the signal; loops poll it and throw interrupted_error(), so destructors remove
// temporary files before the process exits with 128 + the signal number. A second
// signal ends the process at once (the next run removes what it left behind).
#include <functional>

namespace linkage {

/// Installs the handlers (idempotent). Blocking reads return early (no SA_RESTART), and
/// the first signal puts /dev/null in standard input's place, so a prompt waiting for input stops at once
/// even when the signal came just before its read.
void install_interrupt_handler();
/// True once a terminating signal has been received.
[[nodiscard]] bool interrupt_requested() noexcept;
/// The signal received, or 0.
[[nodiscard]] int interrupt_signal() noexcept;
/// The error for the signal received (exit 128 + signal).
[[nodiscard]] class Error interrupted_error();
/// Throws interrupted_error() if a terminating signal has been received (or ends the
/// process, while an EndAtOnceOnSignal lives).
void throw_if_interrupted();

/// While one lives, a signal ends the process at the next throw_if_interrupted(): it runs
/// `last_words` (erase a progress line), prints the error line main would print
/// ("linkage: error: interrupted by SIGTERM") and calls std::_Exit with 128 + the signal,
/// freeing nothing. For work that has begun no file and no output (a long chain's
/// derivation): unwinding it frees its expressions one by one, seconds for 200 links.
/// Where a file or folder is begun (a temporary named, an output folder made): a living
/// EndAtOnceOnSignal stops ending the process at once, so that from now on a signal unwinds
/// and what was begun is removed.
void file_begun() noexcept;

/// From now on a terminating signal ends the process at once by its default action (status
/// 128 + the signal), and one already received does so now: for the end of a run whose
/// output is whole, where what is left (freeing a long chain's expressions, the static
/// destructors) polls nothing and would otherwise end with status 0.
void end_by_default_on_signal() noexcept;

class EndAtOnceOnSignal {
 public:
  explicit EndAtOnceOnSignal(std::function<void()> last_words = {});
  EndAtOnceOnSignal(const EndAtOnceOnSignal&) = delete;
  EndAtOnceOnSignal& operator=(const EndAtOnceOnSignal&) = delete;
  ~EndAtOnceOnSignal();

 private:
  friend void throw_if_interrupted();
  std::function<void()> last_words_;
};

}  // namespace linkage
