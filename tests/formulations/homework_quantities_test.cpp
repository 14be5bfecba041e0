// The homework's named quantities against the statement's worked example, and their
// relations (parallel axes, centre of mass, momentum).
#include "formulations/homework_quantities.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace linkage {
namespace {

double value(const QuantityValues& v, std::string_view name) {
  const auto i = find_quantity(name);
  EXPECT_TRUE(i.has_value()) << name;
  return i ? v[*i] : 0.0;
}

TEST(HomeworkQuantities, MatchTheSpecExample) {
  const QuantityValues v = evaluate_quantities(Inputs{});
  const auto& derived = test::spec_example()["derived"];
  const auto& solution = test::spec_example()["solution"];
  for (const char* name : {"I_zz_C", "I_zz_P", "D"})
    EXPECT_NEAR(value(v, name), test::number(derived[name]), 1e-15) << name;
  for (const char* name : {"x_P", "y_P", "x2", "y2", "energy"})
    EXPECT_NEAR(value(v, name), test::number(derived[name]), 1e-12) << name;
  for (const char* name : {"x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot", "F_x", "F_y"})
    EXPECT_NEAR(value(v, name) / test::number(solution[name]), 1.0, 1e-9) << name;
}

TEST(HomeworkQuantities, HoldTheirRelations) {
  Inputs inputs;
  inputs.set(*find_input_key("m"), 0.2, "test");
  inputs.set(*find_input_key("theta2_dot"), -1.5, "test");
  const QuantityValues v = evaluate_quantities(inputs);
  const double m = 0.2, D = value(v, "L") / 2 - value(v, "b");
  EXPECT_NEAR(value(v, "I_zz_C"), m * (0.1 * 0.1 + 0.3 * 0.3) / 12, 1e-15);
  EXPECT_NEAR(value(v, "I_zz_P"), value(v, "I_zz_C") + m * D * D, 1e-15);
  EXPECT_NEAR(value(v, "x_com"), (value(v, "x1") + value(v, "x2")) / 2, 1e-15);
  EXPECT_NEAR(value(v, "momentum_x"), m * (value(v, "x1_dot") + value(v, "x2_dot")), 1e-15);
  EXPECT_NEAR(value(v, "energy"), value(v, "kinetic_energy") + value(v, "potential_energy"), 1e-12);
  // The pin force on block 2 is -F: its x acceleration is -F_x / m.
  EXPECT_NEAR(value(v, "x2_ddot"), -value(v, "F_x") / m, 1e-12);
  EXPECT_GE(value(v, "cond3"), 1.0);
  EXPECT_FALSE(find_quantity("I_zz_Q").has_value());
}

}  // namespace
}  // namespace linkage
