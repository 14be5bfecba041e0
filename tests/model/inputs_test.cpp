#include "model/inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "model/inputs_toml.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

TEST(Inputs, DefaultsAreTheSpecExampleAndValid) {
  const Inputs inputs;
  EXPECT_NO_THROW(inputs.validate());
  const auto& example = test::spec_example();
  for (const auto& key : kInputKeys) {
    const auto& table = key.param != nullptr ? example["parameters"] : example["state"];
    EXPECT_EQ(inputs.value(key), table[std::string(key.key)].get<double>()) << key.key;
    EXPECT_EQ(inputs.origin(key), "default");
  }
}

TEST(Inputs, CanonicalTextListsEveryInputInRoundTripForm) {
  Inputs inputs;
  inputs.set(*find_input_key("theta2_dot"), 0.1 + 0.2, "test");
  EXPECT_EQ(canonical_text(inputs),
            "L=0.3;w=0.1;b=0.04;m=0.1;g=9.81;x1=1;y1=2;theta1=0.1;theta2=0.2;x1_dot=0.15;"
            "y1_dot=0.25;theta1_dot=0.35;theta2_dot=0.30000000000000004");
  Inputs other;
  other.set(*find_input_key("theta2_dot"), 0.3, "test");
  EXPECT_NE(canonical_text(inputs), canonical_text(other));
}

TEST(Inputs, RangeErrorsNameValueOriginAndRange) {
  Inputs inputs;
  inputs.set(*find_input_key("b"), 0.5, "--b");
  const std::string message = error_of([&] { inputs.validate(); });
  EXPECT_NE(message.find("--b"), std::string::npos) << message;
  EXPECT_NE(message.find("0.5"), std::string::npos) << message;
  EXPECT_NE(message.find("[0, L] = [0, 0.3]"), std::string::npos) << message;

  Inputs negative;
  negative.set(*find_input_key("g"), -9.81, "--g");
  EXPECT_NE(error_of([&] { negative.validate(); }).find("g must be >= 0"), std::string::npos);
  EXPECT_NE(error_of([&] { negative.set(*find_input_key("m"), NAN, "--m"); }).find("not a finite number"),
            std::string::npos);
}

TEST(Inputs, TomlFileErrorsNameFileLineAndColumn) {
  test::TempDir dir;
  const auto file = dir / "run.toml";
  test::write_text(file, "L = 0.5\n  thetta1 = 0.3\n");
  const std::string message = error_of([&] { Inputs().apply_file(file); });
  EXPECT_NE(message.find(file.string() + ":2:3: unknown key 'thetta1' (did you mean 'theta1'?)"), std::string::npos)
      << message;
  EXPECT_NE(message.find("valid keys: L, w, b, m, g, x1"), std::string::npos) << message;

  test::write_text(file, "m = \"heavy\"\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(":1:5: m must be a number in kg, got a string"),
            std::string::npos);

  test::write_text(file, "m = 0.2\nL = = 3\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(file.string() + ":2:"), std::string::npos);

  EXPECT_NE(error_of([&] { Inputs().apply_file(dir / "missing.toml"); }).find("does not exist"), std::string::npos);
}

using test::repeat;

// toml++ recurses once per part of a dotted key: a key of 100,000 parts overflowed the
// stack. Keys are bounded before toml++ sees them; dots in values, strings and comments
// do not count.
TEST(Inputs, TomlKeysNestAsDeepAsTheBoundAndNoDeeper) {
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
  const auto error_in = [&](const std::string& text) {
    test::write_text(file, text);
    return error_of([&] { (void)parse_toml_file(file.string(), "--config"); });
  };
  EXPECT_EQ(error_in("x = 1\na" + repeat(".a", kMaxNesting + 1) + " = 1\n"), file.string() + ":2:1" + too_deep);
  EXPECT_EQ(error_in("a" + repeat(".a", 100000) + " = 1\n"), file.string() + ":1:1" + too_deep);
  EXPECT_EQ(error_in("[" + repeat("a.", 100000) + "a]\n"), file.string() + ":1:2" + too_deep);
  EXPECT_EQ(error_in("[[" + repeat("a . ", 100000) + "a]]\n"), file.string() + ":1:3" + too_deep);
  EXPECT_EQ(error_in("θ = { " + repeat("\"a\".", 100000) + "b = 1 }\n"), file.string() + ":1:7" + too_deep);
}

TEST(Inputs, TomlValuesApplyWithTheirPosition) {
  test::TempDir dir;
  const auto file = dir / "run.toml";
  test::write_text(file, "m = 2\ntheta2_dot = -1.5\n");
  Inputs inputs;
  inputs.apply_file(file);
  EXPECT_EQ(inputs.params().m, 2.0);
  EXPECT_EQ(inputs.state().theta2_dot, -1.5);
  EXPECT_EQ(inputs.origin(*find_input_key("theta2_dot")), file.string() + ":2:14");
}

}  // namespace
}  // namespace linkage
