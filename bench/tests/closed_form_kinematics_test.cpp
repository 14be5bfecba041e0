#include <gtest/gtest.h>

#include <cmath>

#include "bench/closed_form/kinematics.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(Kinematics, DerivedValuesOfTheSpecExample) {
  const auto& want = test::spec_example()["derived"];
  const Derived d = derive(Params{}, State{});  // the defaults are the spec's example
  auto near = [](double got, const nlohmann::json& w, const char* name) {
    const double expected = w.get<double>();
    EXPECT_LE(std::fabs(got - expected), 1e-13 * std::fabs(expected)) << name << " got " << got;
  };
  near(d.I_zz_C, want["I_zz_C"], "I_zz_C");
  near(d.D, want["D"], "D");
  near(d.I_zz_P, want["I_zz_P"], "I_zz_P");
  near(d.pin.x(), want["x_P"], "x_P");
  near(d.pin.y(), want["y_P"], "y_P");
  near(d.C2.x(), want["x2"], "x2");
  near(d.C2.y(), want["y2"], "y2");
  near(d.C2_dot.x(), want["x2_dot"], "x2_dot");
  near(d.C2_dot.y(), want["y2_dot"], "y2_dot");
  near(d.invariants.kinetic_energy, want["kinetic_energy"], "kinetic_energy");
  near(d.invariants.potential_energy, want["potential_energy"], "potential_energy");
  near(d.invariants.energy, want["energy"], "energy");
  near(d.invariants.momentum.x(), want["momentum_x"], "momentum_x");
  near(d.invariants.momentum.y(), want["momentum_y"], "momentum_y");
  const double H = test::number(test::spec_reference()["states"][0]["angular_momentum"]);
  EXPECT_LE(std::fabs(d.invariants.angular_momentum - H), 1e-13 * H);
}

TEST(Kinematics, BodyStateSatisfiesTheConstraintExactly) {
  const Params p;
  const State s{0.3, -4.0, 2.5, -1.0, 3.0, -2.0, 17.0, -40.0};
  const ConstraintError e = constraint_error(p, body_state(p, s));
  EXPECT_LT(e.position.norm(), 1e-15);
  EXPECT_LT(e.velocity.norm(), 1e-13);
  BodyState drifted = body_state(p, s);
  drifted.x2 += 1e-3;
  drifted.y2_dot -= 2e-3;
  const ConstraintError d = constraint_error(p, drifted);
  EXPECT_NEAR(d.position.x(), 1e-3, 1e-15);
  EXPECT_NEAR(d.velocity.y(), -2e-3, 1e-13);
}

TEST(Kinematics, ParallelAxisTheorem) {
  Params p;
  p.L = 2.0;
  p.w = 1.0;
  p.m = 3.0;
  p.b = 0.25;
  EXPECT_DOUBLE_EQ(p.inertia_centroidal(), 3.0 * 5.0 / 12.0);
  EXPECT_DOUBLE_EQ(p.pin_offset(), 0.75);
  EXPECT_DOUBLE_EQ(p.inertia_about_pin(), 1.25 + 3.0 * 0.5625);
}

}  // namespace
}  // namespace linkage
