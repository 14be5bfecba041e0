// The MuJoCo peer models the same physics as ours: the chain's MJCF loads, and the
// double pendulum's accelerations agree with a closed-form double compound pendulum
// written out here by hand; RK4 stepping conserves its energy.
#if LINKAGE_PEER_MUJOCO
#include "bench/peer_mujoco.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace linkage::bench {
namespace {

struct Accelerations {
  double alpha1, alpha2;  // absolute, rad/s^2
};

// Two uniform rods hinged in series, rod 1 pivoted at its end O, angles counter-
// clockwise from +x, gravity along -y. With e(th) = (cos th, sin th), e'(th) =
// (-sin th, cos th) and c = cos(th1 - th2), s = sin(th1 - th2):
//   v_c2 = L1 w1 e'(th1) + (L2/2) w2 e'(th2),
//   T = 1/2 (m1 L1^2/3) w1^2 + 1/2 m2 |v_c2|^2 + 1/2 (m2 L2^2/12) w2^2,
//   |v_c2|^2 = L1^2 w1^2 + L2^2/4 w2^2 + L1 L2 w1 w2 c,
//   V = m1 g (L1/2) sin th1 + m2 g (L1 sin th1 + (L2/2) sin th2).
// Lagrange's equations, with k = m2 L1 L2 / 2:
//   (m1/3 + m2) L1^2 a1 + k c a2 = -k s w2^2 - (m1/2 + m2) g L1 cos th1
//   k c a1 + (m2 L2^2/3) a2      =  k s w1^2 - m2 g (L2/2) cos th2
Accelerations closed_form(const DoublePendulumSpec& p) {
  const double c = std::cos(p.theta1 - p.theta2), s = std::sin(p.theta1 - p.theta2);
  const double k = p.m2 * p.L1 * p.L2 / 2;
  const double M11 = (p.m1 / 3 + p.m2) * p.L1 * p.L1;
  const double M12 = k * c;
  const double M22 = p.m2 * p.L2 * p.L2 / 3;
  const double r1 = -k * s * p.omega2 * p.omega2 - (p.m1 / 2 + p.m2) * p.g * p.L1 * std::cos(p.theta1);
  const double r2 = k * s * p.omega1 * p.omega1 - p.m2 * p.g * (p.L2 / 2) * std::cos(p.theta2);
  const double det = M11 * M22 - M12 * M12;
  return {(M22 * r1 - M12 * r2) / det, (M11 * r2 - M12 * r1) / det};
}

double energy(const DoublePendulumSpec& p) {
  const double v2 = p.L1 * p.L1 * p.omega1 * p.omega1 + p.L2 * p.L2 / 4 * p.omega2 * p.omega2 +
                    p.L1 * p.L2 * p.omega1 * p.omega2 * std::cos(p.theta1 - p.theta2);
  const double T = 0.5 * (p.m1 * p.L1 * p.L1 / 3) * p.omega1 * p.omega1 + 0.5 * p.m2 * v2 +
                   0.5 * (p.m2 * p.L2 * p.L2 / 12) * p.omega2 * p.omega2;
  const double V = p.m1 * p.g * (p.L1 / 2) * std::sin(p.theta1) +
                   p.m2 * p.g * (p.L1 * std::sin(p.theta1) + (p.L2 / 2) * std::sin(p.theta2));
  return T + V;
}

/// MuJoCo's absolute accelerations at the spec's state (qpos relative, see the header).
Accelerations mujoco_accelerations(const DoublePendulumSpec& p) {
  const MujocoModel model = load_mjcf(double_pendulum_mjcf(p));
  const MujocoData data = make_data(*model);
  data->qpos[0] = p.theta1;
  data->qpos[1] = p.theta2 - p.theta1;
  data->qvel[0] = p.omega1;
  data->qvel[1] = p.omega2 - p.omega1;
  mj_forward(model.get(), data.get());
  return {data->qacc[0], data->qacc[0] + data->qacc[1]};
}

void expect_relative(double actual, double expected, double tolerance) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected))
      << "actual " << actual << ", expected " << expected;
}

// Unequal rods and a generic state, so a wrong inertia, frame or sign cannot cancel.
DoublePendulumSpec generic_state() {
  return {.L1 = 0.3,
          .L2 = 0.45,
          .m1 = 0.1,
          .m2 = 0.25,
          .g = 9.81,
          .theta1 = 0.7,
          .theta2 = -1.9,
          .omega1 = 1.3,
          .omega2 = -2.1};
}

TEST(MujocoPeer, ChainLoadsAndHasFiniteAccelerations) {
  for (const int links : {2, 8, 64}) {
    SCOPED_TRACE(links);
    const MujocoModel model = load_mjcf(pendulum_chain_mjcf({.links = links}));
    ASSERT_EQ(model->nq, links);
    ASSERT_EQ(model->nv, links);
    EXPECT_EQ(model->nbody, links + 1);  // and the world
    const MujocoData data = make_data(*model);
    for (int k = 0; k < links; ++k) {
      data->qpos[k] = 0.1 * (k % 5) - 0.2;
      data->qvel[k] = 0.3 * (k % 3) - 0.3;
    }
    mj_forward(model.get(), data.get());
    for (int k = 0; k < links; ++k) EXPECT_TRUE(std::isfinite(data->qacc[k])) << "qacc[" << k << "]";
  }
}

