// Drivers (issue 25): a driver's row and its torque or force in every case. The sign of
// the torque and force against statics, the three cases (and Lagrange's form) against each
// other, the drivers' power against the energy balance, and a driven offset slider-crank's
// piston against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/energy.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using built::q;
using GiNaC::ex;

Driver driver(const std::string& name, const std::string& joint, const std::string& motion) {
  return {name, joint, q(motion), {}};
}

std::vector<CaseSystem> all_cases(const sym::System& system) {
  std::vector<CaseSystem> out;
  for (CaseId id : kAllCases) out.push_back(derive_case(system, id));
  out.push_back(lagrange_case(system));
  return out;
}

std::string case_name(const CaseSystem& c, std::size_t k) {
  return k == 3 ? std::string("Lagrange") : "Case " + std::to_string(case_number(c.id));
}

const sym::SymbolInfo& info(const sym::System& system, const std::string& key) {
  const sym::SymbolInfo* found = system.table().find(key);
  if (found == nullptr) throw std::logic_error("no symbol " + key);
  return *found;
}

double solved(const CaseSystem& c, const GiNaC::exmap& values, const GiNaC::symbol& u) {
  const CaseNumbers numbers = solve_numbers(c, values);
  const auto value = case_value(c, numbers, values, u);
  if (!value) throw std::logic_error("the case has no value for the unknown");
  return *value;
}

// The generalized state with `key` and its rate set.
GiNaC::exmap with(const sym::System& system, GiNaC::exmap state, const std::string& key, double value, double rate) {
  for (const sym::GeneralizedCoordinate& g : system.coordinates())
    if (g.coordinate.key == key) {
      state[g.symbols.q] = GiNaC::numeric(value);
      state[g.symbols.q_dot] = GiNaC::numeric(rate);
      return state;
    }
  throw std::logic_error("no coordinate " + key);
}

// A rod of length l hanging from the ground pin O2 at its end, held by M at th0.
Mechanism held_pendulum(bool reversed) {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"l", 0.3, {}}, {"m", 0.2, {}}, {"g", 9.81, {}}, {"th0", 0.3, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {built::rod("crank", "m", "l", {{"O", {"-l/2", "0"}}})};
  m.joints = {reversed ? built::pin("O2", "crank", "O", "ground", "O") : built::pin("O2", "ground", "O", "crank", "O")};
  m.drivers = {driver("M", "O2", reversed ? "-th0" : "th0")};
  m.initial = {{"crank.theta", 0.3, {}}};
  return m;
}

// The contract: M.torque is the torque on bodies[1], counter-clockwise positive. Gravity's
// moment about O on the rod at th0 is -m g (l/2) cos th0, so the motor on the rod gives
// +m g (l/2) cos th0; with bodies reversed the driver's torque is on the ground, the opposite.
TEST(Drivers, APinDriverHoldsAPendulumWithTheContractsSign) {
  for (const bool reversed : {false, true}) {
    const sym::System system(held_pendulum(reversed));
    const double expected = (reversed ? -1 : 1) * 0.2 * 9.81 * 0.15 * std::cos(0.3);
    const GiNaC::exmap values = state_values(system, with(system, system.initial_state(), "crank.theta", 0.3, 0), 0.7);
    const std::vector<CaseSystem> cases = all_cases(system);
    for (std::size_t k = 0; k < cases.size(); ++k) {
      EXPECT_NEAR(solved(cases[k], values, info(system, "M.torque").symbol), expected, 1e-12)
          << case_name(cases[k], k) << (reversed ? ", reversed" : "");
      EXPECT_NEAR(solved(cases[k], values, info(system, "crank.theta_ddot").symbol), 0, 1e-12)
          << case_name(cases[k], k);
    }
  }
}

