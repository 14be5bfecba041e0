// Long chains (issue 22, F01): a pendulum chain of N uniform rods pinned end to end, the
// first pinned to the ground, written here as a mechanism file. A hundred links derive and
// simulate with the energy kept to the integrator's tolerance (ctest's TIMEOUT for these
// tests, tests/cli/timeouts.cmake, catches a return to the old growth with N); two links
// move exactly as the shipped double pendulum; a signal ends a 200-link derivation at once.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

struct Rod {
  double length = 0.1, mass = 0.1, theta = -0.5;
};

/// The chain's file: rod i has its length and mass, its points A (towards the ground) and
/// B; joint J1 pins A of rod 1 to the ground's O, joint J<i> pins A of rod i to B of rod i-1.
/// Identical rods share the parameters l and m (with a mass and a length per rod, Case 3's
/// mass matrix has n^3 terms: each entry sums the masses beyond its rows' links).
std::string chain_toml(const std::vector<Rod>& rods) {
  bool identical = true;
  for (const Rod& r : rods) identical = identical && r.length == rods[0].length && r.mass == rods[0].mass;
  std::ostringstream f;
  f << "title = \"Chain of " << rods.size() << " rods\"\ngravity = \"g\"\n\n[parameters]\ng = 9.81\n";
  if (identical)
    f << "l = " << rods[0].length << "\nm = " << rods[0].mass << "\n";
  else
    for (std::size_t i = 1; i <= rods.size(); ++i)
      f << "l" << i << " = " << rods[i - 1].length << "\nm" << i << " = " << rods[i - 1].mass << "\n";
  f << "\n[ground]\npoints = { O = [0, 0] }\n";
  for (std::size_t i = 1; i <= rods.size(); ++i) {
    const std::string k = identical ? "" : std::to_string(i);
    f << "\n[[body]]\nname = \"" << i << "\"\nshape = \"rod\"\nmass = \"m" << k << "\"\nlength = \"l" << k
      << "\"\npoints = { A = [\"-l" << k << "/2\", 0], B = [\"l" << k << "/2\", 0] }\n";
  }
  for (std::size_t i = 1; i <= rods.size(); ++i)
    f << "\n[[joint]]\nname = \"J" << i << "\"\ntype = \"pin\"\nbodies = [\""
      << (i == 1 ? "ground" : std::to_string(i - 1)) << "\", \"" << i << "\"]\npoints = [\"" << (i == 1 ? "O" : "B")
      << "\", \"A\"]\n";
  f << "\n[initial]\n";
  for (std::size_t i = 1; i <= rods.size(); ++i) f << "\"" << i << "\" = { theta = " << rods[i - 1].theta << " }\n";
  return f.str();
}

