#include "evaluate/native_library.hpp"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"
#include "core/error.hpp"
#include "core/run_program.hpp"
#include "evaluate/emit_cpp.hpp"

namespace linkage::eval {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kCompiler = "c++";
// A long chain's programs are long; a compile that has not ended by then will not.
constexpr std::chrono::minutes kCompileTimeout{10};

// The table's layout, as the generated source declares it.
struct Entry {
  unsigned long long fingerprint;
  NativeFunction function;
};

std::string hex(std::uint64_t v) {
  std::ostringstream out;
  out << std::hex << v;
  return out.str();
}

std::optional<fs::path> find_compiler() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view rest(path);
  while (true) {
    const std::size_t colon = rest.find(':');
    const std::string_view dir = rest.substr(0, colon);
    // An empty entry would mean the working folder: not a place to take a compiler from.
    if (!dir.empty()) {
      const fs::path candidate = fs::path(dir) / kCompiler;
      std::error_code ec;
      if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    if (colon == std::string_view::npos) return std::nullopt;
    rest.remove_prefix(colon + 1);
  }
}

// Why `path` is unsafe to load code from, or "" when it is this user's and only theirs to write.
std::string unsafe(const fs::path& path, bool folder) {
  struct stat s {};
  if (::lstat(path.c_str(), &s) != 0) return "cannot read " + quoted(path) + ": " + std::strerror(errno);
  if (folder ? !S_ISDIR(s.st_mode) : !S_ISREG(s.st_mode))
    return quoted(path) + (folder ? " is not a folder" : " is not a regular file");
  if (s.st_uid != ::geteuid()) return quoted(path) + " belongs to another user";
  if ((s.st_mode & (S_IWGRP | S_IWOTH)) != 0) return quoted(path) + " can be written by other users";
  return "";
}

// Makes `folder` (owner-only) when missing; the reason it cannot be used, or "".
std::string prepare_folder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) {
    fs::create_directories(folder.parent_path(), ec);
    if (fs::create_directory(folder, ec)) fs::permissions(folder, fs::perms::owner_all, ec);
    if (ec) return "cannot create " + quoted(folder) + ": " + ec.message();
  }
  return unsafe(folder, true);
}

// The compiler's first line that reports an error (else its first line).
std::string first_error(const std::string& output) {
  std::istringstream in(output);
  std::string line, first;
  while (std::getline(in, line)) {
    if (line.find("error") != std::string::npos) return line;
    if (first.empty()) first = line;
  }
  return first.empty() ? "no output" : first;
}

// Compiles `source` into `target` through a temporary; the reason it failed, or "".
std::string compile(const fs::path& compiler, const NativeSource& source, const fs::path& folder,
                    const fs::path& target) {
  remove_stale_temporaries(folder, source.hash);
  const std::string stem = source.hash + temporary_suffix();
  const fs::path cpp = folder / (stem + ".cpp");
  const fs::path temporary = folder / (stem + ".so");
  struct Cleanup {
    fs::path a, b;
    ~Cleanup() {
      std::error_code ec;
      fs::remove(a, ec);
      fs::remove(b, ec);
    }
  } cleanup{cpp, temporary};
  {
    std::ofstream out(cpp, std::ios::binary);
    out << source.text;
    if (!out.flush()) return write_failure(cpp, errno);
  }
  ProgramRun run;
  run.argv = {compiler.string(),  "-O2",        "-fPIC", "-shared", "-ffp-contract=off", "-o",
              temporary.string(), cpp.string(), "-lm"};
  run.capture_output = true;
  run.timeout = kCompileTimeout;
  ProgramResult result;
  try {
    result = run_program(run);
  } catch (const Error& e) {
    return e.what();
  }
  if (result.timed_out) return compiler.string() + " did not finish in 10 min";
  if (!result.succeeded()) return compiler.string() + " failed: " + first_error(result.output);
  std::error_code ec;
  fs::permissions(temporary,
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                      fs::perms::others_exec,
                  ec);
  if (!ec) fs::rename(temporary, target, ec);
  if (ec) return "cannot write " + quoted(target) + ": " + ec.message();
  return "";
}

// The loaded library's table, or the reason it is not what `source` asked for.
struct Loaded {
  void* handle = nullptr;
  std::map<std::uint64_t, NativeFunction> functions;
  std::string problem;
};