// A block on a vertical rail (axis up, or down), held at s0 by M: the force along the
// axis on the block is +m g (axis up) or -m g (axis down).
TEST(Drivers, ASliderDriverHoldsABlockOnAVerticalRailWithTheContractsSign) {
  for (const double up : {1.0, -1.0}) {
    Mechanism m;
    m.gravity = q("g");
    m.parameters = {{"m", 0.7, {}}, {"g", 9.81, {}}};
    m.ground_points = {{"Q", {q("0.1"), q("0.2")}, {}}};
    m.bodies = {built::rectangle("block", "m", "0.1", "0.05", {{"C", {"0", "0"}}})};
    Joint rail = built::pin("rail", "ground", "Q", "block", "C");
    rail.type = JointType::slider;
    rail.axis = Vector2Quantity{q("0"), q(up > 0 ? "2" : "-2")};
    m.joints = {rail};
    m.drivers = {driver("M", "rail", "0.25")};
    m.initial = {{"rail.s", 0.25, {}}};
    const sym::System system(m);
    const GiNaC::exmap values = state_values(system, system.initial_state(), 0.4);
    const std::vector<CaseSystem> cases = all_cases(system);
    for (std::size_t k = 0; k < cases.size(); ++k) {
      EXPECT_NEAR(solved(cases[k], values, info(system, "M.force").symbol), up * 0.7 * 9.81, 1e-12)
          << case_name(cases[k], k) << ", axis " << up;
      EXPECT_NEAR(solved(cases[k], values, info(system, "block.y_ddot").symbol), 0, 1e-12) << case_name(cases[k], k);
    }
  }
}

// The driven mechanisms, each with the rate the driver's torque or force works on, written
// here from the geometry (not from the driver's row).
struct Driven {
  std::string name;
  Mechanism mechanism;
  std::string driver_unknown;  // "M.torque"
  std::string rate;            // the generalized or maximal rate it works on: "2.theta_dot"
};

std::vector<Driven> driven_mechanisms() {
  std::vector<Driven> out;
  Mechanism four_bar = built::four_bar();  // a damper at A and a torque on the coupler too
  four_bar.joints[1].damping = q("0.05");
  four_bar.torques = {{"3", q("0.2*sin(t)"), {}}};
  four_bar.drivers = {driver("M", "O2", "1 + 2*t + 0.3*t^2")};
  out.push_back({"four_bar", four_bar, "M.torque", "2.theta_dot"});
  Mechanism crank = built::slider_crank();
  crank.drivers = {driver("M", "O", "0.8 + 3*t")};
  out.push_back({"slider_crank_crank_driven", crank, "M.torque", "2.theta_dot"});
  // Driven at the piston: the travel s is 4.x (B at the piston's centre, Q at the origin, axis x).
  Mechanism piston = built::slider_crank();
  piston.drivers = {driver("P", "s", "0.4 + 0.05*sin(3*t)")};
  out.push_back({"slider_crank_piston_driven", piston, "P.force", "4.x_dot"});
  return out;
}

// Every case gives the same driver torque or force and joint forces, to 1e-10.
TEST(Drivers, TheCasesAgreeOnTheDriversAndJointForces) {
  for (const Driven& d : driven_mechanisms()) {
    const sym::System system(d.mechanism);
    std::vector<GiNaC::symbol> forces{info(system, d.driver_unknown).symbol};
    for (const sym::JointSystem& j : system.joints()) forces.insert(forces.end(), j.unknowns.begin(), j.unknowns.end());
    const std::vector<CaseSystem> cases = all_cases(system);
    std::mt19937 rng(2511);
    for (int k = 0; k < 4; ++k) {
      const double t = std::uniform_real_distribution<double>(0, 3)(rng);
      const GiNaC::exmap values = state_values(system, built::random_state(system, rng), t);
      std::vector<double> reference;
      for (const GiNaC::symbol& f : forces) reference.push_back(solved(cases[0], values, f));
      double scale = 0;
      for (double r : reference) scale = std::max(scale, std::abs(r));
      ASSERT_GT(scale, 1e-3);
      for (std::size_t c = 1; c < cases.size(); ++c)
        for (std::size_t i = 0; i < forces.size(); ++i)
          EXPECT_NEAR(solved(cases[c], values, forces[i]), reference[i], 1e-10 * scale)
              << d.name << ", " << case_name(cases[c], c) << ", " << forces[i] << ", state " << k;
    }
  }
}

