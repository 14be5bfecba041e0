#pragma once
// Fixed-size Eigen aliases used across modules. Every known dimension is fixed.
#include <Eigen/Core>

namespace linkage {

using Vec2 = Eigen::Vector2d;
template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int R, int C = R>
using Mat = Eigen::Matrix<double, R, C, (C == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;

}  // namespace linkage
