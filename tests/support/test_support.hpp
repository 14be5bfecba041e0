#pragma once
// Shared helpers for the test suites: running the linkage binary, temporary folders,
// and the spec's example files.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace linkage::test {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs the built `linkage` with `args` (no shell), stdin from `input`, and captures
/// stdout, stderr and the exit code.
RunResult run_linkage(const std::vector<std::string>& args, const std::string& input = "");

/// A fresh folder under the system temp dir, removed with everything in it on scope exit.
class TempDir {
 public:
  TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// Names of the entries in the folder, sorted.
  [[nodiscard]] std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

/// Parsed assets/spec/example.json and reference-example.json.
const nlohmann::json& spec_example();
const nlohmann::json& spec_reference();
/// A decimal string or number from those files as a double.
double number(const nlohmann::json& value);

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace linkage::test
