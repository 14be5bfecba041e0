#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/number_format.hpp"

namespace linkage {
namespace {

/// Whole counts below a million in full (frames, rows), anything else to three digits.
std::string amount(double value) {
  return format_significant(value, value == std::floor(value) && std::fabs(value) < 1e6 ? 7 : 3);
}

}  // namespace

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

ProgressOutput ProgressOutput::from_environment() {
  ProgressOutput output;
  output.terminal = stderr_is_terminal();
  if (const char* text = std::getenv("LINKAGE_PROGRESS_INTERVAL")) {
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    if (end != text && *end == '\0' && std::isfinite(seconds) && seconds > 0) {
      output.interval = std::chrono::duration<double>(seconds);
      output.plain = true;
    }
  }
  return output;
}

Progress::Progress(std::string label, double total, std::string unit, bool quiet)
    : Progress(std::move(label), total, std::move(unit), ProgressOutput::from_environment()) {
  visible_ = !quiet;
}

Progress::Progress(std::string label, double total, std::string unit, ProgressOutput output)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      output_(std::move(output)),
      visible_(true),
      start_(output_.now()),
      // A terminal line shows at once; plain lines only after the first interval.
      last_draw_(output_.terminal ? start_ - std::chrono::seconds(1) : start_) {}

Progress::~Progress() { finish(); }

void Progress::update(double done) {
  if (!visible_ || finished_ || !(output_.terminal || output_.plain)) return;
  const auto now = output_.now();
  const std::chrono::duration<double> since_draw = now - last_draw_;
  if (output_.terminal ? since_draw < std::chrono::milliseconds(100) && done < total_ : since_draw < output_.interval)
    return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (output_.terminal)
    draw_terminal_line(done, elapsed);
  else
    print_plain_line(done, elapsed);
}

void Progress::draw_terminal_line(double done, double elapsed) {
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double left = rate > 0 ? (total_ - done) / rate : 0.0;
  std::fprintf(output_.sink, "\r\033[K%s: %s/%s %s, %s %s/s, %.0f s left", label_.c_str(), amount(done).c_str(),
               amount(total_).c_str(), unit_.c_str(), format_significant(rate, 3).c_str(), unit_.c_str(), left);
  std::fflush(output_.sink);
}

void Progress::print_plain_line(double done, double elapsed) {
  const double percent = total_ > 0 ? std::clamp(std::floor(100 * done / total_), 0.0, 100.0) : 0.0;
  std::fprintf(output_.sink, "linkage: %s: %.0f%% (%s of %s %s), %.0f s so far\n", label_.c_str(), percent,
               amount(done).c_str(), amount(total_).c_str(), unit_.c_str(), elapsed);
  std::fflush(output_.sink);
}

void Progress::finish() {
  if (!visible_ || finished_) return;
  finished_ = true;
  if (!output_.terminal) return;
  std::fprintf(output_.sink, "\r\033[K");
  std::fflush(output_.sink);
}

ElapsedLine::ElapsedLine(std::string label, bool quiet, ProgressOutput output, std::chrono::duration<double> delay)
    : label_(std::move(label)), output_(std::move(output)) {
  if (quiet || !output_.terminal) return;
  thread_ = std::thread([this, delay] {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_);
    if (wake_.wait_for(lock, delay, [this] { return done_; })) return;
    do {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(output_.sink, "\r\033[K%s: %.0f s", label_.c_str(), elapsed);
      std::fflush(output_.sink);
    } while (!wake_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; }));
    std::fprintf(output_.sink, "\r\033[K");
    std::fflush(output_.sink);
  });
}

ElapsedLine::~ElapsedLine() { finish(); }

void ElapsedLine::finish() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

}  // namespace linkage
