#include "report/json_layout.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace linkage
