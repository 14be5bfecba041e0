#pragma once
// States of the linkage. `State` holds the generalized coordinates of Cases 2 and 3
// (x1, y1, theta1, theta2 and their rates); `BodyState` holds the maximal coordinates
// of Case 1, both centres of mass and both angles, so it can drift off the pin.
#include "core/types.hpp"

namespace linkage {

struct State {
  double x1 = 1.0, y1 = 2.0, theta1 = 0.1, theta2 = 0.2;                      // m, m, rad, rad
  double x1_dot = 0.15, y1_dot = 0.25, theta1_dot = 0.35, theta2_dot = 0.45;  // m/s, rad/s

  /// (x1, y1, theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot)
  [[nodiscard]] Vec<8> vector() const {
    Vec<8> v;
    v << x1, y1, theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot;
    return v;
  }
  static State from_vector(const Vec<8>& v) { return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}; }
};

struct BodyState {
  double x1 = 0, y1 = 0, theta1 = 0, x2 = 0, y2 = 0, theta2 = 0;
  double x1_dot = 0, y1_dot = 0, theta1_dot = 0, x2_dot = 0, y2_dot = 0, theta2_dot = 0;

  /// (x1, y1, theta1, x2, y2, theta2, then the six rates in the same order)
  [[nodiscard]] Vec<12> vector() const {
    Vec<12> v;
    v << x1, y1, theta1, x2, y2, theta2, x1_dot, y1_dot, theta1_dot, x2_dot, y2_dot, theta2_dot;
    return v;
  }
  static BodyState from_vector(const Vec<12>& v) {
    return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]};
  }
  /// Block 1's coordinates and both angles, dropping x2 and y2.
  [[nodiscard]] State generalized() const { return {x1, y1, theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot}; }
};

}  // namespace linkage
