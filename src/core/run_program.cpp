#include "core/run_program.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

#include "core/error.hpp"
#include "core/interrupt.hpp"

extern char** environ;  // NOLINT: POSIX declares it nowhere else

namespace linkage {
namespace {

constexpr std::size_t kMaxOutput = std::size_t{4} << 20;
constexpr int kPollMilliseconds = 20;     // how often the wait looks at signals and the clock
constexpr int kGraceMilliseconds = 1000;  // from SIGTERM to SIGKILL

// A posix_spawn object, initialised and destroyed with its scope.
template <typename T, int (*init)(T*), int (*destroy)(T*)>
class SpawnObject {
 public:
  SpawnObject() { init(&object_); }
  SpawnObject(const SpawnObject&) = delete;
  SpawnObject& operator=(const SpawnObject&) = delete;
  ~SpawnObject() { destroy(&object_); }
  T* get() { return &object_; }

 private:
  T object_{};
};
using FileActions =
    SpawnObject<posix_spawn_file_actions_t, posix_spawn_file_actions_init, posix_spawn_file_actions_destroy>;
using SpawnAttributes = SpawnObject<posix_spawnattr_t, posix_spawnattr_init, posix_spawnattr_destroy>;

class Descriptor {
 public:
  Descriptor() = default;
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { reset(); }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_ = -1;
};

[[noreturn]] void fail(const std::string& program, const std::string& what, int error) {
  throw Error::failure("cannot run " + program + ": " + what + ": " + std::strerror(error));
}

/// Reaps the child if it has ended; true then.
bool reaped(pid_t pid, int& status) {
  const pid_t r = ::waitpid(pid, &status, WNOHANG);
  return r == pid || (r < 0 && errno == ECHILD);
}

/// Ends the child: SIGTERM, SIGKILL after a grace period, and reaps it (no zombie left).
void end_child(pid_t pid) {
  int status = 0;
  ::kill(pid, SIGTERM);
  for (int waited = 0; waited < kGraceMilliseconds; waited += kPollMilliseconds) {
    if (reaped(pid, status)) return;
    ::poll(nullptr, 0, kPollMilliseconds);
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

/// Reads what is there (the descriptor does not block); false at end of file or an error.
bool read_available(int fd, std::string& output) {
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n > 0) {
      const auto count = static_cast<std::size_t>(n);
      if (output.size() < kMaxOutput) output.append(buffer.data(), std::min(count, kMaxOutput - output.size()));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return n < 0 && errno == EAGAIN;
  }
}

}  // namespace

ProgramResult run_program(const ProgramRun& run) {
  if (run.argv.empty() || run.argv.front().empty()) throw Error::failure("run_program: no program given");
  const std::string& program = run.argv.front();
  std::vector<char*> argv;
  for (const std::string& argument : run.argv) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  FileActions actions;
  if (run.null_input) posix_spawn_file_actions_addopen(actions.get(), STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  Descriptor output_read, output_write;
  if (run.capture_output) {
    std::array<int, 2> ends{};
    if (::pipe2(ends.data(), O_CLOEXEC) != 0) fail(program, "a pipe for its output", errno);
    output_read.reset(ends[0]);
    output_write.reset(ends[1]);
    ::fcntl(output_read.get(), F_SETFL, O_NONBLOCK);
    posix_spawn_file_actions_adddup2(actions.get(), output_write.get(), STDOUT_FILENO);
  } else {
    posix_spawn_file_actions_addopen(actions.get(), STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  }
  posix_spawn_file_actions_adddup2(actions.get(), STDOUT_FILENO, STDERR_FILENO);
  if (!run.directory.empty()) posix_spawn_file_actions_addchdir_np(actions.get(), run.directory.c_str());

  // The child starts with no signal blocked and the default action for the signals this
  // process catches or may ignore (a caught handler does not survive exec; SIG_IGN would).
  SpawnAttributes attributes;
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, signal);
  posix_spawnattr_setsigmask(attributes.get(), &none);
  posix_spawnattr_setsigdefault(attributes.get(), &defaults);
  posix_spawnattr_setflags(attributes.get(), POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, program.c_str(), actions.get(), attributes.get(), argv.data(), environ);
  if (spawned != 0)
    fail(program, run.directory.empty() ? "starting it" : "starting it in " + run.directory.string(), spawned);
  output_write.reset();  // the child's copy is the only writer: end of file when it ends

  ProgramResult result;
  const auto start = std::chrono::steady_clock::now();
  bool reading = output_read.get() >= 0;
  int status = 0;
  for (;;) {
    if (interrupt_requested()) {
      end_child(pid);
      throw interrupted_error();
    }
    if (run.timeout.count() > 0 && std::chrono::steady_clock::now() - start >= run.timeout) {
      end_child(pid);
      result.timed_out = true;
      return result;
    }
    if (reading) {
      pollfd ready{output_read.get(), POLLIN, 0};
      if (::poll(&ready, 1, kPollMilliseconds) > 0) reading = read_available(output_read.get(), result.output);
    } else {
      ::poll(nullptr, 0, kPollMilliseconds);
    }
    if (reaped(pid, status)) break;
  }
  if (reading) (void)read_available(output_read.get(), result.output);  // what it wrote last
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

}  // namespace linkage
