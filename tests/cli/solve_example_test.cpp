// `linkage solve --case all --format json` reproduces the spec's example.json (exact to 17
// digits) key by key under its names (two-blocks.toml's [aliases]): parameters, state and
// derived at the same paths, and for each case every unknown of its "solution", those the
// case solves for in "solution" and those it recovers in "recovered" (Case 3's F_x, ...).
// `--mechanism two-blocks` prints the same numbers under the mechanism contract's names
// ("2.x", "P.force_x"); the spec's names map onto them here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "support/test_support.hpp"

namespace linkage {
namespace {

using nlohmann::json;

// The cases' matrices have condition numbers up to about 1.2e4: a solution is good to
// about that times the machine epsilon, relative; 1e-10 leaves room for the derived sums.
constexpr double kRelative = 1e-10;

// The spec's names in example.json -> the contract's, for two-blocks.toml.
const std::map<std::string, std::string> kContractName = {{"x1", "1.x"},
                                                          {"y1", "1.y"},
                                                          {"theta1", "1.theta"},
                                                          {"theta2", "2.theta"},
                                                          {"x1_dot", "1.x_dot"},
                                                          {"y1_dot", "1.y_dot"},
                                                          {"theta1_dot", "1.theta_dot"},
                                                          {"theta2_dot", "2.theta_dot"},
                                                          {"I_zz_C", "I"},
                                                          {"I_zz_P", "I^P"},
                                                          {"x_P", "P.x"},
                                                          {"y_P", "P.y"},
                                                          {"x2", "2.x"},
                                                          {"y2", "2.y"},
                                                          {"x2_dot", "2.x_dot"},
                                                          {"y2_dot", "2.y_dot"},
                                                          {"x1_ddot", "1.x_ddot"},
                                                          {"y1_ddot", "1.y_ddot"},
                                                          {"theta1_ddot", "1.theta_ddot"},
                                                          {"x2_ddot", "2.x_ddot"},
                                                          {"y2_ddot", "2.y_ddot"},
                                                          {"theta2_ddot", "2.theta_ddot"},
                                                          {"F_x", "P.force_x"},
                                                          {"F_y", "P.force_y"}};

std::string contract(const std::string& spec_name) {
  const auto it = kContractName.find(spec_name);
  return it == kContractName.end() ? spec_name : it->second;
}

json solve_json(std::vector<std::string> args) {
  args.insert(args.begin(), "solve");
  args.insert(args.end(), {"--format", "json"});
  const test::RunResult r = test::run_linkage(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out);
}

void expect_relative(double got, double exact, const std::string& what) {
  EXPECT_LE(std::fabs(got - exact), kRelative * std::fabs(exact)) << what << ": got " << got << ", exact " << exact;
}

TEST(SolveExample, ReproducesEveryValueOfExampleJson) {
  const json& example = test::spec_example();
  const json doc = solve_json({"--case", "all"});

  for (const auto& [key, value] : example["parameters"].items()) {
    ASSERT_TRUE(doc["parameters"].contains(key)) << "parameters." << key << " missing";
    EXPECT_EQ(doc["parameters"][key].get<double>(), test::number(value)) << key;
  }
  for (const auto& [key, value] : example["state"].items()) {
    ASSERT_TRUE(doc["state"].contains(key)) << "state." << key << " missing";
    EXPECT_EQ(doc["state"][key].get<double>(), test::number(value)) << key;
  }
  int compared = 0;
  for (const auto& [key, value] : example["derived"].items()) {
    ASSERT_TRUE(doc["derived"].contains(key)) << "derived." << key << " missing";
    expect_relative(doc["derived"][key].get<double>(), test::number(value), "derived." + key);
    ++compared;
  }
  EXPECT_EQ(compared, 14);

  ASSERT_EQ(doc["cases"].size(), 3u);
  for (const json& c : doc["cases"]) {
    const std::string name = "Case " + std::to_string(c["case"].get<int>());
    int unknowns = 0;
    for (const auto& [key, value] : example["solution"].items()) {
      const bool solved = c["solution"].contains(key);
      ASSERT_TRUE(solved || c["recovered"].contains(key)) << name << " lacks " << key;
      const auto listed = c["unknowns"].get<std::vector<std::string>>();
      EXPECT_EQ(solved, std::find(listed.begin(), listed.end(), key) != listed.end()) << name << " " << key;
      const json& got = solved ? c["solution"][key] : c["recovered"][key];
      expect_relative(got.get<double>(), test::number(value), name + " " + key);
      ++unknowns;
    }
    EXPECT_EQ(unknowns, 8) << name;
  }

  // Every key of example.json at the same place, but its free-text note: the solution
  // (from Case 1, the first case shown) and the units as well.
  for (const auto& [key, value] : example.items()) {
    if (key != "note") {
      EXPECT_TRUE(doc.contains(key)) << key << " missing";
    }
  }
  ASSERT_EQ(doc["solution"].size(), example["solution"].size());
  for (const auto& [key, value] : example["solution"].items()) {
    ASSERT_TRUE(doc["solution"].contains(key)) << "solution." << key << " missing";
    EXPECT_EQ(doc["solution"][key], doc["cases"][0]["solution"][key]) << key;
    expect_relative(doc["solution"][key].get<double>(), test::number(value), "solution." + key);
  }
  for (const auto& [key, unit] : example["units"].items()) EXPECT_EQ(doc["units"][key], unit) << "units." << key;
}

TEST(SolveExample, EachCaseHasTheIssuesFieldsInRowOrder) {
  const json doc = solve_json({});  // --case all is the default
  const std::vector<std::vector<std::string>> labels = {{"1.1", "2.1", "3.1", "4.1", "5.1", "6.1", "7.1", "8.1"},
                                                        {"1.2", "2.2", "3.2", "4.2", "5.2", "6.2"},
                                                        {"1.3", "2.3", "3.3", "4.3"}};
  const std::vector<std::vector<std::string>> unknowns = {
      {"x1_ddot", "y1_ddot", "theta1_ddot", "x2_ddot", "y2_ddot", "theta2_ddot", "F_x", "F_y"},
      {"x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot", "F_x", "F_y"},
      {"x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot"}};
  ASSERT_EQ(doc["cases"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const json& c = doc["cases"][i];
    const std::size_t n = labels[i].size();
    EXPECT_EQ(c["case"].get<std::size_t>(), i + 1);
    EXPECT_EQ(c["equations"].get<std::vector<std::string>>(), labels[i]);
    EXPECT_EQ(c["unknowns"].get<std::vector<std::string>>(), unknowns[i]);
    ASSERT_EQ(c["A"].size(), n);
    for (const json& row : c["A"]) EXPECT_EQ(row.size(), n);
    ASSERT_EQ(c["B"].size(), n);
    // The residual is what it says: || A q - B || recomputed from the printed numbers.
    double sum = 0;
    for (std::size_t r = 0; r < n; ++r) {
      double ax = -c["B"][r].get<double>();
      for (std::size_t k = 0; k < n; ++k)
        ax += c["A"][r][k].get<double>() * c["solution"][unknowns[i][k]].get<double>();
      sum += ax * ax;
    }
    EXPECT_LT(std::sqrt(sum), 1e-13);
    EXPECT_LT(c["residual"].get<double>(), 1e-13);
    EXPECT_GT(c["condition_number"].get<double>(), 1);
    EXPECT_LT(c["condition_number"].get<double>(), 1e6);
  }
  for (const auto& [key, difference] : doc["agreement"].items()) EXPECT_LT(difference.get<double>(), 1e-12) << key;
}

TEST(SolveExample, OneCaseAndInputsFromFileAndFlags) {
  test::TempDir dir;
  test::write_text(dir / "run.toml", "m = 2\ntheta2 = -0.5\n");
  const json doc = solve_json({"--case", "3", "--config", (dir / "run.toml").string(), "--theta2", "0.7"});
  ASSERT_EQ(doc["cases"].size(), 1u);
  EXPECT_EQ(doc["cases"][0]["case"], 3);
  EXPECT_FALSE(doc.contains("agreement"));
  EXPECT_EQ(doc["parameters"]["m"], 2.0);  // from the file
  EXPECT_EQ(doc["state"]["theta2"], 0.7);  // the flag overrides the file
  EXPECT_EQ(doc["parameters"]["L"], 0.3);  // the default
  expect_relative(doc["derived"]["I_zz_C"].get<double>(), 2 * (0.01 + 0.09) / 12, "I_zz_C");

  // The text report says where the inputs came from.
  const test::RunResult text = test::run_linkage(
      {"solve", "--ascii", "--case", "3", "--config", (dir / "run.toml").string(), "--theta2", "0.7"});
  std::string joined;  // undo the prose wrapping
  for (std::size_t i = 0; i < text.out.size(); ++i) {
    const bool wrapped = text.out.compare(i, 3, "\n  ") == 0;
    joined += wrapped ? ' ' : text.out[i];
    if (wrapped) i += 2;
  }
  EXPECT_NE(joined.find("Given: m = 2 (" + (dir / "run.toml").string() +
                        ":1:5), 2.theta = 0.7 (--theta2); the rest as "
                        "in the shipped two-blocks.toml."),
            std::string::npos)
      << text.out.substr(0, 1600);
}

// --mechanism two-blocks is the same solution under the mechanism's own keys: every value
// of the homework's JSON at the key the contract gives it, and no spec name left.
TEST(SolveExample, MechanismTwoBlocksKeepsTheMechanismKeys) {
  const json homework = solve_json({});
  const json mechanism = solve_json({"--mechanism", "two-blocks"});
  for (const char* section : {"parameters", "state", "derived", "solution", "units", "agreement"}) {
    ASSERT_EQ(mechanism[section].size(), homework[section].size()) << section;
    for (const auto& [key, value] : homework[section].items()) {
      ASSERT_TRUE(mechanism[section].contains(contract(key))) << section << "." << contract(key) << " missing";
      EXPECT_EQ(mechanism[section][contract(key)], value) << section << "." << key;
      if (contract(key) != key) {
        EXPECT_FALSE(mechanism[section].contains(key)) << section << "." << key;
      }
    }
  }
  ASSERT_EQ(mechanism["cases"].size(), homework["cases"].size());
  for (std::size_t i = 0; i < homework["cases"].size(); ++i) {
    const json& h = homework["cases"][i];
    const json& m = mechanism["cases"][i];
    std::vector<std::string> unknowns;
    for (const json& u : h["unknowns"]) unknowns.push_back(contract(u.get<std::string>()));
    EXPECT_EQ(m["unknowns"].get<std::vector<std::string>>(), unknowns);
    for (const char* section : {"solution", "recovered"}) {
      ASSERT_EQ(m[section].size(), h[section].size());
      for (const auto& [key, value] : h[section].items()) EXPECT_EQ(m[section][contract(key)], value) << key;
    }
    EXPECT_EQ(m["A"], h["A"]);
    EXPECT_EQ(m["bodies"], h["bodies"]);
    EXPECT_EQ(m["joints"], h["joints"]);
  }
}

}  // namespace
}  // namespace linkage
