#pragma once
// Ctrl-C handling for long work: the handler only sets a flag; loops poll it and throw
// Error::interrupted(), so destructors remove temporary files before exit 130.

namespace linkage {

/// Installs the SIGINT handler (idempotent).
void install_interrupt_handler();
/// True once SIGINT has been received.
[[nodiscard]] bool interrupt_requested() noexcept;
/// Throws Error::interrupted() if SIGINT has been received.
void throw_if_interrupted();

}  // namespace linkage
