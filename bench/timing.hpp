#pragma once
// In-process timing with the steady clock: a measurement repeats the work until it has
// run for a minimum total time and reports the median of the repeats, so one slow run
// (another process taking the core) does not decide the result.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace linkage::bench {

struct Timing {
  double median_seconds = 0;      // steady clock
  double min_seconds = 0;         // steady clock
  double cpu_median_seconds = 0;  // this thread's CPU time: a cross-check on a busy machine
  int repeats = 0;
};

/// Makes the compiler forget what it knows of `value` (an empty asm statement that may
/// read and write it). A timed loop over one state nudged in one entry calls this on the
/// state each time, so the work on its other entries cannot be hoisted out of the loop:
/// GCC did that with the inlined closed form's sincos of theta1, which then cost one
/// sincos a call, not two.
template <class T>
inline void forget(T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}

/// CPU time consumed by the calling thread, s.
[[nodiscard]] inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The median of `values` (which it reorders); 0 for none.
[[nodiscard]] inline double median(std::vector<double>& values) {
  if (values.empty()) return 0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  if (values.size() % 2 == 1) return *mid;
  return (*mid + *std::max_element(values.begin(), mid)) / 2;
}

/// Calls `work()` until the calls have taken `min_total` seconds together (at least
/// once, at most `max_repeats` times) and times each call.
template <class Work>
Timing time_repeated(Work&& work, double min_total, int max_repeats = 1000) {
  using clock = std::chrono::steady_clock;
  std::vector<double> times, cpu;
  double total = 0;
  do {
    const double cpu_start = thread_cpu_seconds();
    const auto start = clock::now();
    work();
    const double t = std::chrono::duration<double>(clock::now() - start).count();
    cpu.push_back(thread_cpu_seconds() - cpu_start);
    times.push_back(t);
    total += t;
  } while (total < min_total && static_cast<int>(times.size()) < max_repeats);
  Timing out;
  out.repeats = static_cast<int>(times.size());
  out.min_seconds = *std::min_element(times.begin(), times.end());
  out.median_seconds = median(times);
  out.cpu_median_seconds = median(cpu);
  return out;
}

/// Cost of one call, by the steady clock and by this thread's CPU time.
struct PerCall {
  double wall_ns = 0;
  double cpu_ns = 0;
};

/// Nanoseconds per call of `call(i)` for i = 0, 1, 2, ...: the median over `batches`
/// batches of calls, each batch running at least `min_batch` seconds.
template <class Call>
PerCall nanoseconds_per_call(Call&& call, double min_batch, int batches = 7) {
  using clock = std::chrono::steady_clock;
  std::vector<double> wall, cpu;
  std::size_t n = 1024;
  std::size_t i = 0;
  for (int b = 0; b < batches; ++b) {
    for (;;) {
      const double cpu_start = thread_cpu_seconds();
      const auto start = clock::now();
      for (std::size_t k = 0; k < n; ++k) call(i++);
      const double t = std::chrono::duration<double>(clock::now() - start).count();
      if (t >= min_batch || n > (std::size_t{1} << 34)) {
        wall.push_back(t * 1e9 / static_cast<double>(n));
        cpu.push_back((thread_cpu_seconds() - cpu_start) * 1e9 / static_cast<double>(n));
        break;
      }
      n *= 2;
    }
  }
  return {median(wall), median(cpu)};
}

}  // namespace linkage::bench
