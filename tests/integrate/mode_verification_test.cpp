// modes --verify (integrate/mode_verification.cpp): the frequency of the full equations'
// motion started on each mode agrees with the linearization's to 1e-5 (issue 26) on the
// double and triple pendulums, the damped elastic pendulum, three coupled pendulums and
// the four-bar on a spring (its one mode through the loop);
// and the check does fail when the predicted frequency is off.
#include "integrate/mode_verification.hpp"

#include <gtest/gtest.h>

#include "model/mechanism_toml.hpp"

namespace linkage {
namespace {

std::vector<ModeCheck> checks_of(const Mechanism& m, std::size_t expected_modes) {
  const sym::System system(m);
  const Linearization linear = linearize(system);
  const ModalAnalysis modes = modal_analysis(linear);
  const std::vector<ModeCheck> checks = verify_modes(system, linear, modes);
  EXPECT_EQ(checks.size(), expected_modes);
  for (const ModeCheck& check : checks) {
    EXPECT_LE(check.relative_error(), 1e-5) << m.name << " mode " << check.mode + 1;
    EXPECT_GE(check.crossings, 9) << m.name;  // ten periods, upwards
  }
  return checks;
}

TEST(ModeVerification, ShippedExamplesAgreeWithTheirMotion) {
  (void)checks_of(load_mechanism("double-pendulum"), 2);
  (void)checks_of(load_mechanism("triple-pendulum"), 3);
  (void)checks_of(load_mechanism("coupled-pendulums"), 3);
  (void)checks_of(load_mechanism("four-bar-spring"), 1);
  // Damped: the bounce's crossings come at w sqrt(1 - zeta^2); the free turn is not checked.
  const std::vector<ModeCheck> elastic = checks_of(load_mechanism("spring-pendulum"), 2);
  EXPECT_LT(elastic.back().predicted, 10.0);
  EXPECT_NEAR(elastic.back().predicted / (10.0 * std::sqrt(1 - 0.0125 * 0.0125)), 1, 1e-12);
}

TEST(ModeVerification, AWrongFrequencyIsCaught) {
  const sym::System system(load_mechanism("double-pendulum"));
  const Linearization linear = linearize(system);
  ModalAnalysis modes = modal_analysis(linear);
  for (Mode& mode : modes.modes) mode.damped_omega *= 1 + 1e-4;  // predicted 1e-4 high
  for (const ModeCheck& check : verify_modes(system, linear, modes)) EXPECT_GT(check.relative_error(), 5e-5);
}

}  // namespace
}  // namespace linkage
