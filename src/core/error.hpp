#pragma once
// One exception type for every user-facing failure, carrying the process exit code.
// Messages are one line: what was wrong, where it came from, and what is allowed.
//
// Errors about one setting are data: the setting's neutral name ("dt", "out",
// "theta1_dot") and the detail ("0 s is out of range; valid: ..."). Only the reader of
// the setting phrases where it came from: the CLI as a flag (--dt: ...), a lesson as
// FILE:LINE:COLUMN and its key. Lower modules never name a flag.
#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace linkage {

enum class ExitCode : int {
  ok = 0,
  failure = 1,       // an environment problem: a file that cannot be written, an encoder error
  bad_input = 2,     // a value, flag, key or file the user gave is invalid
  diverged = 3,      // a simulation left the finite numbers or an iteration failed
  interrupted = 130  // 128 + the signal number (SIGINT 130, SIGTERM 143, SIGHUP 129)
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : Error(code, {}, message) {}
  Error(ExitCode code, std::string setting, const std::string& detail)
      : std::runtime_error(setting.empty() ? detail : setting + ": " + detail),
        code_(code),
        setting_(std::move(setting)),
        detail_(detail) {}
  [[nodiscard]] ExitCode code() const noexcept { return code_; }
  /// The exit status: the code, or 128 + the signal for an interruption.
  [[nodiscard]] int exit_status() const noexcept { return signal_ != 0 ? 128 + signal_ : static_cast<int>(code_); }
  /// The setting the error is about (neutral name), or empty when the message is whole.
  [[nodiscard]] const std::string& setting() const noexcept { return setting_; }
  /// Whether the setting is a neutral name ("dt", "arrow_scale") that a reader spells its
  /// own way (--dt, a lesson key), not a phrase already said as the user wrote it.
  [[nodiscard]] bool setting_is_name() const noexcept {
    return !setting_.empty() && std::all_of(setting_.begin(), setting_.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
  }
  /// The message without the setting's name.
  [[nodiscard]] const std::string& detail() const noexcept { return detail_; }

  /// Invalid user input (exit 2) whose message already says where it came from.
  static Error input(const std::string& message) { return {ExitCode::bad_input, message}; }
  /// Invalid value of one setting (exit 2): the caller phrases where it came from.
  static Error invalid(std::string setting, const std::string& detail) {
    return {ExitCode::bad_input, std::move(setting), detail};
  }
  /// A run that could not go on (exit 3).
  static Error diverged(const std::string& message) { return {ExitCode::diverged, message}; }
  /// An I/O or library failure (exit 1).
  static Error failure(const std::string& message) { return {ExitCode::failure, message}; }
  /// An I/O failure about one setting's target (exit 1).
  static Error failure(std::string setting, const std::string& detail) {
    return {ExitCode::failure, std::move(setting), detail};
  }
  /// A terminating signal (SIGINT, SIGTERM, SIGHUP): exit 128 + signal.
  static Error interrupted(int signal) {
    Error e(ExitCode::interrupted, "interrupted by " + signal_name(signal));
    e.signal_ = signal;
    return e;
  }

  /// The same error about `setting` phrased by its reader, e.g. at a file position.
  [[nodiscard]] Error rephrased(const std::string& message) const {
    Error e(code_, message);
    e.signal_ = signal_;
    return e;
  }

 private:
  static std::string signal_name(int signal);

  ExitCode code_;
  std::string setting_;
  std::string detail_;
  int signal_ = 0;
};

}  // namespace linkage
