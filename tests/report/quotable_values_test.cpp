// The values a lesson may quote about a mechanism: the names and numbers of `linkage solve
// --mechanism --format json` and the parameters, inertias, centre of mass and each case's
// condition number and residual besides; on two-blocks also by its [aliases], the
// homework's names, which keep the spec's worked example and their relations.
#include "report/quotable_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "model/mechanism_toml.hpp"
#include "report/mechanism_solution.hpp"
#include "support/test_support.hpp"
#include "symbolic/system.hpp"

namespace linkage {
namespace {

double number(const QuotableValues& v, const std::string& name) {
  EXPECT_TRUE(v.has(name)) << name;
  return v.has(name) ? sym::to_double(v.value(name)) : 0.0;
}

TEST(QuotableValues, AreTheJsonNumbersAndTheParameters) {
  for (const std::string& name : shipped_mechanism_names()) {
    const auto system = std::make_shared<const sym::System>(load_mechanism(name));
    const QuotableValues values(system);
    const nlohmann::json json = nlohmann::json::parse(mechanism_json(work_out_mechanism(system, case_ids({1, 2, 3}))));
    std::size_t checked = 0;
    auto expect_all = [&](const nlohmann::json& group) {
      for (const auto& [key, value] : group.items()) {
        if (!value.is_number()) continue;
        EXPECT_NEAR(number(values, key), value.get<double>(), 1e-12 * (1 + std::fabs(value.get<double>())))
            << name << ": " << key;
        ++checked;
      }
    };
    expect_all(json.at("parameters"));
    expect_all(json.at("state"));
    expect_all(json.at("derived"));
    expect_all(json.at("cases").at(2).at("solution"));
    EXPECT_GT(checked, 5u) << name;
    for (const Parameter& p : system->mechanism().parameters)
      EXPECT_DOUBLE_EQ(number(values, p.name), p.value) << name << ": " << p.name;
    // Each case's condition number and residual, Cases 1 and 2 worked out when asked for.
    for (int c = 1; c <= 3; ++c) {
      const nlohmann::json& one = json.at("cases").at(static_cast<std::size_t>(c - 1));
      EXPECT_DOUBLE_EQ(number(values, "cond" + std::to_string(c)), one.at("condition_number").get<double>()) << name;
      EXPECT_DOUBLE_EQ(number(values, "residual" + std::to_string(c)), one.at("residual").get<double>()) << name;
    }
    EXPECT_TRUE(values.unit("cond1").empty());
  }
}

// The homework's quantities are two-blocks' by its [aliases]; the spec's worked example.
TEST(QuotableValues, TwoBlocksByItsAliasesIsTheSpecExample) {
  const QuotableValues v(std::make_shared<const sym::System>(load_mechanism("two-blocks")));
  const auto& derived = test::spec_example()["derived"];
  const auto& solution = test::spec_example()["solution"];
  for (const char* name : {"I_zz_C", "I_zz_P", "D"})
    EXPECT_NEAR(number(v, name), test::number(derived[name]), 1e-15) << name;
  for (const char* name : {"x_P", "y_P", "x2", "y2", "energy"})
    EXPECT_NEAR(number(v, name), test::number(derived[name]), 1e-12) << name;
  // From Case 3: the spec's (Case 1's) to round-off of the 4x4 solve.
  for (const char* name : {"x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot", "F_x", "F_y"})
    EXPECT_NEAR(number(v, name) / test::number(solution[name]), 1.0, 1e-9) << name;
  EXPECT_EQ(number(v, "x1_ddot"), number(v, "1.x_ddot")) << "an alias names the same value";
  EXPECT_EQ(v.unit("I_zz_P"), "kg m^2");
  EXPECT_EQ(v.unit("F_x"), "N");
  EXPECT_EQ(v.unit("x_com_dot"), "m/s");
  EXPECT_FALSE(v.has("I_zz_Q"));
}

// The relations the homework's closed form had, on the general values at other settings.
TEST(QuotableValues, HoldTheHomeworksRelations) {
  Mechanism m = load_mechanism("two-blocks");
  for (Parameter& p : m.parameters)
    if (p.name == "m") p.value = 0.2;
  for (InitialValue& i : m.initial)
    if (i.key == "2.theta_dot") i.value = -1.5;
  const QuotableValues v(std::make_shared<const sym::System>(m));
  const double mass = 0.2, D = number(v, "L") / 2 - number(v, "b");
  EXPECT_NEAR(number(v, "I_zz_C"), mass * (0.1 * 0.1 + 0.3 * 0.3) / 12, 1e-15);
  EXPECT_NEAR(number(v, "I_zz_P"), number(v, "I_zz_C") + mass * D * D, 1e-15);
  EXPECT_NEAR(number(v, "x_com"), (number(v, "x1") + number(v, "x2")) / 2, 1e-15);
  EXPECT_NEAR(number(v, "y_com_dot"), (number(v, "y1_dot") + number(v, "y2_dot")) / 2, 1e-15);
  EXPECT_NEAR(number(v, "momentum_x"), mass * (number(v, "x1_dot") + number(v, "x2_dot")), 1e-15);
  EXPECT_NEAR(number(v, "energy"), number(v, "kinetic_energy") + number(v, "potential_energy"), 1e-12);
  // The pin force on block 2 is -F: its x acceleration is -F_x / m.
  EXPECT_NEAR(number(v, "x2_ddot"), -number(v, "F_x") / mass, 1e-12);
  EXPECT_GE(number(v, "cond1"), 1.0);
  EXPECT_GE(number(v, "cond3"), 1.0);
  EXPECT_LT(number(v, "residual1"), 1e-12);
}

}  // namespace
}  // namespace linkage
