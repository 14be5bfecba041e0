// Bad mechanisms found by the symbolic layer: each a one-line error with the file
// position, the value and the valid range.
#include "symbolic/validate.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "core/error.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

Quantity q(const std::string& text, long line = 0) { return {text, {"m.toml", line, 9}}; }

// A pendulum rod hanging from ground point O, and optionally a second pin at the same place.
Mechanism pendulum(const std::string& mass = "m", const std::string& length = "L") {
  Mechanism m;
  m.source = "m.toml";
  m.gravity = q("g");
  m.parameters = {{"L", 0.3, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  Body rod;
  rod.name = "1";
  rod.shape = Shape::rod;
  rod.mass = q(mass, 7);
  rod.length = q(length, 8);
  rod.points = {{"O", {q("-L/2"), q("0")}, {}}};
  m.bodies = {rod};
  Joint pin;
  pin.name = "O";
  pin.bodies = {"ground", "1"};
  pin.points = {"O", "O"};
  pin.pos = {"m.toml", 12, 1};
  m.joints = {pin};
  m.initial = {{"1.theta", -1.0, {}}};
  return m;
}

std::string error_of(const Mechanism& m) {
  try {
    const sym::System system(m);
    sym::validate_quantities(system);
    sym::validate_constraints(system, system.initial_state());
    sym::validate_constraints(system, sym::close_loops(system, system.initial_state()).state);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

TEST(Validate, AGoodPendulumPasses) { EXPECT_EQ(error_of(pendulum()), ""); }

TEST(Validate, UnknownSymbolNamesTheValidOnes) {
  EXPECT_EQ(error_of(pendulum("mass")),
            "m.toml:7:9: unknown name 'mass' at character 1 of 'mass'; valid: L, g, m (t only in [[force]] and "
            "[[torque]] values)");
}

TEST(Validate, NonPositiveMassAtTheParameters) {
  EXPECT_EQ(error_of(pendulum("m - 0.2")),
            "m.toml:7:9: mass of body 1 \"m - 0.2\" is -0.1 at the parameters; valid: > 0");
}

TEST(Validate, DivisionByZero) {
  const std::string e = error_of(pendulum("m", "L/(L - 0.3)"));
  EXPECT_NE(e.find("m.toml:8:9: "), std::string::npos) << e;
  EXPECT_NE(e.find("L/(L - 0.3)"), std::string::npos) << e;
}

TEST(Validate, ARedundantJointIsNamed) {
  Mechanism m = pendulum();
  Joint again = m.joints[0];
  again.name = "O2";
  again.pos = {"m.toml", 20, 1};
  m.joints.push_back(again);
  const std::string e = error_of(m);
  EXPECT_NE(e.find("m.toml:20:1: joint O2 is redundant"), std::string::npos) << e;
  EXPECT_NE(e.find("joints O"), std::string::npos) << e;
}

TEST(Validate, ASliderOnAPointMassIsRefused) {
  Mechanism m = pendulum();
  Body bead;
  bead.name = "bead";
  bead.shape = Shape::point;
  bead.mass = q("m");
  bead.points = {{"C", {q("0"), q("0")}, {}}};
  m.bodies.push_back(bead);
  m.bodies[0].points.push_back({"A", {q("L/2"), q("0")}, {}});
  Joint slider;
  slider.name = "s";
  slider.type = JointType::slider;
  slider.bodies = {"1", "bead"};
  slider.points = {"A", "C"};
  slider.axis = Vector2Quantity{q("1"), q("0")};
  m.joints.push_back(slider);
  const std::string e = error_of(m);
  EXPECT_NE(e.find("slider s joins the point mass 'bead'"), std::string::npos) << e;
}

// Issue 22 F03: an axis zero whatever the parameters was GiNaC's "division by zero".
TEST(Validate, ASliderAxisZeroForAnyParametersIsRefused) {
  Mechanism m = pendulum();
  m.bodies[0].points.push_back({"A", {q("L/2"), q("0")}, {}});
  Body block = m.bodies[0];
  block.name = "2";
  m.bodies.push_back(block);
  Joint slider;
  slider.name = "s";
  slider.type = JointType::slider;
  slider.bodies = {"1", "2"};
  slider.points = {"A", "O"};
  slider.axis = Vector2Quantity{q("L-L", 30), q("0", 30)};
  m.joints.push_back(slider);
  m.initial.push_back({"s.s", 0.1, {}});
  EXPECT_EQ(error_of(m),
            "m.toml:30:9: the axis of slider s (\"L-L\", \"0\") is zero for any parameter values; valid: a "
            "direction of non-zero length");
}

// Issue 22 F13: only a literal's sign was checked; "-g" made gravity point up.
TEST(Validate, GravityNegativeAtTheParametersIsRefused) {
  Mechanism m = pendulum();
  m.gravity = q("-g", 2);
  EXPECT_EQ(error_of(m), "m.toml:2:9: gravity \"-g\" is -9.81 at the parameters; valid: >= 0");
  m.gravity = q("g", 2);
  m.parameters[2].value = -9.81;
  EXPECT_EQ(error_of(m), "m.toml:2:9: gravity \"g\" is -9.81 at the parameters; valid: >= 0");
}

// Issue 22 F06: exact decimals multiply into numbers beyond double range; GiNaC keeps an
// inertia of them as 1/N m (K1 w^2 + K2) with N = 3.8e1317, which evaluated to 0 * inf.
TEST(Validate, ProductsOfExactDecimalsEvaluateInDoubleRange) {
  const GiNaC::symbol m("m"), w("w");
  const GiNaC::ex decimal = GiNaC::numeric("30000000000000001") / GiNaC::pow(GiNaC::numeric(10), 17);
  const GiNaC::ex length = GiNaC::pow(decimal, 12) / GiNaC::pow(GiNaC::numeric(3, 10), 11);
  const GiNaC::ex inertia = m * (GiNaC::pow(length, 2) + GiNaC::pow(w, 2)) / 12;
  const GiNaC::exmap values{{m, GiNaC::numeric(0.1)}, {w, GiNaC::numeric(0.1)}};
  const double exact = 0.0008333333333333339;  // by Python's fractions, rounded once
  EXPECT_NEAR(sym::evaluate(inertia, values), exact, 4 * std::numeric_limits<double>::epsilon() * exact);
}

// Issue 22 F04/F05: numbers beyond double range threw CLN's "floating point underflow".
TEST(Validate, NumbersBeyondDoubleRangeAreNamedNotTrapped) {
  EXPECT_EQ(error_of(pendulum("m*1e-300*1e-300")),
            "m.toml:7:9: mass of body 1 \"m*1e-300*1e-300\" is 0 at the parameters; valid: > 0");
  const std::string huge = error_of(pendulum("m*1e300*1e300"));
  EXPECT_NE(huge.find("m.toml:7:9: "), std::string::npos) << huge;
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

TEST(Validate, ExpressionsThatWouldExplodeOrAreUnknownAreRefused) {
  EXPECT_NE(error_of(pendulum("m", "L*9^9^9"))
                .find("m.toml:8:9: the power is too high or nested at character 6 of 'L*9^9^9'"),
            std::string::npos);
  EXPECT_NE(error_of(pendulum("m", "L^100")).find("is too high"), std::string::npos);
  EXPECT_NE(error_of(pendulum("m", "L*(9)^(9)^(9)")).find("is too high or nested"), std::string::npos);
  EXPECT_NE(error_of(pendulum("m", "(L+1)^(2^9)")).find("is too high or nested"), std::string::npos);
  EXPECT_NE(error_of(pendulum("m", std::string(600, '1'))).find("characters long; valid: at most 500"),
            std::string::npos);
  const std::string unknown = error_of(pendulum("m", "L*tgamma(2)"));
  EXPECT_NE(unknown.find("m.toml:8:9: "), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown function 'tgamma' at character 3 of 'L*tgamma(2)'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("valid: sin, cos, tan, sqrt, exp, log, hypot, log10"), std::string::npos) << unknown;
  EXPECT_EQ(error_of(pendulum("m", "L^2/L + 0*sqrt(L)")), "");
  EXPECT_EQ(error_of(pendulum("m", "hypot(L, 0) * log10(10) + 0*log(L)")), "");
  // Read by the one reader, but no notation in the printers and exporters yet.
  EXPECT_EQ(error_of(pendulum("m", "abs(L)")),
            "m.toml:8:9: the function 'abs' is not available here at character 1 of 'abs(L)'; valid: sin, cos, tan, "
            "sqrt, exp, log, hypot, log10");
}

}  // namespace
}  // namespace linkage
