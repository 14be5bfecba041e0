#include "report/json_report.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "report/text_layout.hpp"

namespace linkage {
namespace {

using nlohmann::ordered_json;

TEST(JsonLayout, RowsOnOneLineAndParsesBackToTheSameValue) {
  const ordered_json doc = ordered_json::parse(
      R"({"short": {"a": 1, "b": [1, 2]}, "flat": {"x": 1.5, "y": "text"}, "A": [[1, 2.5], [-3, 4e-20]],
          "long": {"k1": 0.1234567890123, "k2": 0.1234567890123, "k3": 0.1234567890123, "k4": 0.1234567890123},
          "empty": [], "none": {}})");
  const std::string text = json_layout(doc);
  EXPECT_EQ(ordered_json::parse(text), doc);
  EXPECT_NE(text.find("\n  \"flat\": {\"x\": 1.5, \"y\": \"text\"},\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    [1, 2.5],\n    [-3, 4e-20]\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    \"k4\": 0.1234567890123\n"), std::string::npos) << text;  // too long for one line
  EXPECT_NE(text.find("\"empty\": [],"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(JsonReport, HasTheIssuesKeysInOrder) {
  const ordered_json doc = ordered_json::parse(json_report(work_out(Inputs{}, {1, 2, 3})));
  std::vector<std::string> keys;
  for (const auto& [key, value] : doc.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"parameters", "state", "derived", "cases", "agreement"}));
  ASSERT_EQ(doc["cases"].size(), 3u);
  const ordered_json& case2 = doc["cases"][1];
  EXPECT_EQ(case2["case"], 2);
  EXPECT_EQ(case2["unknowns"],
            ordered_json::parse(R"(["x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot", "F_x", "F_y"])"));
  EXPECT_EQ(case2["equations"], ordered_json::parse(R"(["1.2", "2.2", "3.2", "4.2", "5.2", "6.2"])"));
  EXPECT_EQ(case2["A"].size(), 6u);
  EXPECT_EQ(case2["A"][0].size(), 6u);
  EXPECT_EQ(case2["B"].size(), 6u);
  EXPECT_EQ(case2["recovered"].size(), 2u);
  EXPECT_TRUE(case2["residual"].is_number());
  EXPECT_GT(case2["condition_number"].get<double>(), 1.0);
  EXPECT_FALSE(ordered_json::parse(json_report(work_out(Inputs{}, {3}))).contains("agreement"));
  // Each matrix row on one line: the document stays short.
  const std::string text = json_report(work_out(Inputs{}, {1, 2, 3}));
  EXPECT_LT(std::count(text.begin(), text.end(), '\n'), 160);
}

}  // namespace
}  // namespace linkage
