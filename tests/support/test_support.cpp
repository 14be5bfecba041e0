#include "support/test_support.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"

extern char** environ;

namespace linkage::test {
namespace fs = std::filesystem;

const std::string& linkage_binary() {
  static const std::string binary = [] {
    const char* other = std::getenv("LINKAGE_BINARY_UNDER_TEST");
    return std::string(other != nullptr && *other != '\0' ? other : LINKAGE_BINARY);
  }();
  return binary;
}

std::string source_path(std::string_view relative) {
  std::string path = LINKAGE_SOURCE_DIR;
  path += '/';
  path += relative;
  return path;
}

std::string test_mechanism(std::string_view name) { return source_path("tests/data/mechanisms/" + std::string(name)); }

namespace {

/// A pseudo-terminal pair: the child writes to `slave`, we drain `master`. The slave
/// is open here until the child has it, so the master never reads as hung up early.
struct Terminal {
  int master = -1;
  int slave = -1;
};

Terminal open_terminal() {
  Terminal t;
  t.master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (t.master < 0 || ::grantpt(t.master) != 0 || ::unlockpt(t.master) != 0)
    throw std::runtime_error("cannot open a pseudo-terminal");
  t.slave = ::open(::ptsname(t.master), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (t.slave < 0) throw std::runtime_error("cannot open the pseudo-terminal's slave");
  return t;
}

/// The child starts with default signal dispositions and nothing blocked, whatever this
/// process does (it ignores SIGPIPE, so that a child closing its stdin early is no crash
/// here).
posix_spawnattr_t child_attributes() {
  static const bool ignored = [] { return std::signal(SIGPIPE, SIG_IGN) != SIG_ERR; }();
  (void)ignored;
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&defaults, s);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  return attributes;
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

/// This process's environment, but LeakSanitizer does not list the suppressions it used
/// when the program exits (a sanitizer build's stderr would not be one line otherwise).
std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  bool lsan = false;
  for (char** e = environ; *e != nullptr; ++e) {
    env.emplace_back(*e);
    if (env.back().rfind("LSAN_OPTIONS=", 0) == 0) {
      env.back() += ":print_suppressions=0";
      lsan = true;
    }
  }
  if (!lsan) env.emplace_back("LSAN_OPTIONS=print_suppressions=0");
  return env;
}

}  // namespace

RunResult run_linkage(const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  std::array<int, 2> in{-1, -1}, out{-1, -1}, err{-1, -1};
  if (::pipe2(in.data(), O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  Terminal terminal, error_terminal;
  if (options.stderr_terminal) {
    error_terminal = open_terminal();
    err = {error_terminal.master, error_terminal.slave};
  } else if (::pipe2(err.data(), O_CLOEXEC) != 0) {
    throw std::runtime_error("pipe failed");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], 0);
  switch (options.stdout_to) {
    case RunOptions::Stdout::pipe:
      if (::pipe2(out.data(), O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
      posix_spawn_file_actions_adddup2(&actions, out[1], 1);
      break;
    case RunOptions::Stdout::dev_full:  // opened for writing only: every write fails with ENOSPC
      posix_spawn_file_actions_addopen(&actions, 1, "/dev/full", O_WRONLY, 0);
      break;
    case RunOptions::Stdout::terminal:
      terminal = open_terminal();
      out[0] = terminal.master;
      posix_spawn_file_actions_adddup2(&actions, terminal.slave, 1);
      break;
  }
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);
  if (!options.cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, options.cwd.c_str());

  std::vector<std::string> argv_storage{linkage_binary()};
  argv_storage.insert(argv_storage.end(), options.args.begin(), options.args.end());
  std::vector<char*> argv;
  for (auto& a : argv_storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawnattr_t attributes = child_attributes();
  std::vector<std::string> env_storage = child_environment();
  std::vector<char*> env;
  for (auto& e : env_storage) env.push_back(e.data());
  env.push_back(nullptr);
  const int rc = ::posix_spawn(&pid, linkage_binary().c_str(), &actions, &attributes, argv.data(), env.data());
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  close_fd(terminal.slave);
  close_fd(in[0]);
  close_fd(out[1]);
  close_fd(err[1]);
  if (rc != 0) {
    close_fd(in[1]);
    close_fd(out[0]);
    close_fd(err[0]);
    throw std::runtime_error("cannot start " + linkage_binary());
  }

  RunResult result;
  std::size_t written = 0;
  if (options.input.empty() && !options.keep_stdin_open) close_fd(in[1]);
  const auto start = Clock::now();
  const auto deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_seconds));
  Clock::time_point signalled;
  std::array<char, 65536> buffer{};
  // 0: stdout, 1: stderr, 2: stdin while there is input to write.
  std::array<pollfd, 3> fds{pollfd{out[0], POLLIN, 0}, pollfd{err[0], POLLIN, 0}, pollfd{-1, POLLOUT, 0}};
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    fds[2].fd = in[1] >= 0 && written < options.input.size() ? in[1] : -1;
    const bool waiting_to_signal = options.signal != 0 && !result.signal_sent;
    const auto now = Clock::now();
    if (now >= deadline && !result.timed_out) {
      ::kill(pid, SIGKILL);
      result.timed_out = true;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count();
    const int wait_ms =
        result.timed_out ? -1 : static_cast<int>(std::clamp<long long>(left, 0, waiting_to_signal ? 5 : 200));
    if (::poll(fds.data(), fds.size(), wait_ms) < 0 && errno != EINTR) break;
    for (std::size_t i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
      if (n <= 0) {  // end of file (or EIO from a terminal whose other end closed)
        ::close(fds[i].fd);
        fds[i].fd = -1;
      } else {
        (i == 0 ? result.out : result.err).append(buffer.data(), static_cast<std::size_t>(n));
      }
    }
    if (fds[2].fd >= 0 && (fds[2].revents & (POLLOUT | POLLERR | POLLHUP))) {
      const ssize_t n = ::write(in[1], options.input.data() + written, options.input.size() - written);
      if (n > 0) written += static_cast<std::size_t>(n);
      if (n <= 0 || (written == options.input.size() && !options.keep_stdin_open)) close_fd(in[1]);
    }
    if (waiting_to_signal && options.ready && options.ready(result.out, result.err)) {
      ::kill(pid, options.signal);
      result.signal_sent = true;
      signalled = Clock::now();
    }
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (result.signal_sent) result.seconds_after_signal = std::chrono::duration<double>(Clock::now() - signalled).count();
  close_fd(in[1]);
  if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else {
    result.killed_by = WTERMSIG(status);
    result.exit_code = 128 + result.killed_by;
  }
  return result;
}

RunResult run_linkage(const std::vector<std::string>& args, const std::string& input) {
  RunOptions options;
  options.args = args;
  options.input = input;
  options.timeout_seconds = 600;  // the ctest timeout of a whole test
  return run_linkage(options);
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = fs::temp_directory_path() / ("linkage-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> TempDir::entries() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

namespace {
nlohmann::json load_json(const char* name) {
  return nlohmann::json::parse(read_text(fs::path(LINKAGE_SPEC_DIR) / name));
}
}  // namespace

const nlohmann::json& spec_example() {
  static const nlohmann::json json = load_json("example.json");
  return json;
}

const nlohmann::json& spec_reference() {
  static const nlohmann::json json = load_json("reference-example.json");
  return json;
}

double number(const nlohmann::json& value) {
  return value.is_string() ? std::stod(value.get<std::string>()) : value.get<double>();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t Table::index(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::runtime_error("no column " + name);
}

namespace {
std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(line);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}
}  // namespace

Table parse_csv(const std::string& text) {
  Table t;
  std::stringstream in(text);
  std::string line;
  std::getline(in, line);
  t.columns = split(line, ',');
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& cell : split(line, ',')) row.push_back(std::stod(cell));
    EXPECT_EQ(row.size(), t.columns.size()) << line;
    t.rows.push_back(row);
  }
  return t;
}

std::string repeat(std::string_view s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

std::string test_name(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

std::string input_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input) << e.what();
    return e.what();
  }
  return "";
}

}  // namespace linkage::test
