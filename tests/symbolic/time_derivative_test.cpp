// System::time_derivative differentiates a sum term by term, each term by the symbols it
// holds (issue 22, F01: differentiating a long chain's whole positions by each coordinate
// cost n^3). It must still be the chain rule: de/dt + sum over q of de/dq q'.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "model/mechanism_toml.hpp"
#include "symbolic/system.hpp"

namespace linkage {
namespace {

/// The chain rule over every coordinate and rate of `system`, one diff of the whole
/// expression per symbol: the definition the term-by-term version must agree with.
GiNaC::ex chain_rule(const sym::System& system, const GiNaC::ex& e) {
  GiNaC::ex out = e.diff(system.time());
  auto add = [&](const sym::CoordinateSymbols& c) { out += e.diff(c.q) * c.q_dot + e.diff(c.q_dot) * c.q_ddot; };
  for (const sym::BodySystem& b : system.bodies()) {
    add(b.x);
    add(b.y);
    if (b.rotates) add(b.theta);
  }
  for (const sym::GeneralizedCoordinate& g : system.coordinates())
    if (g.coordinate.kind == CoordinateKind::s) add(g.symbols);
  return out;
}

/// A chain of `n` rods pinned end to end, the first to the ground.
std::string chain(int n) {
  std::ostringstream f;
  f << "title = \"chain\"\ngravity = \"g\"\n[parameters]\ng = 9.81\nl = 0.1\nm = 0.1\n[ground]\npoints = { O = [0, 0] "
       "}\n";
  for (int i = 1; i <= n; ++i)
    f << "[[body]]\nname = \"" << i
      << "\"\nshape = \"rod\"\nmass = \"m\"\nlength = \"l\"\npoints = { A = [\"-l/2\", 0], B = [\"l/2\", 0] }\n";
  for (int i = 1; i <= n; ++i)
    f << "[[joint]]\nname = \"J" << i << "\"\ntype = \"pin\"\nbodies = [\""
      << (i == 1 ? "ground" : std::to_string(i - 1)) << "\", \"" << i << "\"]\npoints = [\"" << (i == 1 ? "O" : "B")
      << "\", \"A\"]\n";
  f << "[initial]\n";
  for (int i = 1; i <= n; ++i) f << "\"" << i << "\" = { theta = -0.5 }\n";
  return f.str();
}

void expect_chain_rule(const sym::System& system) {
  int checked = 0;
  // Every body's points in maximal coordinates; every maximal position and rate in
  // generalized coordinates (sums of a term per ancestor); each joint's constraint rows.
  for (std::size_t b = 0; b < system.bodies().size(); ++b)
    for (const auto& [name, local] : system.bodies()[b].points) {
      const sym::Vec2 p = system.point_position(static_cast<int>(b), name);
      for (const GiNaC::ex& e : {p.x, p.y}) {
        EXPECT_TRUE(GiNaC::expand(system.time_derivative(e) - chain_rule(system, e)).is_zero()) << e;
        ++checked;
      }
    }
  for (const auto& [symbol, expression] : system.to_generalized()) {
    const GiNaC::ex ours = system.time_derivative(expression);
    EXPECT_TRUE(GiNaC::expand(ours - chain_rule(system, expression)).is_zero()) << symbol << ": " << ours;
    ++checked;
  }
  for (const sym::JointSystem& j : system.joints())
    for (const GiNaC::ex& phi : j.constraints) {
      const GiNaC::ex ours = system.time_derivative(system.time_derivative(phi));
      EXPECT_TRUE(GiNaC::expand(ours - chain_rule(system, chain_rule(system, phi))).is_zero()) << phi;
      ++checked;
    }
  EXPECT_GT(checked, 0);
}

TEST(TimeDerivative, IsTheChainRuleForEveryShippedMechanism) {
  for (const char* name : {"two-blocks", "unequal-blocks", "double-pendulum", "triple-pendulum", "spring-pendulum",
                           "slider-crank", "four-bar"}) {
    SCOPED_TRACE(name);
    expect_chain_rule(sym::System(load_mechanism(name)));
  }
}

TEST(TimeDerivative, IsTheChainRuleForAChainOfTwentyLinks) {
  const sym::System system(read_mechanism(chain(20), "chain.toml"));
  expect_chain_rule(system);
  // The tip's x: one term per link, l (cos th1 + ... + cos th19) + l/2 cos th20; its rate
  // one term per link too, as the tree's recursion writes it.
  const GiNaC::ex x20 = system.to_generalized().at(system.bodies()[19].x.q);
  EXPECT_EQ(x20.nops(), 20U) << x20;
  EXPECT_EQ(system.to_generalized().at(system.bodies()[19].x.q_dot).nops(), 20U);
}

// A constant, a symbol without a rate (a parameter) and t itself.
TEST(TimeDerivative, OfConstantsParametersAndTime) {
  const sym::System system(load_mechanism("double-pendulum"));
  EXPECT_TRUE(system.time_derivative(GiNaC::ex(3)).is_zero());
  EXPECT_TRUE(system.time_derivative(GiNaC::symbol("not_a_coordinate")).is_zero());
  EXPECT_TRUE((system.time_derivative(GiNaC::pow(system.time(), 2)) - 2 * system.time()).is_zero());
  const GiNaC::symbol& th = system.bodies()[0].theta.q;
  EXPECT_TRUE(GiNaC::expand(system.time_derivative(GiNaC::sin(th)) - GiNaC::cos(th) * system.bodies()[0].theta.q_dot)
                  .is_zero());
}

}  // namespace
}  // namespace linkage
