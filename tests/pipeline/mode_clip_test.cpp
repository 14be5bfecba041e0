// A mode drawn about the equilibrium (`render --mode`, issue 26): the linear motion is
// prescribed, q0 + A shape cos(w t), and every pose comes from it; the nonlinear one starts
// on the displaced equilibrium with its loops closed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/mode_motion.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

struct Modes {
  explicit Modes(const char* name)
      : system(load_mechanism(name)), linear(linearize(system)), modes(modal_analysis(linear)) {}
  sym::System system;
  Linearization linear;
  ModalAnalysis modes;
};

TEST(ModeClip, TheLinearMotionsPosesAreTheEquilibriumPlusTheShapeTimesCosine) {
  const Modes m("double-pendulum");
  ASSERT_EQ(m.modes.modes.size(), 2U);
  const double amplitude = 0.1;
  const ModeMotion motion = mode_motion(m.system, m.linear, m.modes, 2, amplitude, false);
  ASSERT_TRUE(motion.prescribed);
  const Mode& mode = m.modes.modes[1];
  EXPECT_NEAR(motion.displacement.cwiseAbs().maxCoeff(), amplitude, 1e-15);
  const double w = mode.damped_omega;
  const double scale = amplitude / mode.tree_shape.cwiseAbs().maxCoeff();
  SimulationOptions options;
  options.duration = 2.0;
  std::vector<double> times;
  for (int k = 0; k <= 50; ++k) times.push_back(0.04 * k);
  ClipResult result;
  const MechanismMotion drawn = sample_mechanism_motion(m.system, motion.initial, options, times, 4, result, {}, {},
                                                        nullptr, {}, true, motion.prescribed);
  EXPECT_TRUE(drawn.prescribed);
  EXPECT_TRUE(drawn.energy_error.empty());
  EXPECT_TRUE(result.warnings.empty());
  // The rods' angles are the tree coordinates 1.theta, 2.theta (absolute): pose 3 b + 2.
  for (std::size_t k = 0; k < times.size(); ++k)
    for (Eigen::Index i = 0; i < 2; ++i) {
      const double expected = m.linear.equilibrium[i] + scale * mode.tree_shape[i] * std::cos(w * times[k]);
      EXPECT_NEAR(drawn.samples[k].pose[3 * static_cast<std::size_t>(i) + 2], expected, 1e-12)
          << "t = " << times[k] << ", coordinate " << i;
    }
  // The anti-phase mode: the rods turn opposite ways.
  EXPECT_LT(mode.tree_shape[0] * mode.tree_shape[1], 0);
  // A trail's poses between frames come from the same motion.
  ASSERT_GT(drawn.trail_times.size(), times.size());
  for (std::size_t j = 0; j < drawn.trail_times.size(); ++j) {
    const double t = drawn.trail_times[j];
    EXPECT_NEAR(drawn.trail_poses[j][5], m.linear.equilibrium[1] + scale * mode.tree_shape[1] * std::cos(w * t), 1e-12);
  }
}

