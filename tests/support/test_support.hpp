#pragma once
// Shared helpers for the test suites: running the linkage binary, temporary folders,
// and the spec's example files.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace linkage::test {

struct RunResult {
  int exit_code = -1;  // the exit status, or 128 + the signal that ended the process
  std::string out;
  std::string err;
  int killed_by = 0;                // the signal that ended the process (a crash, or our kill), else 0
  bool timed_out = false;           // still running at the timeout: killed with SIGKILL
  bool signal_sent = false;         // RunOptions::signal was sent
  double seconds_after_signal = 0;  // from sending it to the process's end
};

/// The program the CLI tests run: $LINKAGE_BINARY_UNDER_TEST when set (to hold another
/// build to the same tests), else the one this build made.
const std::string& linkage_binary();

/// A file of the source tree: source_path("mechanisms/four-bar.toml").
std::string source_path(std::string_view relative);
/// One of the tests' own mechanisms: tests/data/mechanisms/NAME.
std::string test_mechanism(std::string_view name);

/// What a run of the program sees.
struct RunOptions {
  std::vector<std::string> args;
  std::string input;             // written to stdin, which is then closed...
  bool keep_stdin_open = false;  // ...unless this is set: a pipe open until the process ends
  enum class Stdout { pipe, dev_full, terminal } stdout_to = Stdout::pipe;  // terminal: a pseudo-terminal
  bool stderr_terminal = false;                                             // stderr on a pseudo-terminal
  std::filesystem::path cwd;                                                // empty: this process's
  double timeout_seconds = 60;                                              // then SIGKILL and RunResult::timed_out
  /// When set: sent once `ready(stdout so far, stderr so far)` returns true (it is
  /// polled every few milliseconds).
  int signal = 0;
  std::function<bool(const std::string& out, const std::string& err)> ready;
};

/// Runs linkage_binary() with `options.args` (no shell) and captures stdout, stderr and
/// how it ended.
RunResult run_linkage(const RunOptions& options);

/// Runs linkage_binary() with `args` (no shell), stdin from `input`, and captures
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

/// The text's lines, without their line ends.
std::vector<std::string> lines_of(const std::string& text);
/// A parsed CSV table (simulate's output): the header and the rows of numbers.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// The column named `name` (throws when there is none).
  [[nodiscard]] std::size_t index(const std::string& name) const;
};
/// `text` as a Table: every row as many numbers as the header has names (checked).
Table parse_csv(const std::string& text);
/// `s` written `n` times (hostile input: deep nesting, long names).
std::string repeat(std::string_view s, int n);
/// A mechanism's name as a GoogleTest parameter name (letters, digits and '_' only).
std::string test_name(std::string name);
/// The message of the Error `action` throws, checked to be a bad-input error (exit 2); ""
/// when it throws none.
std::string input_error_of(const std::function<void()>& action);

}  // namespace linkage::test
