#pragma once
// The shape of native code for a Program, apart from program.hpp so that generated code
// (tools/native_gen.cpp) compiles without GiNaC's headers.
#include <cstdint>

namespace linkage::eval {

/// Compiled code for one Program (evaluate/emit_cpp.hpp): outputs from inputs, no scratch.
/// The program's state inputs (Program::read_state_from) are read from `state`, the others
/// from `in`, so a right-hand side reads y where it is, with no copy into `in`.
using NativeFunction = void (*)(const double* in, const double* state, double* out);

/// One row of a table of native code: the function computing the Program of `fingerprint`.
struct NativeEntry {
  std::uint64_t fingerprint = 0;
  NativeFunction function = nullptr;
};

}  // namespace linkage::eval
