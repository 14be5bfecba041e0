// emit_cpp's text: literals of exactly the constants' values, one name per instruction's
// result (the interpreter's reused registers renamed apart), one sincos per pair.
#include "evaluate/emit_cpp.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <regex>
#include <set>
#include <string>

namespace linkage::eval {
namespace {

TEST(EmitCpp, LiteralsReadBackToTheSameBits) {
  const double values[] = {3.0,
                           -0.125,
                           0.1,
                           -0.0,
                           1.0 / 3.0,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           -6.02214076e23};
  for (const double v : values) {
    std::string text = cpp_literal(v);
    // "(-0x...)" is the negation of the literal inside.
    const bool negative = text.rfind("(-", 0) == 0;
    if (negative) text = text.substr(2, text.size() - 3);
    const double back = (negative ? -1.0 : 1.0) * std::strtod(text.c_str(), nullptr);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << cpp_literal(v);
  }
  EXPECT_EQ(cpp_literal(3.0), "0x1.8p+1");
  EXPECT_EQ(cpp_literal(std::numeric_limits<double>::infinity()), "__builtin_inf()");
}

TEST(EmitCpp, EachResultHasItsOwnNameAndSinCosIsOneCall) {
  const GiNaC::symbol x("x"), y("y");
  // Many temporaries, so the interpreter reuses registers.
  const Program p = compile(
      {GiNaC::sin(x) * GiNaC::cos(x) + GiNaC::pow(x + y, 3) - GiNaC::exp(y) / (x * x + 1), GiNaC::cos(x)}, {x, y});
  const std::string code = emit_cpp(p, "f");
  EXPECT_NE(code.find("extern \"C\" void f(const double* in, const double* state, double* out) {"), std::string::npos)
      << code;
  const std::regex local("const double (t[0-9]+) =");
  std::set<std::string> names;
  std::size_t locals = 0;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), local); it != std::sregex_iterator(); ++it, ++locals)
    names.insert((*it)[1]);
  EXPECT_EQ(names.size(), locals) << code;
  EXPECT_EQ(locals + 1, p.instruction_count()) << code;  // every instruction but the sincos
  std::size_t sincos = 0;
  for (std::size_t at = code.find("__builtin_sincos("); at != std::string::npos;
       at = code.find("__builtin_sincos(", at + 1))
    ++sincos;
  EXPECT_EQ(sincos, 1U) << code;
  EXPECT_EQ(code.find("__builtin_sin("), std::string::npos) << code;
  EXPECT_EQ(emit_cpp(p, "f"), code);  // deterministic
  EXPECT_NE(code.find("const double i1 = in[1];"), std::string::npos) << code;
  Program apart = p;
  apart.read_state_from(1, 1);
  const std::string reading = emit_cpp(apart, "f");
  EXPECT_NE(reading.find("const double i0 = in[0];"), std::string::npos) << reading;
  EXPECT_NE(reading.find("const double i1 = state[0];"), std::string::npos) << reading;
}

}  // namespace
}  // namespace linkage::eval