// dT/dt + dV/dt = P + the drivers' power (torque times the relative rate, force times the
// travel's rate), P the dampers' and applied loads' power: the drivers' unknown checked
// against the energy, at random states, in every case, to 1e-10 relative.
TEST(Drivers, TheDriversPowerBalancesTheEnergy) {
  for (const Driven& d : driven_mechanisms()) {
    const sym::System system(d.mechanism);
    const ex T_rate = system.time_derivative(sym::kinetic_energy(system));
    const ex V_rate = system.time_derivative(sym::potential_energy(system));
    const ex P = sym::nonconservative_power(system);
    const ex driver_power = info(system, d.driver_unknown).symbol * info(system, d.rate).symbol;
    const std::vector<CaseSystem> cases = all_cases(system);
    std::mt19937 rng(1125);
    for (int k = 0; k < 4; ++k) {
      const double t = std::uniform_real_distribution<double>(0, 3)(rng);
      const GiNaC::exmap values = state_values(system, built::random_state(system, rng), t);
      for (std::size_t c = 0; c < cases.size(); ++c) {
        const CaseNumbers numbers = solve_numbers(cases[c], values);
        GiNaC::exmap all = values;
        for (const sym::SymbolInfo& s : system.table().all())
          if (s.role == sym::Role::acceleration || s.role == sym::Role::force)
            if (const auto v = case_value(cases[c], numbers, values, s.symbol)) all[s.symbol] = GiNaC::numeric(*v);
        const double dT = value_at(T_rate, all), dV = value_at(V_rate, all), p = value_at(P, all);
        const double driven = value_at(driver_power, all);
        const double scale = std::abs(dT) + std::abs(dV) + std::abs(p) + std::abs(driven);
        ASSERT_GT(std::abs(driven), 1e-2 * scale) << d.name << ": the driver must do real work here";
        EXPECT_NEAR(dT + dV, p + driven, 1e-10 * scale) << d.name << ", " << case_name(cases[c], c) << ", state " << k;
      }
    }
  }
}

// An offset slider-crank (the rail's line y = e) driven at th(t) = 0.3 + 2 t + 0.5 t^2:
// with the crank on its motion and the loop closed, the piston's x and x' are the closed
// form's x = r cos th + sqrt(l^2 - (r sin th - e)^2), and every case's x'' is its second
// time derivative (written here in GiNaC from the closed form alone).
TEST(Drivers, AnOffsetSliderCrankPistonFollowsTheClosedForm) {
  Mechanism m = built::slider_crank();
  m.parameters.push_back({"e", 0.04, {}});
  m.ground_points[1] = {"Q", {q("0"), q("e")}, {}};
  m.drivers = {driver("M", "O", "0.3 + 2*t + 0.5*t^2")};
  m.initial = {{"2.theta", 0.3, {}}, {"3.theta", -0.1, {}}, {"s.s", 0.44, {}}};
  const sym::System system(m);
  const std::vector<CaseSystem> cases = all_cases(system);

  const GiNaC::symbol T("T");
  const ex th = 0.3 + 2 * T + ex(1) / 2 * T * T;
  const double r = 0.1, l = 0.35, e = 0.04;
  const ex x = r * GiNaC::cos(th) + GiNaC::sqrt(l * l - GiNaC::pow(r * GiNaC::sin(th) - e, 2));
  const GiNaC::symbol& px = info(system, "4.x").symbol;
  const GiNaC::symbol& px_dot = info(system, "4.x_dot").symbol;
  const GiNaC::symbol& px_ddot = info(system, "4.x_ddot").symbol;
  for (const double t : {0.0, 0.35, 1.1, 2.4}) {
    const auto at = [&](const ex& f) { return sym::to_double(f.subs(T == t)); };
    GiNaC::exmap state = with(system, system.initial_state(), "2.theta", at(th), at(th.diff(T)));
    state = sym::close_loops(system, state, t).state;  // the crank stays on its motion at t
    const GiNaC::exmap values = state_values(system, state, t);
    EXPECT_NEAR(value_at(px, values), at(x), 1e-12) << "t = " << t;
    EXPECT_NEAR(value_at(px_dot, values), at(x.diff(T)), 1e-12) << "t = " << t;
    for (std::size_t c = 0; c < cases.size(); ++c)
      EXPECT_NEAR(solved(cases[c], values, px_ddot), at(x.diff(T, 2)), 1e-10)
          << case_name(cases[c], c) << ", t = " << t;
  }
}

}  // namespace
}  // namespace linkage
