#pragma once
// Progress of long work on stderr: shown only when stderr is a terminal (and not
// silenced), redrawn at most ten times a second, erased when done.
#include <chrono>
#include <string>

namespace linkage {

class Progress {
 public:
  /// `total` units of work named `what` (e.g. "frames"); quiet forces silence.
  Progress(std::string label, long total, std::string unit, bool quiet = false);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();

  /// Reports that `done` units are complete.
  void update(long done);
  /// Erases the line.
  void finish();
  [[nodiscard]] bool visible() const { return visible_; }

 private:
  std::string label_;
  std::string unit_;
  long total_;
  bool visible_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

/// True when stderr is a terminal.
[[nodiscard]] bool stderr_is_terminal();

}  // namespace linkage
