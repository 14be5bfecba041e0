#include "model/inputs_toml.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

TEST(InputsToml, FileErrorsNameFileLineAndColumn) {
  test::TempDir dir;
  const auto file = dir / "run.toml";
  test::write_text(file, "L = 0.5\n  thetta1 = 0.3\n");
  const std::string message = error_of([&] { Inputs().apply_file(file); });
  EXPECT_NE(message.find(file.string() + ":2:3: config: unknown key 'thetta1' (did you mean 'theta1'?)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("; valid keys: L, w, b, m, g, x1"), std::string::npos) << message;

  test::write_text(file, "m = \"heavy\"\n");
  EXPECT_EQ(error_of([&] { Inputs().apply_file(file); }),
            file.string() + ":1:5: config: 'm' must be a number in kg, got a string");
  test::write_text(file, "m = 0.2\ntheta2_dot = -inf\n");
  EXPECT_EQ(error_of([&] { Inputs().apply_file(file); }),
            file.string() + ":2:14: config: 'theta2_dot' = -inf is not a finite number");
  // The first unknown key in file order (toml++ sorts keys by name), before any value.
  test::write_text(file, "zeta = 1\nm = \"x\"\nalpha = 2\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(":1:1: config: unknown key 'zeta'"), std::string::npos);

  test::write_text(file, "m = 0.2\nL = = 3\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(file.string() + ":2:"), std::string::npos);

  EXPECT_NE(error_of([&] { Inputs().apply_file(dir / "missing.toml"); }).find("does not exist"), std::string::npos);
}

using test::repeat;

// toml++ recurses once per part of a dotted key: a key of 100,000 parts overflowed the
// stack. Keys are bounded before toml++ sees them; dots in values, strings and comments
// do not count.
TEST(InputsToml, KeysNestAsDeepAsTheBoundAndNoDeeper) {
  test::TempDir dir;
  const auto file = dir / "deep.toml";
  const std::string dots = repeat(".", 200);
  test::write_text(file, "# " + dots + "\ns = \"" + dots + "\" # " + dots + "\nl = '" + dots + "'\nm = \"\"\"\n" +
                             dots + "\n\"\"\"\nn = '''" + dots +
                             "'''\nf = [1.5, 2.5, 1e-3, 3.25]\n[t]\n\"a.b\".c = 1\n" + "a" + repeat(".a", kMaxNesting) +
                             " = 1\n");
  const toml::table table = parse_toml_file(file.string(), "--config");
  EXPECT_EQ(table["s"].value_or(std::string()), dots);
  EXPECT_EQ(table["n"].value_or(std::string()), dots);
  EXPECT_EQ(table["t"]["a.b"]["c"].value_or(0), 1);

  const std::string too_deep =
      ": the key is nested more than " + std::to_string(kMaxNesting) + " levels deep (each '.' is a level)";
  // Appended, not "literal" + std::string (GCC 12's false -Wrestrict).
  const auto cat = [](std::initializer_list<std::string_view> parts) {
    std::string out;
    for (std::string_view part : parts) out += part;
    return out;
  };
  const auto error_in = [&](const std::string& text) {
    test::write_text(file, text);
    return error_of([&] { (void)parse_toml_file(file.string(), "--config"); });
  };
  EXPECT_EQ(error_in(cat({"x = 1\na", repeat(".a", kMaxNesting + 1), " = 1\n"})), file.string() + ":2:1" + too_deep);
  EXPECT_EQ(error_in(cat({"a", repeat(".a", 100000), " = 1\n"})), file.string() + ":1:1" + too_deep);
  EXPECT_EQ(error_in(cat({"[", repeat("a.", 100000), "a]\n"})), file.string() + ":1:2" + too_deep);
  EXPECT_EQ(error_in(cat({"[[", repeat("a . ", 100000), "a]]\n"})), file.string() + ":1:3" + too_deep);
  EXPECT_EQ(error_in(cat({"θ = { ", repeat("\"a\".", 100000), "b = 1 }\n"})), file.string() + ":1:7" + too_deep);
}

TEST(InputsToml, ValuesApplyWithTheirPosition) {
  test::TempDir dir;
  const auto file = dir / "run.toml";
  test::write_text(file, "m = 2\ntheta2_dot = -1.5\n");
  Inputs inputs;
  inputs.apply_file(file);
  EXPECT_EQ(inputs.value(*find_input_key("m")), 2.0);
  EXPECT_EQ(inputs.value(*find_input_key("theta2_dot")), -1.5);
  EXPECT_EQ(inputs.origin(*find_input_key("theta2_dot")), file.string() + ":2:14");
}

// A lesson's [parameters] and [state] read through the same function, under their own name.
TEST(InputsToml, ApplyNamesItsTableAndKeepsEveryPosition) {
  const toml::table table = parse_toml_text("m = 0.25\n\ntheta1 = 0.5\n", "l.toml", "lesson");
  Inputs inputs;
  apply_toml(inputs, table, "l.toml", "[parameters]");
  EXPECT_EQ(inputs.value(*find_input_key("m")), 0.25);
  EXPECT_EQ(inputs.value(*find_input_key("theta1")), 0.5);
  EXPECT_EQ(inputs.origin(*find_input_key("theta1")), "l.toml:3:10");
  EXPECT_EQ(inputs.origin(*find_input_key("L")), "default");

  const toml::table typo = parse_toml_text("[state]\nx1_dto = 1\n", "l.toml", "lesson");
  EXPECT_EQ(error_of([&] { apply_toml(inputs, *typo["state"].as_table(), "l.toml", "[state]"); }),
            "l.toml:2:1: [state]: unknown key 'x1_dto' (did you mean 'x1_dot'?); valid keys: L, w, b, m, g, x1, y1, "
            "theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot");
  const toml::table boolean = parse_toml_text("g = true\n", "l.toml", "lesson");
  EXPECT_EQ(error_of([&] { apply_toml(inputs, boolean, "l.toml", "[parameters]"); }),
            "l.toml:1:5: [parameters]: 'g' must be a number in m/s^2, got a boolean");
}

}  // namespace
}  // namespace linkage
