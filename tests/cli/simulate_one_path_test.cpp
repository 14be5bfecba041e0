// Issue 23: `simulate` with the homework's flags is `simulate --mechanism two-blocks --set`
// at the same settings, computed by the one path: the same bytes in every column of the
// spec's table (its columns, order and names as before), its header two-blocks.toml's
// column names renamed by its [aliases], for every case, integrator and stabilization.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "model/mechanism.hpp"
#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

struct OnePathRun {
  int case_id;
  std::string integrator, stabilize;
};

std::string run_name(const ::testing::TestParamInfo<OnePathRun>& info) {
  return test_name("case" + std::to_string(info.param.case_id) + "_" + info.param.integrator + "_" +
                   info.param.stabilize);
}

// Settings away from the defaults, as a homework flag and as the --set of two-blocks.
struct Setting {
  const char *flag, *key, *value;
};
constexpr Setting kSettings[] = {
    {"--L", "L", "0.4"},
    {"--w", "w", "0.12"},
    {"--b", "b", "0.05"},
    {"--m", "m", "0.2"},
    {"--g", "g", "9.7"},
    {"--x1", "1.x", "0.5"},
    {"--y1", "1.y", "1.5"},
    {"--theta1", "1.theta", "0.3"},
    {"--theta2", "2.theta", "-0.2"},
    {"--x1-dot", "1.x_dot", "0.1"},
    {"--y1-dot", "1.y_dot", "-0.2"},
    {"--theta1-dot", "1.theta_dot", "1.1"},
    {"--theta2-dot", "2.theta_dot", "-0.7"},
};

// The homework's CSV header before issue 23 (main's Simulation and columns).
constexpr const char* kSpecHeader =
    "t,x1,y1,theta1,theta2,x1_dot,y1_dot,theta1_dot,theta2_dot,x2,y2,x2_dot,y2_dot,x1_ddot,y1_ddot,theta1_ddot,"
    "theta2_ddot,F_x,F_y,energy,momentum_x,momentum_y,angular_momentum,constraint_position_error,"
    "constraint_velocity_error";

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, separator);) out.push_back(item);
  return out;
}

class SimulateOnePath : public ::testing::TestWithParam<OnePathRun> {};

TEST_P(SimulateOnePath, HomeworkFlagsAreTwoBlocksWithTheSameSettings) {
  const OnePathRun& run = GetParam();
  const std::vector<std::string> common{"simulate",     "--case",       std::to_string(run.case_id),
                                        "--integrator", run.integrator, "--stabilize",
                                        run.stabilize,  "--dt",         "0.01",
                                        "--duration",   "0.5",          "--every",
                                        "0.05"};
  const Mechanism two_blocks = load_mechanism("two-blocks");
  // The spec's table by two-blocks' own column names: each name's [aliases] key, if any.
  std::string keys;
  for (const std::string& name : split(kSpecHeader, ',')) {
    std::string key = name;
    for (const Alias& a : two_blocks.aliases)
      if (a.name == name) key = a.key;
    keys += (keys.empty() ? "" : ",") + key;
  }
  std::vector<std::string> homework = common, mechanism = common;
  mechanism.insert(mechanism.end(), {"--mechanism", "two-blocks", "--columns", keys});
  for (const Setting& s : kSettings) {
    homework.insert(homework.end(), {s.flag, s.value});
    mechanism.insert(mechanism.end(), {"--set", std::string(s.key) + "=" + s.value});
  }
  const RunResult a = run_linkage(homework), b = run_linkage(mechanism);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  // The homework's table as it always was: every column by default, in the spec's order.
  ASSERT_EQ(lines_of(a.out).front(), kSpecHeader);
  // The mechanism's header through the aliases; its rows as they are.
  const std::vector<std::string> lines_b = lines_of(b.out);
  ASSERT_FALSE(lines_b.empty());
  std::string header;
  for (const std::string& name : split(lines_b.front(), ',')) {
    if (!header.empty()) header += ',';
    header += two_blocks.aliased(name);
  }
  const std::string rows = b.out.substr(lines_b.front().size());
  EXPECT_EQ(a.out, header + rows) << "every column, bit for bit";
  EXPECT_EQ(lines_of(a.out).size(), 12U) << "0 to 0.5 s every 0.05 s";
}

std::vector<OnePathRun> runs() {
  std::vector<OnePathRun> out;
  for (int case_id : {1, 2, 3})
    for (const char* integrator : {"euler", "symplectic-euler", "rk4", "dopri5", "dop853", "gauss-legendre"})
      for (const char* stabilize : {"none", "baumgarte", "projection"})
        if (case_id == 1 || std::string(stabilize) == "none") out.push_back({case_id, integrator, stabilize});
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryCaseIntegratorAndStabilization, SimulateOnePath, ::testing::ValuesIn(runs()), run_name);

}  // namespace
}  // namespace linkage::test
