// Issue 27: the gear joint against the closed forms, in every case (a dense sample at the
// closed initial state; Case 3 by the structured solve and by the O(n) recursion with the
// mesh's loop row). Two discs on the ground in external mesh and a pinion in a ring gear
// with a torque tau on gear 1: th1'' = tau / (I1 + I2 (r1/r2)^2), th2'' = -s (r1/r2) th1''
// (s = +1 external, -1 internal), the tooth force F from gear 2's moment s r2 F = I2 th2'';
// gear 2's pin holds it against -F t and its weight. An epicyclic set (the arm the
// carrier): its constant mass matrix in (th_sun, th_arm) against the compiled rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "evaluate/mechanism_dynamics.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

// Round-off of a few operations on numbers of order 1 to 10.
constexpr double kClosed = 1e-12;

// Each case's sample at the closed initial state, with the accelerations; for Case 3 also
// the derivative by the O(n) recursion (unstructured) and by the structured solve.
template <typename Check>
void each_case(const sym::System& system, Check check) {
  const GiNaC::exmap state = sym::checked_initial_state(system).state;
  for (CaseId id : kAllCases)
    for (const bool structured : {true, false}) {
      eval::MechanismDynamics dynamics(system, id);
      dynamics.solve_by_structure(structured);
      const Eigen::VectorXd y = dynamics.initial_state(state);
      eval::MechanismSample s;
      dynamics.sample(0, y, s, true);
      check(s, "Case " + std::to_string(static_cast<int>(id) + 1) + (structured ? " structured" : " dense"));
    }
}

// Gear 1's angular acceleration from the derivative Case 3 integrates (its first rate).
double case3_acceleration(const sym::System& system, bool structured, const std::string& coordinate) {
  eval::MechanismDynamics reduced(system, CaseId::reduced);
  reduced.solve_by_structure(structured);
  const Eigen::VectorXd y = reduced.initial_state(sym::checked_initial_state(system).state);
  Eigen::VectorXd dydt;
  EXPECT_TRUE(reduced.derivative(0, y, dydt));
  const auto& names = reduced.coordinate_names();
  const auto at = std::find(names.begin(), names.end(), coordinate) - names.begin();
  return dydt[reduced.coordinates() + at];
}

TEST(JointGear, ExternalPairMatchesTheClosedForm) {
  const double r1 = 0.1, r2 = 0.25, m1 = 0.4, m2 = 1.5, tau = 0.3, g = 9.81;
  const double I1 = m1 * r1 * r1 / 2, I2 = m2 * r2 * r2 / 2, ratio = r1 / r2;
  const double a1 = tau / (I1 + I2 * ratio * ratio), a2 = -ratio * a1, F = I2 * a2 / r2;
  const sym::System system(built::gear_pair());
  each_case(system, [&](const eval::MechanismSample& s, const std::string& at) {
    EXPECT_NEAR(s.accelerations[2], a1, kClosed * a1) << at;
    EXPECT_NEAR(s.accelerations[5], a2, kClosed * a1) << at;
    // Joints P1, P2, G: G's force unknown after the three joints' x, y, moment.
    const double tooth = s.force[3 * 3 + 2 * 2];
    EXPECT_NEAR(tooth, F, kClosed) << at;
    EXPECT_NEAR(I1 * s.accelerations[2], tau + r1 * tooth, kClosed) << at;
    // t = k x e with e = +x: the tooth force on gear 1 is F along +y, on gear 2 -F along +y.
    EXPECT_NEAR(s.force[3 * 2], 0, kClosed) << at;
    EXPECT_NEAR(s.force[3 * 2 + 1], F, kClosed) << at;
    // Gear 2's centre is still: on it the pin's force, -F t and its weight balance; P2's
    // column is what gear 2 exerts on the ground, the opposite of the pin's force on it.
    EXPECT_NEAR(s.force[3 * 1], 0, kClosed) << at;
    EXPECT_NEAR(s.force[3 * 1 + 1], -F - m2 * g, kClosed) << at;
    EXPECT_NEAR(s.force[3 * 0 + 1], F - m1 * g, kClosed) << at;
    for (double c : s.constraint) EXPECT_LT(c, 1e-13) << at;
  });
  for (const bool structured : {true, false})
    EXPECT_NEAR(case3_acceleration(system, structured, "1.theta"), a1, kClosed * a1) << structured;
}

TEST(JointGear, InternalMeshMatchesTheClosedForm) {
  const double r1 = 0.1, r2 = 0.3, m1 = 0.3, m2 = 1.0, tau = 0.2;
  const double I1 = m1 * r1 * r1 / 2, I2 = m2 * r2 * r2, ratio = r1 / r2;  // a ring: m r^2
  const double a1 = tau / (I1 + I2 * ratio * ratio), a2 = ratio * a1, F = -I2 * a2 / r2;
  const sym::System system(built::ring_gear());
  each_case(system, [&](const eval::MechanismSample& s, const std::string& at) {
    EXPECT_NEAR(s.accelerations[2], a1, kClosed * a1) << at;
    EXPECT_NEAR(s.accelerations[5], a2, kClosed * a1) << at;
    EXPECT_NEAR(s.force[3 * 3 + 2 * 2], F, kClosed) << at;
    EXPECT_NEAR(I1 * s.accelerations[2], tau + r1 * s.force[3 * 3 + 2 * 2], kClosed) << at;
    // Both turn the same way: the ring at (r1/r2) of the pinion's rate.
    EXPECT_NEAR(s.rates[5], ratio * s.rates[2], kClosed) << at;
  });
  for (const bool structured : {true, false})
    EXPECT_NEAR(case3_acceleration(system, structured, "1.theta"), a1, kClosed * a1) << structured;
}

// Sun s, planet p on the arm a (the carrier), k = rs/rp: the planet turns at
// wp = (1 + k) wa - k ws, so in (th_s, th_a) the mass matrix is constant,
// [[Is + Ip k^2, -Ip k (1 + k)], [-Ip k (1 + k), Ia_O + mp L^2 + Ip (1 + k)^2]], and the
// torque tau on the arm gives (th_s'', th_a'') = M^-1 (0, tau).
TEST(JointGear, PlanetaryOnAMovingCarrierMatchesTheClosedForm) {
  const double rs = 0.12, rp = 0.06, ms = 0.8, mp = 0.2, ma = 0.3, L = 0.18, tau = 0.05, k = rs / rp;
  const double Is = ms * rs * rs / 2, Ip = mp * rp * rp / 2, Ia = ma * L * L / 3;
  const double m11 = Is + Ip * k * k, m12 = -Ip * k * (1 + k), m22 = Ia + mp * L * L + Ip * (1 + k) * (1 + k);
  const double det = m11 * m22 - m12 * m12;
  const double as = -m12 * tau / det, aa = m11 * tau / det, ap = (1 + k) * aa - k * as;
  const sym::System system(built::planetary_gears());
  each_case(system, [&](const eval::MechanismSample& s, const std::string& at) {
    EXPECT_NEAR(s.accelerations[2], as, kClosed * aa) << at;
    EXPECT_NEAR(s.accelerations[8], aa, kClosed * aa) << at;
    EXPECT_NEAR(s.accelerations[5], ap, kClosed * aa) << at;
    EXPECT_NEAR(s.rates[5], (1 + k) * s.rates[8] - k * s.rates[2], kClosed) << at;
  });
}

}  // namespace
}  // namespace linkage
