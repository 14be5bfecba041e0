#pragma once
// A Program as straight-line C++, so the system compiler can turn the very expressions
// the report prints into native code: one `const double` per instruction's result (the
// interpreter's reused registers renamed apart), constants as exact hexfloat literals,
// sin and cos of one argument by one sincos, and only the libm functions the interpreter
// calls, so the compiled code computes the same operations in the same order.
#include <string>
#include <string_view>

#include "evaluate/program.hpp"

namespace linkage::eval {

/// `extern "C" void FUNCTION(const double* in, const double* state, double* out)`
/// computing `program`'s outputs from its inputs, its state inputs read from `state`.
/// Needs no header (GCC and Clang builtins); the same program and name give the same text.
[[nodiscard]] std::string emit_cpp(const Program& program, std::string_view function_name);

/// A double as a C++ literal of exactly its value: "0x1.8p+1", "(-0x1p-3)", or a builtin
/// for infinities and NaN.
[[nodiscard]] std::string cpp_literal(double value);

}  // namespace linkage::eval
