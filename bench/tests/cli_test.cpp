// `linkage bench accuracy` and `linkage bench stress` in --quick mode: the reports are
// produced and sane (not their timings), and bad input is a one-line error, exit 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bench/method.hpp"
#include "bench/tests/csv_reader.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::run_linkage;
using test::TempDir;

using test::read_csv;

TEST(BenchAccuracy, QuickRunWritesASaneReport) {
  TempDir dir;
  const auto out = dir / "acc";
  const test::RunResult r =
      run_linkage({"bench", "accuracy", "--quick", "--quiet", "--duration", "1", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<bench::PeerLibrary> peers = bench::peer_libraries();
  const auto built = static_cast<std::size_t>(
      std::count_if(peers.begin(), peers.end(), [](const bench::PeerLibrary& p) { return p.built; }));
  for (const char* f : {"accuracy.csv", "accuracy.md", "work_precision_fast.png", "work_precision_fast.svg"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  // Case 3 against the peers: only when a peer ran.
  for (const char* f : {"work_precision_fast_case3.png", "work_precision_fast_case3.svg"})
    EXPECT_EQ(std::filesystem::exists(out / f), built > 0) << f;
  EXPECT_NE(r.out.find("reference good to"), std::string::npos) << r.out;
  // Each peer the build lacks: one note on stderr; the report names the peers that ran.
  for (const bench::PeerLibrary& peer : peers)
    EXPECT_EQ(r.err.find("linkage: note: " + peer.not_built_note() + "\n") != std::string::npos, !peer.built) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), static_cast<long>(peers.size() - built)) << r.err;
  EXPECT_NE(r.out.find("Peers run: "), std::string::npos) << r.out;

  const auto rows = read_csv(out / "accuracy.csv");
  ASSERT_FALSE(rows.empty());
  for (const char* column :
       {"scenario", "case", "method", "library", "rhs", "kind", "tolerance", "step_count", "time_s", "rhs_evaluations",
        "steps", "error", "energy_error", "constraint_error", "status"})
    EXPECT_TRUE(rows.front().count(column)) << column;
  // Every library, every case, both right-hand sides of the peers.
  std::map<std::string, int> libraries, cases;
  std::map<std::string, std::pair<double, double>> loose_tight;  // adaptive curves: error at loosest, tightest
  for (const auto& row : rows) {
    ++libraries[row.at("library")];
    ++cases[row.at("case")];
    if (row.at("status") != "ok") continue;
    const double error = std::stod(row.at("error"));
    EXPECT_TRUE(std::isfinite(error) && error >= 0) << row.at("method");
    EXPECT_GT(std::stod(row.at("time_s")), 0);
    EXPECT_GT(std::stol(row.at("rhs_evaluations")), 0);
    if (row.at("case") == "1") {
      EXPECT_FALSE(row.at("constraint_error").empty());
    }
    if (row.at("kind") != "adaptive") continue;
    const std::string curve = row.at("method") + "/" + row.at("case") + "/" + row.at("rhs");
    const double tol = std::stod(row.at("tolerance"));
    auto [it, fresh] = loose_tight.try_emplace(curve, error, error);
    if (tol == 1e-3) it->second.first = error;
    if (tol == 1e-9) it->second.second = error;
  }
  EXPECT_EQ(libraries.size(), 1 + built);  // linkage and each peer built: Boost.Odeint, SUNDIALS
  for (const bench::PeerLibrary& peer : peers) EXPECT_EQ(libraries.count(peer.library), peer.built ? 1u : 0u);
  EXPECT_EQ(cases.size(), 3u);
  ASSERT_GE(loose_tight.size(), 6u + bench::peer_methods().size());  // ours: Dopri5, DOP853 on each case
  for (const auto& [curve, errors] : loose_tight)
    EXPECT_LT(errors.second, errors.first * 1e-2) << curve << ": tolerance 1e-9 is not better than 1e-3";
  EXPECT_EQ(test::read_text(out / "accuracy.csv").find("nan"), std::string::npos);

  const std::string md = test::read_text(out / "accuracy.md");
  for (const char* text : {"significant digits", "### Targets", "time to error 1e-08", "work_precision_fast.svg",
                           "linkage bench accuracy --scenario fast", "Peers run: "})
    EXPECT_NE(md.find(text), std::string::npos) << text;
  for (const bench::PeerLibrary& peer : peers)
    EXPECT_EQ(md.find(peer.not_built_note()) != std::string::npos, !peer.built) << peer.library;
  // The targets against the peers: a figure only from peers that ran.
  EXPECT_EQ(md.find("not measured: peer not built") != std::string::npos, built == 0) << md;
  EXPECT_EQ(test::read_text(out / "work_precision_fast.svg").rfind("<?xml", 0), 0u);
}

TEST(BenchAccuracy, SelectionOfCasesAndIntegrators) {
  TempDir dir;
  const test::RunResult r = run_linkage({"bench", "accuracy", "--quick", "--quiet", "--duration", "0.5", "--cases", "2",
                                         "--integrators", "dop853,rk4", "--out", (dir / "o").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& row : read_csv(dir / "o" / "accuracy.csv")) {
    EXPECT_EQ(row.at("case"), "2");
    EXPECT_TRUE(row.at("method") == "dop853" || row.at("method") == "rk4") << row.at("method");
  }
}

TEST(BenchAccuracy, BadInputIsAOneLineErrorAndWritesNothing) {
  TempDir dir;
  const std::string out = (dir / "o").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--scenario", "nope"}, "--scenario: 'nope' is not a scenario"},
      {{"--cases", "4"}, "--cases: '4' is not a case"},
      {{"--cases", "1,,3"}, "--cases"},
      {{"--integrators", "rk5"}, "--integrators: 'rk5' is not an integrator"},
      {{"--duration", "-1"}, "--duration"},
      {{"--duration", "abc"}, "--duration"},
  };
  for (const auto& [args, message] : cases) {
    std::vector<std::string> argv{"bench", "accuracy", "--quick", "--out", out};
    argv.insert(argv.end(), args.begin(), args.end());
    const test::RunResult r = run_linkage(argv);
    EXPECT_EQ(r.exit_code, 2) << args[1];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args[1];
  }
  // A folder in the way is an error; a missing one is made with its parents (mkdir -p).
  test::write_text(dir / "file", "x");
  const test::RunResult in_the_way =
      run_linkage({"bench", "accuracy", "--quick", "--out", (dir / "file" / "sub").string()});
  EXPECT_EQ(in_the_way.exit_code, 2);
  EXPECT_NE(in_the_way.err.find("exists and is not a folder"), std::string::npos) << in_the_way.err;
}

TEST(BenchAccuracy, AnIntegratorOfAPeerNotBuiltIsAOneLineError) {
  std::vector<bench::PeerLibrary> missing;
  for (const bench::PeerLibrary& peer : bench::peer_libraries())
    if (!peer.built) missing.push_back(peer);
  if (missing.empty()) GTEST_SKIP() << "every peer is built";
  TempDir dir;
  for (const bench::PeerLibrary& peer : missing) {
    const std::string out = (dir / "o").string();
    const test::RunResult r =
        run_linkage({"bench", "accuracy", "--quick", "--integrators", "dop853," + peer.ids.front(), "--out", out});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--integrators: '" + peer.ids.front() + "' is not in this build: " + peer.not_built_note()),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(BenchStress, QuickRunWritesEveryStudy) {
  TempDir dir;
  const auto out = dir / "stress";
  const test::RunResult r = run_linkage({"bench", "stress", "--quick", "--quiet", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f :
       {"stress.md", "stress_long_runs.csv", "stress_stable_step.csv", "stress_extremes.csv", "stress_drift.csv",
        "stress_long_runs_energy.png", "stress_long_runs_constraint.svg", "stress_drift.png", "stress_drift.svg"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;

  const auto steps = read_csv(out / "stress_stable_step.csv");
  EXPECT_EQ(steps.size(), 12u);  // 3 cases x 4 fixed-step methods
  for (const auto& row : steps) {
    const double dt = std::stod(row.at("largest_stable_dt_s"));
    EXPECT_GT(dt, 1e-6) << row.at("integrator");
    EXPECT_LT(dt, std::stod(row.at("smallest_unstable_dt_s"))) << row.at("integrator");
  }
  // Drift: projection keeps Case 1 on the constraint far better than no stabilization.
  std::map<std::string, double> final_drift;
  for (const auto& row : read_csv(out / "stress_drift.csv"))
    final_drift[row.at("stabilization") + row.at("run")] = std::stod(row.at("constraint_error"));
  ASSERT_EQ(final_drift.size(), 5u);
  EXPECT_LT(final_drift.at("projectionprojection"), 1e-3 * final_drift.at("nonenone"));

  const auto extremes = read_csv(out / "stress_extremes.csv");
  EXPECT_EQ(extremes.size() % 3, 0u);
  for (const auto& row : extremes) EXPECT_GE(std::stod(row.at("condition_number")), 1.0) << row.at("variant");
  const std::string md = test::read_text(out / "stress.md");
  for (const char* text :
       {"## Long runs", "## Largest stable step", "## Extreme parameters", "## Case 1 constraint drift"})
    EXPECT_NE(md.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace linkage
