#pragma once
// MuJoCo peer (Debian's libmujoco-dev 2.2.2): the same planar pendulum physics as ours
// written as MJCF, for timing MuJoCo's forward dynamics and stepping against ours.
// Built only when CMake found MuJoCo (LINKAGE_PEER_MUJOCO is then 1).
//
// Frames: our tool is planar in x-y, gravity along -y, angles counter-clockwise about
// +z. The MJCF keeps that: hinge axes along z, gravity (0, -g, 0), each rod along its
// body's x axis from the joint, so a joint angle of 0 puts the rod along +x.
//
// Angles: MuJoCo's qpos of a hinge chain holds each link's angle RELATIVE to its
// parent; the absolute angle of link k (0-based) is theta_k = q_0 + ... + q_k, and its
// rate omega_k = qvel_0 + ... + qvel_k. Conversely q_0 = theta_0, q_k = theta_k -
// theta_{k-1}.
#include <memory>
#include <string>

struct mjModel_;
struct mjData_;

namespace linkage::bench {

/// A chain of `links` uniform slender rods hanging from a ground pin, all alike.
struct ChainSpec {
  int links = 2;
  double length = 0.3;  // m, each rod
  double mass = 0.1;    // kg, each rod
  double g = 9.81;      // m/s^2, along -y
};

/// The MJCF of the chain: link k+1 is pinned to the far end of link k (pos "L 0 0"),
/// explicit inertia m L^2/12 about the centre for the planar axis, no contacts,
/// damping, armature or limits. Throws Error::invalid for links < 1 or a non-positive
/// length or mass.
[[nodiscard]] std::string pendulum_chain_mjcf(const ChainSpec& spec);

struct MujocoModelDeleter {
  void operator()(mjModel_* m) const noexcept;
};
struct MujocoDataDeleter {
  void operator()(mjData_* d) const noexcept;
};
using MujocoModel = std::unique_ptr<mjModel_, MujocoModelDeleter>;
using MujocoData = std::unique_ptr<mjData_, MujocoDataDeleter>;

/// Compiles MJCF text (in memory, no file). Throws Error::failure with MuJoCo's
/// message when it rejects the model.
[[nodiscard]] MujocoModel load_mjcf(const std::string& xml);
/// mj_makeData for `model`; throws Error::failure when MuJoCo cannot allocate it.
[[nodiscard]] MujocoData make_data(const mjModel_& model);

/// Nanoseconds per mj_forward on the `links`-link chain at a fixed pseudo-random state
/// (a fixed seed): the median of 7 batches after a warm-up, about `seconds_budget` s
/// in all, by this thread's CPU time (the wall clock swings with the machine's load).
[[nodiscard]] double mujoco_forward_ns(int links, double seconds_budget);

/// Two rods hinged in series from a ground pin, and their initial state in ABSOLUTE
/// angles (counter-clockwise from +x).
struct DoublePendulumSpec {
  double L1 = 0.3, L2 = 0.3;      // m
  double m1 = 0.1, m2 = 0.1;      // kg
  double g = 9.81;                // m/s^2, along -y
  double theta1 = 0, theta2 = 0;  // rad
  double omega1 = 0, omega2 = 0;  // rad/s
};

/// The MJCF of the two rods (as pendulum_chain_mjcf, with rods of their own sizes).
[[nodiscard]] std::string double_pendulum_mjcf(const DoublePendulumSpec& spec);

/// The state at t_end in ABSOLUTE angles and rates, and the cost of getting there.
struct MujocoRun {
  double theta1 = 0, theta2 = 0;  // rad
  double omega1 = 0, omega2 = 0;  // rad/s
  double seconds = 0;             // the mj_step loop alone, this thread's CPU time
  long steps = 0;                 // round(t_end / dt)
};

/// Steps the double pendulum with mj_step at timestep `dt` from t = 0 to t_end.
/// `integrator` is mjINT_RK4 (a full classical RK4 step per mj_step, 4 evaluations of
/// the dynamics) or mjINT_EULER (MuJoCo's Euler is semi-implicit: the velocity is
/// updated first and the position with the new velocity). Throws Error::invalid for
/// another integrator or a non-positive dt, Error::diverged when the state leaves the
/// finite numbers (MuJoCo would reset it silently).
[[nodiscard]] MujocoRun mujoco_double_pendulum(const DoublePendulumSpec& spec, int integrator, double dt, double t_end);

}  // namespace linkage::bench
