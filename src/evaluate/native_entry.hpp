#pragma once
// The shape of native code for a Program, apart from program.hpp so that generated code
// (tools/native_gen.cpp) compiles without GiNaC's headers.
#include <cstdint>

namespace linkage::eval {

/// Compiled code for one Program (evaluate/emit_cpp.hpp): outputs from inputs, no scratch.
using NativeFunction = void (*)(const double* in, double* out);

/// One row of a table of native code: the function computing the Program of `fingerprint`.
struct NativeEntry {
  std::uint64_t fingerprint = 0;
  NativeFunction function = nullptr;
};

}  // namespace linkage::eval
