#pragma once
// An axis-aligned box in metres: what the fit camera frames and what a label must keep clear of.
#include "core/types.hpp"

namespace linkage {

struct Bounds {
  Vec2 min{1e300, 1e300};
  Vec2 max{-1e300, -1e300};
  void include(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  [[nodiscard]] bool empty() const { return min.x() > max.x(); }
};

}  // namespace linkage
