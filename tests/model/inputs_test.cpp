#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "model/inputs.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

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
  EXPECT_NE(error_of([&] { negative.set(*find_input_key("m"), NAN, "--m"); }).find("not a finite number"), std::string::npos);
}

TEST(Inputs, TomlFileErrorsNameFileLineAndColumn) {
  test::TempDir dir;
  const auto file = dir / "run.toml";
  test::write_text(file, "L = 0.5\n  thetta1 = 0.3\n");
  const std::string message = error_of([&] { Inputs().apply_file(file); });
  EXPECT_NE(message.find(file.string() + ":2:3: unknown key 'thetta1' (did you mean 'theta1'?)"), std::string::npos) << message;
  EXPECT_NE(message.find("valid keys: L, w, b, m, g, x1"), std::string::npos) << message;

  test::write_text(file, "m = \"heavy\"\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(":1:5: m must be a number in kg, got a string"), std::string::npos);

  test::write_text(file, "m = 0.2\nL = = 3\n");
  EXPECT_NE(error_of([&] { Inputs().apply_file(file); }).find(file.string() + ":2:"), std::string::npos);

  EXPECT_NE(error_of([&] { Inputs().apply_file(dir / "missing.toml"); }).find("does not exist"), std::string::npos);
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
