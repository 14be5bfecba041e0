// `linkage bench mechanisms --quick` and `bench accuracy --mechanism --quick`: the reports'
// structure (every shipped mechanism and case, the chains beside MuJoCo, every peer's
// curve, each target with a verdict); and the peers' inputs: the hand-written double
// pendulum the Odeint peer runs agrees with our derivation, and the chain file is the
// chain MuJoCo is given.
#include "bench/mechanisms_bench.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "bench/double_pendulum_user.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "model/mechanism_toml.hpp"
#include "support/scoped_env.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

namespace fs = std::filesystem;

// One quick run for the tests below (the chains compile into a cache of the test's own).
struct QuickRun {
  test::TempDir dir;
  test::RunResult result;
  std::string csv;
  QuickRun() {
    const test::ScopedEnv cache("XDG_CACHE_HOME", (dir / "cache").string());
    result = test::run_linkage({"bench", "mechanisms", "--quick", "--out", (dir / "out").string()});
    if (result.exit_code == 0) csv = test::read_text(dir / "out" / "mechanisms.csv");
  }
};

const QuickRun& quick_run() {
  static const QuickRun run;
  return run;
}

// Every shipped mechanism and case is timed on the evaluator and on the built-in native code.
TEST(MechanismsBench, EveryShippedCaseOnBothPaths) {
  const QuickRun& run = quick_run();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  for (const std::string& name : shipped_mechanism_names())
    for (const std::string c : {"1", "2", "3"})
      for (const std::string path : {"evaluator", "compiled"})
        EXPECT_NE(run.csv.find("\n" + name + "," + c + "," + path + ","), std::string::npos)
            << name << " Case " << c << " " << path;
}

// The homework's Case 3 has all three paths' rows, each a positive time.
TEST(MechanismsBench, HomeworkCase3HasTheThreePaths) {
  const QuickRun& run = quick_run();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  for (const std::string path : {"evaluator", "compiled", "closed-form"}) {
    const std::string prefix = "\ntwo-blocks,3," + path + ",2,";
    const std::size_t at = run.csv.find(prefix);
    ASSERT_NE(at, std::string::npos) << path << "\n" << run.csv;
    EXPECT_GT(std::stod(run.csv.substr(at + prefix.size())), 0) << path;
  }
}

