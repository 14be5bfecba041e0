#pragma once
// Progress of long work on stderr. On a terminal: one line redrawn at most ten times a
// second and erased when done. Elsewhere (a log, a CI job, a pipe) nothing, unless
// LINKAGE_PROGRESS_INTERVAL (seconds) asks for a plain line at that interval,
// "linkage: simulate: 41% (410000 of 1e+06 s simulated), 12 s so far", once the work
// has lasted that long. `quiet` silences both.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace linkage {

/// Where and how a Progress reports; the defaults come from the environment.
struct ProgressOutput {
  using Clock = std::chrono::steady_clock;
  std::FILE* sink = stderr;
  bool terminal = false;                        // redraw one line in place
  bool plain = false;                           // off a terminal: plain lines at `interval`
  std::chrono::duration<double> interval{5.0};  // between plain lines, and before the first
  std::function<Clock::time_point()> now = [] { return Clock::now(); };

  /// stderr, a terminal if it is one; plain lines at the interval LINKAGE_PROGRESS_INTERVAL
  /// gives if that is a positive number of seconds (else none off a terminal, 5 s kept).
  static ProgressOutput from_environment();
};

class Progress {
 public:
  /// `total` units of work named `unit` (e.g. "frames", "s simulated"); quiet forces silence.
  Progress(std::string label, double total, std::string unit, bool quiet = false);
  Progress(std::string label, long total, std::string unit, bool quiet = false)
      : Progress(std::move(label), static_cast<double>(total), std::move(unit), quiet) {}
  /// The same, reporting to `output` (tests give a clock and a file).
  Progress(std::string label, double total, std::string unit, ProgressOutput output);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();

  /// Reports that `done` units are complete.
  void update(double done);
  void update(long done) { update(static_cast<double>(done)); }
  /// Erases the terminal line (plain lines stay).
  void finish();
  /// Whether anything may be shown (false when quiet).
  [[nodiscard]] bool visible() const { return visible_; }

 private:
  void draw_terminal_line(double done, double elapsed);
  void print_plain_line(double done, double elapsed);

  std::string label_;
  std::string unit_;
  double total_;
  ProgressOutput output_;
  bool visible_;
  bool finished_ = false;
  ProgressOutput::Clock::time_point start_;
  ProgressOutput::Clock::time_point last_draw_;
};

/// A line for one long step that has no measure of its own progress (deriving a long
/// chain's equations): on a terminal, once the step has lasted `delay`, "label: 3 s" redrawn
/// every second by a thread of its own, erased when done; nothing elsewhere or when quiet.
class ElapsedLine {
 public:
  explicit ElapsedLine(std::string label, bool quiet = false,
                       ProgressOutput output = ProgressOutput::from_environment(),
                       std::chrono::duration<double> delay = std::chrono::seconds(1));
  ElapsedLine(const ElapsedLine&) = delete;
  ElapsedLine& operator=(const ElapsedLine&) = delete;
  ~ElapsedLine();
  /// Stops the thread and erases the line if it was shown.
  void finish();

 private:
  std::string label_;
  ProgressOutput output_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

/// True when stderr is a terminal.
[[nodiscard]] bool stderr_is_terminal();

}  // namespace linkage
