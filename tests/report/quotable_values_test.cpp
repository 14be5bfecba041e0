// The values a lesson may quote about a mechanism: the names and numbers of `linkage solve
// --mechanism --format json` and the parameters, inertias, centre of mass and each case's
// condition number and residual besides; on two-blocks also by its [aliases], the
// homework's names, which keep the spec's worked example and their relations; the
// modes' numbers, against the double pendulum's closed form.
#include "report/quotable_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "report/mechanism_solution.hpp"
#include "support/closed_forms.hpp"
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

TEST(QuotableValues, TheModesMatchTheDoublePendulumsClosedForm) {
  Mechanism m = load_mechanism("double-pendulum");
  for (const char* s : {"l1=0.7", "m1=1.3", "l2=0.4", "m2=0.55"}) apply_setting(m, s, "test");
  const QuotableValues values(std::make_shared<const sym::System>(m));
  EXPECT_EQ(number(values, "modes.count"), 2);
  const auto w2 = test::double_pendulum_w2(0.7, 1.3, 0.4, 0.55, 9.81, 1);
  for (int k = 1; k <= 2; ++k) {
    const std::string mode = "mode" + std::to_string(k);
    const double omega = std::sqrt(w2[static_cast<std::size_t>(k - 1)]);
    EXPECT_NEAR(number(values, mode + ".omega") / omega, 1, 1e-10) << mode;
    EXPECT_NEAR(number(values, mode + ".frequency_hz") * 2 * std::numbers::pi / omega, 1, 1e-10) << mode;
    EXPECT_NEAR(number(values, mode + ".period") * omega / (2 * std::numbers::pi), 1, 1e-10) << mode;
    EXPECT_EQ(number(values, mode + ".damping_ratio"), 0) << mode;
    // The shape: rod 2 leads (1), rod 1 in phase in mode 1 and against it in mode 2; K v = w^2 M v's
    // first row, (K11 - w^2 M11) v1 = w^2 M12 v2, gives v1.
    const double M11 = (1.3 / 3 + 0.55) * 0.49, M12 = 0.55 * 0.7 * 0.4 / 2, K11 = (1.3 / 2 + 0.55) * 9.81 * 0.7;
    const double w = omega * omega;
    EXPECT_EQ(number(values, "2.theta_" + mode), 1) << mode;
    EXPECT_NEAR(number(values, "1.theta_" + mode), w * M12 / (K11 - w * M11), 1e-10) << mode;
  }
  EXPECT_EQ(values.unit("mode2.frequency_hz"), "Hz");
  EXPECT_EQ(values.unit("mode1.omega"), "rad/s");
  EXPECT_EQ(values.unit("mode1.period"), "s");
  EXPECT_EQ(values.unit("mode1.growth_rate"), "1/s");
  EXPECT_FALSE(values.has("mode3.omega"));
  // A hanging pendulum oscillates: no growth rate.
  try {
    (void)values.value("mode1.growth_rate");
    ADD_FAILURE() << "mode1.growth_rate of an oscillation";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("mode1.growth_rate: mode 1 of double-pendulum oscillates (omega 3.70069 "
                                         "rad/s): it has no growth_rate; valid: mode1.omega"),
              0U)
        << e.what();
  }
}

TEST(QuotableValues, AnUprightPendulumsModesGrowAndHaveNoFrequency) {
  Mechanism m = load_mechanism("double-pendulum");
  for (const char* s : {"1.theta=1.4", "2.theta=1.7"}) apply_setting(m, s, "test");
  const QuotableValues values(std::make_shared<const sym::System>(m));
  const auto w2 = test::double_pendulum_w2(0.3, 0.2, 0.25, 0.15, 9.81, -1);
  // Upright the roots are negative: sigma = sqrt(-w^2), the faster first.
  EXPECT_NEAR(number(values, "mode1.growth_rate") / std::sqrt(-w2[0]), 1, 1e-10);
  for (const char* name : {"mode1.omega", "mode2.frequency_hz", "mode2.period", "mode1.damping_ratio"}) {
    try {
      (void)values.value(name);
      ADD_FAILURE() << name << " of an unstable mode";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("is unstable (it grows at "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(".growth_rate"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace linkage
