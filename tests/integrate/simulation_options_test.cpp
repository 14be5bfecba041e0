// The simulation options: values out of range refused naming the setting (never a
// flag), and the integrator and stabilization names parsed with suggestions.
#include "integrate/simulation_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace linkage {
namespace {

// Errors are data: the setting at fault, never a flag (the CLI and lessons phrase it).
void expect_bad(SimulationOptions o, const std::string& setting) {
  try {
    o.validate();
    ADD_FAILURE() << "accepted a bad " << setting;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_EQ(e.setting(), setting) << e.what();
    EXPECT_EQ(e.detail().find("--"), std::string::npos) << e.what();
  }
}

TEST(SimulationOptions, RejectsValuesOutOfRange) {
  SimulationOptions o;
  EXPECT_NO_THROW(o.validate());
  auto with = [&](auto change) {
    SimulationOptions c;
    change(c);
    return c;
  };
  expect_bad(with([](auto& c) { c.case_id = 4; }), "case");
  expect_bad(with([](auto& c) { c.dt = 0; }), "dt");
  expect_bad(with([](auto& c) { c.dt = -1e-3; }), "dt");
  expect_bad(with([](auto& c) { c.dt = 20; }), "dt");
  expect_bad(with([](auto& c) { c.duration = 0; }), "duration");
  expect_bad(with([](auto& c) { c.duration = 2e6; }), "duration");
  expect_bad(with([](auto& c) { c.rtol = 0; }), "rtol");
  expect_bad(with([](auto& c) { c.rtol = 1e-16; }), "rtol");
  expect_bad(with([](auto& c) { c.atol = -1; }), "atol");
  expect_bad(with([](auto& c) { c.baumgarte_alpha = -1; }), "baumgarte_alpha");
  expect_bad(with([](auto& c) { c.baumgarte_beta = std::nan(""); }), "baumgarte_beta");
  expect_bad(with([](auto& c) {
               c.integrator = IntegratorKind::rk4;
               c.dt = 1e-9;
             }),
             "dt");
  EXPECT_NO_THROW(with([](auto& c) {
                    c.integrator = IntegratorKind::dop853;
                    c.dt = 1e-9;
                  }).validate())
      << "an adaptive method's first step may be tiny";
}

TEST(SimulationOptions, ParsesNamesAndListsTheValidOnes) {
  for (const IntegratorInfo& i : integrators()) EXPECT_EQ(parse_integrator(i.name, "--integrator"), i.kind);
  EXPECT_EQ(parse_stabilization("projection", "--stabilize"), Stabilization::projection);
  EXPECT_EQ(name(Stabilization::baumgarte), "baumgarte");
  try {
    (void)parse_integrator("rk45", "--integrator");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "--integrator: 'rk45' is not an integrator (did you mean 'rk4'?); valid: euler, symplectic-euler, rk4, "
              "dopri5, dop853, vern7, gauss-legendre");
  }
  const auto message = [](auto parse) {
    try {
      (void)parse();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message([] { return parse_integrator("euler", "x"); }), "accepted");
  EXPECT_NE(message([] {
              return parse_integrator("dorpi5", "integrator");
            }).find("integrator: 'dorpi5' is not an integrator (did you mean 'dopri5'?); valid: euler,"),
            std::string::npos);
  EXPECT_EQ(message([] { return parse_integrator("leapfrog", "integrator"); }),
            "integrator: 'leapfrog' is not an integrator; valid: euler, symplectic-euler, rk4, dopri5, dop853, "
            "vern7, gauss-legendre");
  EXPECT_EQ(message([] { return parse_stabilization("baumgärte", "--stabilize"); }),
            "--stabilize: 'baumgärte' is not a stabilization (did you mean 'baumgarte'?); valid: none, baumgarte, "
            "projection");
  EXPECT_EQ(message([] { return parse_stabilization("projektion", "--stabilize"); }),
            "--stabilize: 'projektion' is not a stabilization (did you mean 'projection'?); valid: none, baumgarte, "
            "projection");
}

}  // namespace
}  // namespace linkage
