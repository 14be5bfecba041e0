#include "model/inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

TEST(Inputs, DefaultsAreTheSpecExampleAndValid) {
  const Inputs inputs;
  EXPECT_NO_THROW(inputs.validate());
  const auto& example = test::spec_example();
  for (const auto& key : kInputKeys) {
    const auto& table = key.parameter ? example["parameters"] : example["state"];
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

}  // namespace
}  // namespace linkage