Loaded load(const fs::path& file, const NativeSource& source) {
  Loaded out;
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = ::dlerror();
    out.problem = std::string("it does not load (") + (why != nullptr ? why : "dlopen failed") + ")";
    return out;
  }
  const auto* version = static_cast<const unsigned long long*>(::dlsym(handle, "linkage_native_version"));
  const auto* hash = static_cast<const char*>(::dlsym(handle, "linkage_native_source_hash"));
  const auto* count = static_cast<const unsigned long long*>(::dlsym(handle, "linkage_native_count"));
  const auto* table = static_cast<const Entry*>(::dlsym(handle, "linkage_native_table"));
  if (version == nullptr || hash == nullptr || count == nullptr || table == nullptr)
    out.problem = "it lacks linkage's symbols";
  else if (*version != kNativeGeneratorVersion)
    out.problem =
        "it is from generator version " + std::to_string(*version) + ", not " + std::to_string(kNativeGeneratorVersion);
  else if (std::string_view(hash) != source.hash)
    out.problem = "its source hash " + std::string(hash) + " is not " + source.hash;
  else if (*count != source.functions)
    out.problem = "it has " + std::to_string(*count) + " functions, not " + std::to_string(source.functions);
  if (!out.problem.empty()) {
    ::dlclose(handle);
    return out;
  }
  for (std::size_t k = 0; k < *count; ++k) out.functions.emplace(table[k].fingerprint, table[k].function);
  out.handle = handle;
  return out;
}

}  // namespace

NativeSource native_source(const std::vector<const Program*>& programs) {
  std::map<std::uint64_t, const Program*> distinct;
  for (const Program* p : programs) distinct.emplace(p->fingerprint(), p);
  NativeSource out;
  out.functions = distinct.size();
  std::string& s = out.text;
  s = "// Generated by linkage (src/evaluate/native_library.cpp) from compiled GiNaC expressions.\n";
  for (const auto& [fingerprint, program] : distinct) s += emit_cpp(*program, "linkage_native_" + hex(fingerprint));
  s += "struct LinkageNativeEntry {\n  unsigned long long fingerprint;\n  void (*function)(const double*, "
       "const double*, double*);\n};\n";
  s += "extern \"C\" const LinkageNativeEntry linkage_native_table[] = {\n";
  for (const auto& [fingerprint, program] : distinct)
    s += "    {0x" + hex(fingerprint) + "ULL, linkage_native_" + hex(fingerprint) + "},\n";
  if (distinct.empty()) s += "    {0ULL, nullptr},\n";  // an array has at least one element
  s += "};\n";
  s += "extern \"C\" const unsigned long long linkage_native_count = " + std::to_string(distinct.size()) + "ULL;\n";
  s += "extern \"C\" const unsigned long long linkage_native_version = " + std::to_string(kNativeGeneratorVersion) +
       "ULL;\n";
  out.hash = content_hash(s);
  s += "extern \"C\" const char linkage_native_source_hash[] = \"" + out.hash + "\";\n";
  return out;
}

bool native_compiler_found() { return find_compiler().has_value(); }

fs::path native_cache_folder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg != nullptr && fs::path(xdg).is_absolute()) return fs::path(xdg) / "linkage" / "native";
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home != '\0') return fs::path(home) / ".cache" / "linkage" / "native";
  return {};
}

NativeAttachment attach_native(const std::vector<Program*>& programs, bool may_compile) {
  NativeAttachment out;
  const std::vector<const Program*> views(programs.begin(), programs.end());
  const NativeSource source = native_source(views);
  out.functions = source.functions;
  const fs::path folder = native_cache_folder();
  if (folder.empty()) {
    out.reason = "no cache folder for native code (neither XDG_CACHE_HOME nor HOME is set)";
    return out;
  }
  for (const fs::path& f : {folder.parent_path(), folder}) {
    if (std::string why = prepare_folder(f); !why.empty()) {
      out.reason = "cache folder refused: " + why;
      return out;
    }
  }
  out.library = folder / (source.hash + ".so");
  std::error_code ec;
  const auto build = [&]() -> bool {
    if (!may_compile) {
      out.reason = "not compiled yet";
      return false;
    }
    const std::optional<fs::path> compiler = find_compiler();
    if (!compiler) {
      out.reason = "no C++ compiler (" + std::string(kCompiler) + ") on PATH";
      return false;
    }
    out.compiled = true;
    if (std::string why = compile(*compiler, source, folder, out.library); !why.empty()) {
      out.reason = why;
      return false;
    }
    return true;
  };
  if (!fs::exists(out.library, ec) && !build()) return out;
  Loaded loaded;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (std::string why = unsafe(out.library, false); !why.empty()) {
      out.reason = "cached native code refused: " + why;
      return out;
    }
    loaded = load(out.library, source);
    if (loaded.problem.empty()) break;
    if (out.compiled) {  // freshly built and still wrong: never retried
      out.reason = quoted(out.library) + " was just built but " + loaded.problem;
      return out;
    }
    out.rebuilt = quoted(out.library) + " rebuilt: " + loaded.problem;
    fs::remove(out.library, ec);
    if (!build()) return out;
  }
  for (const Program* p : programs) {
    if (!loaded.functions.contains(p->fingerprint())) {
      out.reason = quoted(out.library) + " has no function for a program";  // unreachable: the hash matched
      return out;
    }
  }
  for (Program* p : programs) p->attach(loaded.functions.at(p->fingerprint()));
  out.attached = true;
  return out;
}

}  // namespace linkage::eval
