#pragma once
// The shipped mechanisms' native code, defined by the generated library
// linkage_native_shipped (tools/native_gen.cpp); `main` hands it to evaluate.
#include <cstddef>

#include "evaluate/native_entry.hpp"

namespace linkage::eval {
extern const NativeEntry kShippedNative[];
extern const std::size_t kShippedNativeCount;
}  // namespace linkage::eval
