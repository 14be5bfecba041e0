#pragma once
// The motion a clip shows: the state at every frame time (and the pin force when
// force arrows are drawn), sampled once before drawing. Knowing the whole clip first
// lets arrow scales come from the largest magnitude over the clip and lets the fit
// camera frame the whole motion.
#include <array>
#include <functional>
#include <vector>

#include "core/types.hpp"
#include "model/kinematics.hpp"  // system_com, used with the motion
#include "model/params.hpp"
#include "model/state.hpp"
#include "scene/draw_list.hpp"

namespace linkage {

class Simulation;

struct MotionSample {
  double t = 0;  // s
  BodyState state;
  Vec2 pin_force = Vec2::Zero();  // N, on block 1 at P; zero unless Motion::has_pin_force
};

struct Motion {
  std::vector<MotionSample> samples;  // increasing t
  bool has_pin_force = false;
  double energy0 = 0;       // J, at t = 0
  double energy_scale = 1;  // J, model/kinematics.hpp energy_scale at t = 0

  /// Sets energy0 and energy_scale from the state at t = 0.
  void set_energy_reference(const Params& p, const BodyState& initial);
};

/// Samples `sim` at `times` (non-decreasing, within the simulation's duration); solves
/// for the pin force only when `pin_force` is true (Simulation::dynamics is not called
/// otherwise). Polls Ctrl-C between samples; `progress(j)` (if set) after sample j.
[[nodiscard]] Motion sample_motion(Simulation& sim, const std::vector<double>& times, bool pin_force,
                                   const std::function<void(long)>& progress = {});

/// The four corners of a block of the given size, centred at (x, y), turned by theta,
/// counter-clockwise.
[[nodiscard]] std::array<Vec2, 4> block_corners(const Params& p, double x, double y, double theta);

/// An axis-aligned box in metres.
struct Bounds {
  Vec2 min{1e300, 1e300};
  Vec2 max{-1e300, -1e300};
  void include(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  [[nodiscard]] bool empty() const { return min.x() > max.x(); }
};

/// Every block corner over the whole motion (the fit camera).
[[nodiscard]] Bounds motion_bounds(const Params& p, const Motion& motion);
/// The largest distance of a block corner from G over the motion (the follow camera).
[[nodiscard]] double max_radius_about_com(const Params& p, const Motion& motion);

/// The largest magnitude of each arrow kind over the motion, indexed by ArrowKind: pin
/// force (N, zero unless sampled), gravity m g (N), centre-of-mass speed (m/s; relative
/// to G when `relative_to_com`).
[[nodiscard]] std::array<double, kArrowKinds> arrow_maxima(const Params& p, const Motion& motion, bool relative_to_com);

/// What the HUD reports at a sample.
struct SampleErrors {
  double energy = 0;      // (E - E0) / energy scale, relative
  double constraint = 0;  // m, |C| of the pin constraint (Case 1 drift; round-off otherwise)
};
[[nodiscard]] SampleErrors sample_errors(const Params& p, const Motion& motion, std::size_t index);

}  // namespace linkage
