#pragma once
// One exception type for every user-facing failure, carrying the process exit code.
// Messages are one line: what was wrong, where it came from, and what is allowed.
#include <stdexcept>
#include <string>

namespace linkage {

enum class ExitCode : int {
  ok = 0,
  failure = 1,      // an environment problem: a file that cannot be written, an encoder error
  bad_input = 2,    // a value, flag, key or file the user gave is invalid
  diverged = 3,     // a simulation left the finite numbers or an iteration failed
  interrupted = 130 // SIGINT
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  [[nodiscard]] ExitCode code() const noexcept { return code_; }

  /// Invalid user input (exit 2).
  static Error input(const std::string& message) { return {ExitCode::bad_input, message}; }
  /// A run that could not go on (exit 3).
  static Error diverged(const std::string& message) { return {ExitCode::diverged, message}; }
  /// An I/O or library failure (exit 1).
  static Error failure(const std::string& message) { return {ExitCode::failure, message}; }
  /// Ctrl-C (exit 130).
  static Error interrupted() { return {ExitCode::interrupted, "interrupted"}; }

 private:
  ExitCode code_;
};

}  // namespace linkage