TEST(ModeClip, TheNonlinearClipStartsOnTheDisplacedClosedState) {
  for (const char* name : {"double-pendulum", "four-bar-spring"}) {
    SCOPED_TRACE(name);
    const auto m = std::make_unique<Modes>(name);
    const ModeMotion motion = mode_motion(m->system, m->linear, m->modes, 1, 0.05, true);
    EXPECT_FALSE(motion.prescribed);
    // The state it starts from: q0 + displacement, closed again (a tree keeps it exactly).
    const auto& coordinates = m->system.coordinates();
    GiNaC::exmap start;
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
      start[coordinates[i].symbols.q] =
          motion.equilibrium[static_cast<Eigen::Index>(i)] + motion.displacement[static_cast<Eigen::Index>(i)];
      start[coordinates[i].symbols.q_dot] = 0;
    }
    const GiNaC::exmap closed = sym::close_loops(m->system, start).state;
    SimulationOptions options;
    options.duration = 0.1;
    ClipResult result;
    const MechanismMotion drawn = sample_mechanism_motion(m->system, motion.initial, options, {0.0, 0.1}, 1, result);
    const MechanismMotion expected = sample_mechanism_motion(m->system, closed, options, {0.0}, 1, result);
    ASSERT_EQ(drawn.samples[0].pose.size(), expected.samples[0].pose.size());
    for (std::size_t i = 0; i < drawn.samples[0].pose.size(); ++i)
      EXPECT_NEAR(drawn.samples[0].pose[i], expected.samples[0].pose[i], 1e-12);
    EXPECT_FALSE(drawn.energy_error.empty());
    for (const double rate : drawn.samples[0].rates) EXPECT_NEAR(rate, 0, 1e-12);
  }
  // The double pendulum's tree: the first pose is the displaced equilibrium itself.
  const Modes m("double-pendulum");
  const ModeMotion motion = mode_motion(m.system, m.linear, m.modes, 1, 0.1, true);
  SimulationOptions options;
  options.duration = 0.1;
  ClipResult result;
  const MechanismMotion drawn = sample_mechanism_motion(m.system, motion.initial, options, {0.0}, 1, result);
  for (Eigen::Index i = 0; i < 2; ++i)
    EXPECT_NEAR(drawn.samples[0].pose[3 * static_cast<std::size_t>(i) + 2],
                m.linear.equilibrium[i] +
                    0.1 * m.modes.modes[0].tree_shape[i] / m.modes.modes[0].tree_shape.cwiseAbs().maxCoeff(),
                1e-12);
}

TEST(ModeClip, TheHudSaysWhatIsShown) {
  const Modes m("double-pendulum");
  const double hz = m.modes.modes[0].damped_omega / (2 * std::numbers::pi);
  EXPECT_EQ(mode_motion(m.system, m.linear, m.modes, 1, 0.1, false).hud,
            "mode 1 \u00b7 linear, " + format_significant(hz, 3) + " Hz");
  EXPECT_EQ(mode_motion(m.system, m.linear, m.modes, 1, 0.1, true).hud, "mode 1 \u00b7 nonlinear, A = 0.1 rad");
  const std::string caption = mode_motion(m.system, m.linear, m.modes, 2, 0.2, false).caption;
  EXPECT_NE(caption.find("Mode 2 of 2"), std::string::npos) << caption;
  EXPECT_NE(caption.find("amplitude 0.2 rad"), std::string::npos) << caption;
  EXPECT_NE(caption.find(format_significant(m.modes.modes[1].damped_omega / (2 * std::numbers::pi), 3) + " Hz"),
            std::string::npos)
      << caption;
  // No energy balance in the draw list of a prescribed motion; the simulated one keeps it.
  for (const bool nonlinear : {false, true}) {
    const ModeMotion motion = mode_motion(m.system, m.linear, m.modes, 1, 0.1, nonlinear);
    SimulationOptions options;
    options.duration = 0.1;
    ClipResult result;
    const MechanismMotion drawn = sample_mechanism_motion(m.system, motion.initial, options, {0.0, 0.1}, 1, result, {},
                                                          {}, nullptr, {}, false, motion.prescribed);
    const MechanismScene scene(mechanism_geometry(m.system), drawn, {}, 2.0, {}, ElementSet::defaults());
    MechanismDrawList list;
    scene.frame(1, list);
    EXPECT_EQ(list.hud.energy, nonlinear);
  }
}

TEST(ModeClip, AModeOutOfRangeOrNotOscillatingAndABadAmplitudeAreRefused) {
  const Modes m("double-pendulum");
  const auto message = [&](int n, double a) {
    try {
      (void)mode_motion(m.system, m.linear, m.modes, n, a, false);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(3, 0.1).find("has 2 modes: 2 oscillations; valid: 1 to 2"), std::string::npos) << message(3, 0.1);
  EXPECT_NE(message(0, 0.1).find("valid: 1 to 2"), std::string::npos);
  EXPECT_NE(message(1, 0).find("amplitude"), std::string::npos);
  EXPECT_NE(message(1, -1).find("> 0"), std::string::npos);
  EXPECT_NE(message(1, std::nan("")).find("> 0"), std::string::npos);
}

}  // namespace
}  // namespace linkage