TEST(MujocoPeer, RejectedModelIsAnErrorWithMujocosReason) {
  try {
    (void)load_mjcf("<mujoco><worldbody><body><joint type=\"bogus\"/></body></worldbody></mujoco>");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::failure);
    const std::string what = e.what();
    EXPECT_NE(what.find("MuJoCo rejected the model: "), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(MujocoPeer, DoublePendulumAccelerationsMatchTheClosedForm) {
  const DoublePendulumSpec moving = generic_state();
  DoublePendulumSpec at_rest = moving;
  at_rest.omega1 = at_rest.omega2 = 0;
  DoublePendulumSpec equal = moving;
  equal.L2 = equal.L1;
  equal.m2 = equal.m1;
  for (const DoublePendulumSpec& p : {moving, at_rest, equal}) {
    const Accelerations expected = closed_form(p);
    const Accelerations actual = mujoco_accelerations(p);
    expect_relative(actual.alpha1, expected.alpha1, 1e-10);
    expect_relative(actual.alpha2, expected.alpha2, 1e-10);
  }
}

TEST(MujocoPeer, EqualRodChainIsTheDoublePendulum) {
  const DoublePendulumSpec p{.theta1 = -0.4, .theta2 = 2.2, .omega1 = 0.5, .omega2 = 3.0};
  const MujocoModel model = load_mjcf(pendulum_chain_mjcf({.links = 2, .length = p.L1, .mass = p.m1, .g = p.g}));
  const MujocoData data = make_data(*model);
  data->qpos[0] = p.theta1;
  data->qpos[1] = p.theta2 - p.theta1;
  data->qvel[0] = p.omega1;
  data->qvel[1] = p.omega2 - p.omega1;
  mj_forward(model.get(), data.get());
  const Accelerations expected = closed_form(p);
  expect_relative(data->qacc[0], expected.alpha1, 1e-10);
  expect_relative(data->qacc[0] + data->qacc[1], expected.alpha2, 1e-10);
}

TEST(MujocoPeer, Rk4ConservesTheEnergy) {
  const DoublePendulumSpec start = generic_state();
  const MujocoRun run = mujoco_double_pendulum(start, mjINT_RK4, 1e-4, 1.0);
  EXPECT_EQ(run.steps, 10'000);
  EXPECT_GT(run.seconds, 0);
  DoublePendulumSpec end = start;
  end.theta1 = run.theta1;
  end.theta2 = run.theta2;
  end.omega1 = run.omega1;
  end.omega2 = run.omega2;
  // It moved: the check is not of a state at rest.
  EXPECT_GT(std::abs(run.theta1 - start.theta1) + std::abs(run.theta2 - start.theta2), 0.1);
  const double e0 = energy(start);
  ASSERT_GT(std::abs(e0), 0.1);  // J: the relative measure is of a real size
  EXPECT_LE(std::abs(energy(end) - e0), 1e-8 * std::abs(e0)) << "E(0) " << e0 << ", E(1 s) " << energy(end);
}

// MuJoCo's Euler updates the velocity first and moves the position with the new one.
// With a configuration-dependent mass matrix that is not symplectic: it loses energy at
// first order (about -52% of E(0) after 1 s at dt = 1 ms here, -6% at 0.1 ms).
TEST(MujocoPeer, EulerIsSemiImplicitInVelocity) {
  const DoublePendulumSpec start = generic_state();
  constexpr double dt = 1e-3;
  const MujocoRun run = mujoco_double_pendulum(start, mjINT_EULER, dt, 1.0);
  ASSERT_EQ(run.steps, 1000);
  DoublePendulumSpec ours = start;
  for (long i = 0; i < run.steps; ++i) {
    const Accelerations a = closed_form(ours);
    ours.omega1 += dt * a.alpha1;
    ours.omega2 += dt * a.alpha2;
    ours.theta1 += dt * ours.omega1;
    ours.theta2 += dt * ours.omega2;
  }
  expect_relative(run.theta1, ours.theta1, 1e-9);
  expect_relative(run.theta2, ours.theta2, 1e-9);
  expect_relative(run.omega1, ours.omega1, 1e-9);
  expect_relative(run.omega2, ours.omega2, 1e-9);
  EXPECT_LT(energy(ours), 0.9 * energy(start));
}

TEST(MujocoPeer, RejectsOtherIntegratorsAndSteps) {
  EXPECT_THROW((void)mujoco_double_pendulum(generic_state(), mjINT_IMPLICIT, 1e-3, 0.1), Error);
  EXPECT_THROW((void)mujoco_double_pendulum(generic_state(), mjINT_RK4, 0.0, 0.1), Error);
  EXPECT_THROW((void)pendulum_chain_mjcf({.links = 0}), Error);
}

}  // namespace
}  // namespace linkage::bench
#endif