/// N rods of 0.1 m and 0.1 kg, each leaning a little further than the one above.
std::vector<Rod> leaning_rods(int n) {
  std::vector<Rod> rods(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rods[static_cast<std::size_t>(i)].theta = -0.5 - 0.01 * i;
  return rods;
}

std::filesystem::path write(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(LongChain, TwoLinksMoveAsTheShippedDoublePendulum) {
  const TempDir dir;
  const std::vector<Rod> rods{{0.3, 0.2, -0.8}, {0.25, 0.15, -1.2}};
  const std::string chain = write(dir, "chain2.toml", chain_toml(rods)).string();
  const std::vector<std::string> tail{"--duration", "1", "--columns", "t,1.x,1.y,1.theta,2.x,2.y,2.theta,energy"};
  std::vector<std::string> ours{"simulate", "--mechanism", chain},
      shipped{"simulate", "--mechanism", "double-pendulum"};
  ours.insert(ours.end(), tail.begin(), tail.end());
  shipped.insert(shipped.end(), tail.begin(), tail.end());
  const RunResult a = run_linkage(ours), b = run_linkage(shipped);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto x = csv_rows(a.out), y = csv_rows(b.out);
  ASSERT_EQ(x.size(), 101U);
  ASSERT_EQ(x.size(), y.size());
  // The same equations up to the order of their terms: round-off, grown by the chaos of
  // one second (the integrator's tolerance is 1e-10).
  for (std::size_t r = 0; r < x.size(); ++r)
    for (std::size_t c = 0; c < x[r].size(); ++c) EXPECT_NEAR(x[r][c], y[r][c], 1e-8) << "row " << r << " column " << c;
}

TEST(LongChain, HundredLinksDeriveAndSimulateKeepingTheEnergy) {
  const TempDir dir;
  const std::string chain = write(dir, "chain100.toml", chain_toml(leaning_rods(100))).string();
  const RunResult r =
      run_linkage({"simulate", "--mechanism", chain, "--duration", "1", "--columns", "t,energy,energy_error,100.y"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 101U);
  // The energy scale: the potential energy's range, sum m g l (i - 1/2) for the chain from
  // horizontal to hanging, 0.1 * 9.81 * 0.1 * 100^2 / 2 = 49 J. DOP853 at rtol = atol =
  // 1e-10 keeps the balance to about that times the tolerance per unit time.
  const double scale = 0.1 * 9.81 * 0.1 * 100 * 100 / 2;
  double largest = 0;
  for (const auto& row : rows) {
    ASSERT_TRUE(std::isfinite(row[1]) && std::isfinite(row[2]) && std::isfinite(row[3]));
    largest = std::max(largest, std::fabs(row[2]));
  }
  EXPECT_LT(largest, 1e-8 * scale);
  // It moves: the tip falls from its start.
  EXPECT_LT(rows.back()[3], rows.front()[3] - 0.01);

  // The worked solution derives all three cases, and they agree.
  const RunResult s = run_linkage({"solve", "--mechanism", chain, "--case", "3", "--format", "json"});
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto json = nlohmann::json::parse(s.out);
  ASSERT_EQ(json["cases"].size(), 1U);
  EXPECT_EQ(json["cases"][0]["unknowns"].size(), 100U);
  EXPECT_LT(json["cases"][0]["residual"].get<double>(), 1e-9);
}

TEST(LongChain, SigtermEndsTheDerivationOfTwoHundredLinksAtOnce) {
  const TempDir dir;
  write(dir, "chain200.toml", chain_toml(leaning_rods(200)));
  RunOptions options;
  options.args = {"simulate", "--mechanism", (dir / "chain200.toml").string(), "--duration",
                  "1",        "--out",       (dir / "run.csv").string()};
  options.signal = SIGTERM;
  options.timeout_seconds = 30;
  const auto start = std::chrono::steady_clock::now();
  options.ready = [&](const std::string&, const std::string&) {
    return std::chrono::steady_clock::now() - start > std::chrono::milliseconds(300);
  };
  const RunResult r = run_linkage(options);
  ASSERT_TRUE(r.signal_sent) << "it ended before the signal: " << r.err;
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 128 + SIGTERM) << r.err;
  EXPECT_LT(r.seconds_after_signal, 1.0);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"chain200.toml"});
}

// Every stage of the derivation polls for the signal (building the system, closing and
// checking the initial state, deriving the case, solving it at the start, compiling it,
// and compiling the sample: the angular momentum's substitution and walk, which took
// seconds without a check, lie at about 0.5 and 0.65 of the run): a signal at any moment
// of it ends the run within a second. The moments are fractions of the time the same run
// takes here unsignalled, measured first, so that they fall at the same stages on any
// machine (the integration is the last 0.2 s).
TEST(LongChain, ASignalAtAnyMomentOfTheDerivationEndsTheRunWithinASecond) {
  const TempDir dir;
  const std::string chain = write(dir, "chain100.toml", chain_toml(leaning_rods(100))).string();
  const std::vector<std::string> args{
      "simulate", "--mechanism", chain, "--duration", "1", "--out", (dir / "run.csv").string()};
  const auto begun = std::chrono::steady_clock::now();
  const RunResult whole = run_linkage(args);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const double run = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  std::filesystem::remove(dir / "run.csv");
  struct Moment {
    double fraction;
    int signal;
  };
  for (const Moment m : {Moment{0.05, SIGTERM}, Moment{0.3, SIGINT}, Moment{0.5, SIGTERM}, Moment{0.55, SIGTERM},
                         Moment{0.65, SIGTERM}, Moment{0.85, SIGTERM}}) {
    SCOPED_TRACE("signal " + std::to_string(m.signal) + " at " + std::to_string(m.fraction) + " of " +
                 std::to_string(run) + " s");
    RunOptions options;
    options.args = args;
    options.signal = m.signal;
    options.timeout_seconds = 10 * run + 30;
    const auto start = std::chrono::steady_clock::now();
    options.ready = [&](const std::string&, const std::string&) {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > m.fraction * run;
    };
    const RunResult r = run_linkage(options);
    ASSERT_TRUE(r.signal_sent) << "it ended before the signal: " << r.err;
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.exit_code, 128 + m.signal) << r.err;
    EXPECT_LT(r.seconds_after_signal, 1.0);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"chain100.toml"});
  }
}

}  // namespace
}  // namespace linkage::test
