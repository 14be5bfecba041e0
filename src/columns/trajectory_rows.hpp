#pragma once
// The row times of a trajectory table (`linkage simulate --every`, a lesson's simulate
// step): t = k every from 0, with the duration itself as the last row, once, when every
// divides it to 1e-9.
#include <algorithm>
#include <cmath>

namespace linkage {

struct TrajectoryRows {
  TrajectoryRows(double duration_s, double every_s) : duration(duration_s), every(every_s) {
    const double ratio = duration / every;
    const double nearest = std::round(ratio);
    const bool divides = std::fabs(ratio - nearest) <= 1e-9 * std::max(1.0, ratio);
    count = static_cast<long>(divides ? nearest : std::floor(ratio) + 1) + 1;
  }
  [[nodiscard]] double at(long i) const { return i + 1 == count ? duration : static_cast<double>(i) * every; }

  double duration, every;
  long count = 0;
};

}  // namespace linkage
