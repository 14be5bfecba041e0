#pragma once
// Starting an external program (pdflatex; the system C++ compiler) from an argument
// vector with posix_spawn: no shell reads the arguments, so a file name with quotes, ';'
// or '$(...)' is one argument and nothing more. The wait polls core/interrupt: on
// SIGINT/SIGTERM/SIGHUP the child is killed and reaped before interrupted_error() is thrown.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace linkage {

struct ProgramRun {
  /// The program (looked up on $PATH when it has no '/') and its arguments.
  std::vector<std::string> argv;
  /// The child's working folder; empty: this process's.
  std::filesystem::path directory;
  /// Standard input from /dev/null (a program that asks a question gets end of file), else inherited.
  bool null_input = true;
  /// Standard output and error captured into ProgramResult::output, else sent to /dev/null.
  bool capture_output = false;
  /// Killed after this long (zero: no limit).
  std::chrono::milliseconds timeout{0};
};

struct ProgramResult {
  int exit_code = -1;      // the program's exit status; -1 when a signal ended it
  int signal = 0;          // the signal that ended it, or 0
  bool timed_out = false;  // killed at the timeout
  std::string output;      // standard output and error interleaved, when captured (at most 4 MiB: the rest dropped)

  [[nodiscard]] bool succeeded() const { return exit_code == 0 && !timed_out; }
};

/// Runs `run` to its end. Error::failure when it cannot be started (naming the program
/// and why); interrupted_error() when this process is interrupted meanwhile.
[[nodiscard]] ProgramResult run_program(const ProgramRun& run);

}  // namespace linkage
