// Every method of the study (ours and the peers) solves the spec's example to its
// tolerance, and agrees with the long double reference; the reference itself agrees
// with reference-example.json.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "bench/method.hpp"
#include "bench/reference.hpp"
#include "bench/rhs.hpp"
#include "linkage/reference_example.hpp"
#include "support/test_support.hpp"

namespace linkage::bench {
namespace {

const Reference& example_reference() {
  static const Reference ref = compute_reference(find_scenario("example", "test"), false);
  return ref;
}

TEST(Reference, MatchesTheSpecsTwentyFiveDigitStates) {
  const Reference& ref = example_reference();
  ASSERT_TRUE(ref.spec_difference.has_value()) << "the example's reference skipped the reference-example.json check";
  // long double: eps 1.1e-19, |y1| ~ 480 m at t = 10 s
  EXPECT_LT(*ref.spec_difference, 1e-14);
  EXPECT_LT(ref.check_difference, 1e-14);
  EXPECT_GT(ref.digits, 15.0);
}

TEST(Reference, EmbedsReferenceExampleJsonByteForByte) {
  EXPECT_EQ(kReferenceExampleJson, test::read_text(std::filesystem::path(LINKAGE_SPEC_DIR) / "reference-example.json"));
}

TEST(Reference, QuickModeIsLooserButStillFarBeyondDouble) {
  const Reference quick = compute_reference(find_scenario("fast", "test"), true);
  EXPECT_LT(quick.check_difference, 1e-10);
  EXPECT_GT(quick.digits, 11.0);
}

TEST(UserRhs, MatchesTheDefinition) {
  const Params p;
  const UserConstants c(p);
  const Vec<8> y = (Vec<8>() << 1, 2, 0.7, -2.1, 0.3, -0.2, 20, -35).finished();
  Vec<8> dy;
  user_case3_rhs(c, y.data(), dy.data());
  const LinearSystem<Case3> s = assemble<Case3>(make_env(p, y[2], y[3], y[6], y[7]));
  Vec<4> q;
  ASSERT_TRUE(solve_blocks<Case3>(s.A, s.B, q));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(dy[i], y[i + 4]);
    EXPECT_NEAR(dy[i + 4], q[i], 1e-12 * (1 + std::fabs(q[i])));
  }
}

/// The error a method may have at a setting on the example over 10 s.
double allowed_error(const Method& m, double knob) {
  if (m.adaptive) return 1e4 * knob;  // rtol against |y1| ~ 480 m, plus the methods' own slack
  // fixed steps: 1024 steps of ~0.01 s
  return m.order >= 4 ? 1e-6 : 1.0;
}

void expect_solves_the_example(const Method& m) {
  const Scenario& s = find_scenario("example", "test");
  const double knob = m.adaptive ? 1e-8 : 1024;
  const Outcome out = m.run(s, knob);
  EXPECT_TRUE(out.failure.empty()) << m.id << ": " << out.failure;
  const double error = final_error(example_reference(), out.final);
  EXPECT_LT(error, allowed_error(m, knob)) << m.id << " case " << m.case_id << " rhs " << name(m.rhs);
  EXPECT_GT(out.rhs_evaluations, 0) << m.id;
  EXPECT_GT(out.steps, 0) << m.id;
}

TEST(Methods, OursSolveTheExampleOnEveryCase) {
  for (int c : {1, 2, 3})
    for (const Method& m : linkage_methods(c)) expect_solves_the_example(m);
}

/// The peer library `name`, as this build has it.
PeerLibrary peer(const std::string& name) {
  for (const PeerLibrary& p : peer_libraries())
    if (p.library == name) return p;
  ADD_FAILURE() << "no peer library " << name;
  return {};
}

/// peer_methods() of one library.
std::vector<Method> methods_of(const std::string& library) {
  std::vector<Method> out;
  for (Method& m : peer_methods())
    if (m.library == library) out.push_back(std::move(m));
  return out;
}

TEST(Methods, OdeintPeersSolveTheExampleWithEitherRightHandSide) {
  if (!peer("Boost.Odeint").built) GTEST_SKIP() << peer("Boost.Odeint").not_built_note();
  const std::vector<Method> peers = methods_of("Boost.Odeint");
  EXPECT_EQ(peers.size(), 6u);  // RKF78, dense Dopri5, Bulirsch-Stoer on Case 3; each with 2 RHS
  for (const Method& m : peers) expect_solves_the_example(m);
}

TEST(Methods, SundialsPeersSolveTheExampleWithEitherRightHandSide) {
  if (!peer("SUNDIALS").built) GTEST_SKIP() << peer("SUNDIALS").not_built_note();
  const std::vector<Method> peers = methods_of("SUNDIALS");
  EXPECT_EQ(peers.size(), 4u);  // CVODE on Case 3, IDA on Case 1; each with 2 RHS
  for (const Method& m : peers) expect_solves_the_example(m);
}

// What peer_libraries() says of each peer is what peer_methods() holds: a built peer
// has every id it lists, one that is not built has no method at all.
TEST(Methods, PeerLibrariesListExactlyTheMethodsBuilt) {
  const std::vector<PeerLibrary> libraries = peer_libraries();
  ASSERT_EQ(libraries.size(), 2u);
  std::size_t listed = 0;
  for (const PeerLibrary& lib : libraries) {
    std::vector<std::string> ids;
    for (const Method& m : methods_of(lib.library))
      if (std::find(ids.begin(), ids.end(), m.id) == ids.end()) ids.push_back(m.id);
    EXPECT_EQ(ids, lib.built ? lib.ids : std::vector<std::string>{}) << lib.library;
    listed += methods_of(lib.library).size();
    const std::string note = lib.not_built_note();
    EXPECT_NE(note.find(lib.library), std::string::npos) << note;
    EXPECT_NE(note.find("install " + lib.package), std::string::npos) << note;
  }
  EXPECT_EQ(listed, peer_methods().size()) << "a peer method of no listed library";
}

TEST(Methods, TighterToleranceGivesSmallerErrorForEveryAdaptiveMethod) {
  const Scenario& s = find_scenario("example", "test");
  std::vector<Method> all = peer_methods();
  for (Method& m : linkage_methods(3)) all.push_back(std::move(m));
  for (const Method& m : all) {
    if (!m.adaptive) continue;
    const double loose = final_error(example_reference(), m.run(s, 1e-4).final);
    const double tight = final_error(example_reference(), m.run(s, 1e-10).final);
    EXPECT_LT(tight, 1e-2 * loose) << m.id << " " << name(m.rhs);
  }
}

TEST(Methods, EvaluationCountsAreTheMethodsOwn) {
  const Scenario& s = find_scenario("example", "test");
  for (const Method& m : linkage_methods(3)) {
    if (m.id == "rk4") {
      EXPECT_EQ(m.run(s, 100).rhs_evaluations, 400);
    } else if (m.id == "euler") {
      EXPECT_EQ(m.run(s, 100).rhs_evaluations, 100);
    }
  }
}

}  // namespace
}  // namespace linkage::bench
