#pragma once
// Native code compiled into the program: the shipped mechanisms' Programs, generated at
// build time (tools/native_gen.cpp) and handed over by `main` at start-up, since this
// module cannot link the generated library (the generator is built from this module).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "evaluate/native_entry.hpp"
#include "evaluate/program.hpp"

namespace linkage::eval {

/// The table of built-in native code from now on (sorted by fingerprint; not copied, so it
/// must outlive every use: the generated table is static).
void use_builtin_native(std::span<const NativeEntry> table);
/// The built-in function computing a program of `fingerprint`, or nullptr.
[[nodiscard]] NativeFunction builtin_native(std::uint64_t fingerprint);
/// Attaches built-in code to every one of `programs` when each has some; else to none.
[[nodiscard]] bool attach_builtin(const std::vector<Program*>& programs);

/// `programs` as one C++ file of functions and a table `kShippedNative` of NativeEntry,
/// sorted by fingerprint, for the build step (tools/native_gen.cpp).
[[nodiscard]] std::string builtin_native_source(const std::vector<const Program*>& programs);

}  // namespace linkage::eval
