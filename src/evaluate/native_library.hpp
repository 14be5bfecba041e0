#pragma once
// Native code for the Programs of one run: their C++ (emit_cpp.hpp) in one translation
// unit, compiled by the system's C++ compiler into a shared object, cached by the hash of
// that source and loaded with dlopen; each Program then runs its own function (by
// fingerprint) instead of the interpreter. Anything that stops this (no compiler, a
// failed compile, an unsafe cache folder) leaves every Program interpreted and says why.
//
// The cache is $XDG_CACHE_HOME/linkage/native (else $HOME/.cache/linkage/native), one
// HASH.so per source. Loading a shared object runs its code, so a folder or file that is
// not this user's or that others can write is refused; an entry that does not load or
// whose version or source hash differ from what was asked is deleted and rebuilt.
// Loaded libraries stay loaded for the process's lifetime (attached Programs call into them).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "evaluate/program.hpp"

namespace linkage::eval {

/// The one translation unit for `programs`: a function per distinct fingerprint (in
/// fingerprint order, so the same programs give the same text in any order), a table
/// {fingerprint, function}, the generator version and the hash of the text before it.
struct NativeSource {
  std::string text;
  std::string hash;  // content_hash of the text up to the hash's own symbol; names the cache entry
  std::size_t functions = 0;
};
[[nodiscard]] NativeSource native_source(const std::vector<const Program*>& programs);

/// $XDG_CACHE_HOME/linkage/native when XDG_CACHE_HOME is an absolute path, else
/// $HOME/.cache/linkage/native; empty when neither is set.
[[nodiscard]] std::filesystem::path native_cache_folder();

/// Whether the system's C++ compiler (c++) is on PATH.
[[nodiscard]] bool native_compiler_found();

struct NativeAttachment {
  bool attached = false;  // every Program runs native code
  std::string reason;     // when not: why the interpreter runs, one line
  bool compiled = false;  // the compiler ran (else the cached entry was used)
  std::string rebuilt;    // why a cached entry was deleted and rebuilt ("" when none was)
  std::filesystem::path library;
  std::size_t functions = 0;
};

/// Attaches native code to every one of `programs`, or to none. Without `may_compile`,
/// only a cached entry is used (the compiler never runs). Throws only interrupted_error
/// (a signal while the compiler runs).
[[nodiscard]] NativeAttachment attach_native(const std::vector<Program*>& programs, bool may_compile = true);

}  // namespace linkage::eval
