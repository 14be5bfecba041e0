#pragma once
// Terminating signals (SIGINT, SIGTERM, SIGHUP) during long work: the handler only
// records the signal; loops poll it and throw interrupted_error(), so destructors remove
// temporary files before the process exits with 128 + the signal number. A second
// signal ends the process at once (the next run removes what it left behind).

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
/// Throws interrupted_error() if a terminating signal has been received.
void throw_if_interrupted();

}  // namespace linkage
