// Long chains (issue 22, F01; the chain's file from support/long_chain.hpp). A hundred links derive and
// simulate with the energy kept to the integrator's tolerance (ctest's TIMEOUT for these
// tests, tests/cli/timeouts.cmake, catches a return to the old growth with N); two links
// move exactly as the shipped double pendulum; a signal ends a 200-link derivation at once.
#include "support/long_chain.hpp"

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

}  // namespace
}  // namespace linkage::test
