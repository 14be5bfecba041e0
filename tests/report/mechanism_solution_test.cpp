// The values a text may quote from a mechanism's solution: the names and numbers of
// `linkage solve --mechanism --format json`, and the parameters and inertias besides.
#include "report/mechanism_solution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "model/mechanism_toml.hpp"
#include "symbolic/system.hpp"

namespace linkage {
namespace {

TEST(QuotableValues, AreTheJsonNumbersAndTheParameters) {
  for (const std::string& name : shipped_mechanism_names()) {
    const sym::System system(load_mechanism(name));
    const auto values = quotable_values(system);
    const nlohmann::json json =
        nlohmann::json::parse(mechanism_json(work_out_mechanism(system.mechanism(), case_ids({3}))));
    std::size_t checked = 0;
    auto expect_all = [&](const nlohmann::json& group) {
      for (const auto& [key, number] : group.items()) {
        if (!number.is_number()) continue;
        ASSERT_TRUE(values.count(key)) << name << ": " << key;
        EXPECT_NEAR(sym::evaluate(values.at(key), {}), number.get<double>(),
                    1e-12 * (1 + std::fabs(number.get<double>())))
            << name << ": " << key;
        ++checked;
      }
    };
    expect_all(json.at("parameters"));
    expect_all(json.at("state"));
    expect_all(json.at("cases").at(0).at("solution"));
    EXPECT_GT(checked, 5u) << name;
    for (const Parameter& p : system.mechanism().parameters)
      EXPECT_DOUBLE_EQ(sym::evaluate(values.at(p.name), {}), p.value) << name << ": " << p.name;
  }
}

}  // namespace
}  // namespace linkage