// Without a compiler the chains have no compiled rows and the report says why in one
// line; the shipped mechanisms' built-in code needs none.
TEST(MechanismsBench, WithoutACompilerTheChainsKeepTheEvaluatorRows) {
  const test::TempDir dir;
  const test::ScopedEnv cache("XDG_CACHE_HOME", (dir / "cache").string());
  const test::ScopedEnv path("PATH", (dir / "no-compiler").string());
  const test::RunResult r =
      test::run_linkage({"bench", "mechanisms", "--quick", "--quiet", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("chains: no compiled rows (no C++ compiler (c++) on PATH); the evaluator's rows stand\n"),
            std::string::npos)
      << r.out;
  const std::string csv = test::read_text(dir / "out" / "mechanisms.csv");
  EXPECT_NE(csv.find("\nchain-8,3,evaluator,8,"), std::string::npos);
  EXPECT_EQ(csv.find(",compiled,", csv.find("\nchain-")), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nfour-bar,1,compiled,3,"), std::string::npos);
  EXPECT_NE(test::read_text(dir / "out" / "mechanisms.md").find("- chains: no compiled rows"), std::string::npos);
}

TEST(MechanismsBench, QuickRunWritesEveryRowPeerAndTarget) {
  const QuickRun& run = quick_run();
  const test::RunResult& r = run.result;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path dir = run.dir / "out";
  const std::string& csv = run.csv;
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "mechanism,case,path,bodies,ns_per_rhs");
  EXPECT_NE(csv.find("\nchain-8,3,evaluator,8,"), std::string::npos);
  EXPECT_NE(csv.find("\nchain-8,3,compiled,8,"), std::string::npos) << "a compiler is on PATH in the tests";
  EXPECT_NE(csv.find("\nchain-8,3,mujoco,8,"), std::string::npos);
  const std::string work = test::read_text(dir / "work-precision.csv");
  for (const std::string method :
       {"ours dop853", "ours rk4", "odeint rkf78", "odeint rk4", "mujoco rk4", "mujoco euler"})
    EXPECT_NE(work.find("\n" + method + ","), std::string::npos) << method;
  const std::string md = test::read_text(dir / "mechanisms.md");
  for (const std::string target :
       {"| homework Case 3: compiled / closed form |", "| four-bar Case 1 right-hand side (compiled) |",
        "| four-bar Case 3 right-hand side (compiled) |", "| chain of 32: mj_forward / ours (compiled) |",
        "| chain: time at 64 links / at 8 (compiled) |"})
    EXPECT_NE(md.find(target), std::string::npos) << target << "\n" << md;
  EXPECT_NE(md.find("not measured: --quick stops at 8 links"), std::string::npos) << md;
  EXPECT_NE(r.out.find("MuJoCo RK4 / ours"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "work-precision.png"));
  EXPECT_TRUE(fs::exists(dir / "chain-scaling.png"));
}

TEST(MechanismsBench, AccuracyOfAnyMechanism) {
  const test::TempDir dir;
  const test::RunResult r = test::run_linkage(
      {"bench", "accuracy", "--mechanism", "four-bar", "--quick", "--quiet", "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("reference (DOP853 1e-14, Case 3) against Case 2: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("path: reference (Case 3): compiled (built in); Case 1: compiled (built in); Case 2: compiled "
                       "(built in); Case 3: compiled (built in)\n"),
            std::string::npos)
      << r.out;
  const std::string csv = test::read_text(dir / "accuracy-four-bar.csv");
  for (const std::string method : {"Case 1 dop853", "Case 2 rk4", "Case 3 gauss-legendre", "Case 3 euler"})
    EXPECT_NE(csv.find("\n" + method + ","), std::string::npos) << method;
  EXPECT_TRUE(fs::exists(dir / "accuracy-four-bar.png"));
  const test::RunResult bad =
      test::run_linkage({"bench", "accuracy", "--mechanism", "four-bar", "--scenario", "fast", "--quick"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--scenario and --integrators are the homework's"), std::string::npos) << bad.err;
}

// A mechanism file with no built-in code and no compiler on PATH runs on the evaluator
// and says why.
TEST(MechanismsBench, AccuracyOfAFileWithoutACompilerRunsTheEvaluator) {
  const test::TempDir dir;
  std::string text = test::read_text(fs::path(LINKAGE_SOURCE_DIR) / "mechanisms" / "four-bar.toml");
  const std::string mass = "mass = \"mb\"";
  ASSERT_NE(text.find(mass), std::string::npos);
  text.replace(text.find(mass), mass.size(), "mass = \"mb + ma/10\"");  // other equations: not built in
  test::write_text(dir / "four-bar.toml", text);
  const test::ScopedEnv cache("XDG_CACHE_HOME", (dir / "cache").string());
  const test::ScopedEnv path("PATH", (dir / "no-compiler").string());
  const test::RunResult r = test::run_linkage({"bench", "accuracy", "--mechanism", (dir / "four-bar.toml").string(),
                                               "--cases", "3", "--quick", "--quiet", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("path: reference (Case 3): interpreted (no C++ compiler (c++) on PATH); Case 3: interpreted (no "
                       "C++ compiler (c++) on PATH)\n"),
            std::string::npos)
      << r.out;
}

// The Odeint peer's right-hand side, written by hand, equals our derivation of the
// shipped double pendulum at random states to 1e-12.
TEST(MechanismsBench, HandWrittenDoublePendulumIsOurs) {
  const sym::System system(load_mechanism("double-pendulum"));
  const sym::ClosedState closed = sym::checked_initial_state(system);
  const eval::MechanismDynamics ours(system, CaseId::reduced);
  const bench::DoublePendulumUser user{0.3, 0.2, 0.25, 0.15, 9.81};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> draw(-3, 3);
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::VectorXd y = ours.initial_state(closed.state);
    for (int i = 0; i < 4; ++i) y[i] = draw(rng);
    Eigen::VectorXd dydt;
    ASSERT_TRUE(ours.derivative(0, y, dydt));
    std::array<double, 4> x{y[0], y[1], y[2], y[3]}, dx{};
    user(x, dx, 0.0);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(dx[static_cast<std::size_t>(i)], dydt[i], 1e-12 * (1 + std::abs(dydt[i])));
  }
}

// A chain's file reads, has one coordinate per link, and Case 3 of it runs.
TEST(MechanismsBench, ChainFileIsAChainOfRods) {
  const sym::System system(read_mechanism(bench::pendulum_chain_toml(5), "chain-5.toml"));
  EXPECT_EQ(system.coordinates().size(), 5U);
  const eval::MechanismDynamics d(system, CaseId::reduced);
  Eigen::VectorXd dydt;
  EXPECT_TRUE(d.derivative(0, d.initial_state(sym::checked_initial_state(system).state), dydt));
  EXPECT_TRUE(dydt.allFinite());
}

// The chains' compiled path (attach_native_derivative: the recursion's programs alone, A
// and B never expanded) gives the interpreter's y' at random states.
TEST(MechanismsBench, ChainsCompiledPathAgreesWithTheEvaluator) {
  const test::TempDir dir;
  const test::ScopedEnv cache("XDG_CACHE_HOME", (dir / "cache").string());
  const sym::System system(read_mechanism(bench::pendulum_chain_toml(5), "chain-5.toml"));
  const eval::MechanismDynamics interpreted(system, CaseId::reduced);
  eval::MechanismDynamics compiled(system, CaseId::reduced);
  const eval::NativeAttachment a = compiled.attach_native_derivative();
  ASSERT_TRUE(a.attached) << a.reason;
  EXPECT_TRUE(a.compiled);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> draw(-3, 3);
  Eigen::VectorXd y = interpreted.initial_state(sym::checked_initial_state(system).state);
  for (int trial = 0; trial < 3; ++trial) {
    for (Eigen::Index i = 0; i + 1 < y.size(); ++i) y[i] = draw(rng);
    Eigen::VectorXd expected, got;
    ASSERT_TRUE(interpreted.derivative(0, y, expected));
    ASSERT_TRUE(compiled.derivative(0, y, got));
    for (Eigen::Index i = 0; i < y.size(); ++i)
      EXPECT_NEAR(got[i], expected[i], 1e-13 * (1 + std::abs(expected[i]))) << "entry " << i;
  }
}

}  // namespace
}  // namespace linkage
