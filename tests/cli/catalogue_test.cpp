// The catalogue of bad input, faults and signals (tests/data/catalogue/*.toml, format in
// its README.md): one test per case, each a run of the program in a fresh folder held to
// the project's rule: the expected exit code, one stderr line matching the case's pattern,
// no crash, no hang, no inf or nan printed, and nothing left behind or lost.
//
// LINKAGE_BINARY_UNDER_TEST=/path/to/linkage holds another build to the same cases; the
// run then ends with totals by kind of failure (also printed whenever more than one case
// ran), e.g. `test_cli --gtest_filter='Cases/Catalogue.*'`.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/stat.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCatalogueDir = fs::path(LINKAGE_SOURCE_DIR) / "tests" / "data" / "catalogue";
constexpr int kMinimumCases = 150;
// Longer than any list of valid names the program gives; an echoed 100 KB value is not.
constexpr std::size_t kLongestLine = 1000;

struct SetupEntry {
  enum class Kind { file, folder, symlink, fifo } kind = Kind::file;
  std::string name;
  std::string text;    // a file's content
  std::string target;  // a symlink's target
};

struct Case {
  std::string name;
  std::string where;  // catalogue file:line, for messages
  std::vector<std::string> args;
  std::string input;
  bool stdin_open = false;
  RunOptions::Stdout stdout_to = RunOptions::Stdout::pipe;
  std::vector<SetupEntry> setup;
  int exit_code = 0;
  std::string stderr_pattern;
  std::optional<std::string> stdout_pattern;
  std::optional<std::vector<std::string>> after;
  std::set<std::string> changed;
  std::map<std::string, std::string> files;  // entry -> pattern its content must match
  std::string fifo_reader;                   // a FIFO a helper thread reads while the case runs
  std::optional<std::string> fifo_pattern;
  int signal = 0;
  std::string when_entry, when_stdout, when_stderr;  // send the signal once one of these matches
  double within = 3;                                 // seconds from the signal to the process's end
  double timeout = 10;
};

// ---------------------------------------------------------------------------------------
// Reading the catalogue

std::string substitute(std::string text, const fs::path& dir) {
  // {repeat:N:TEXT} -> TEXT N times (TEXT has no '}')
  for (std::size_t at = text.find("{repeat:"); at != std::string::npos; at = text.find("{repeat:", at)) {
    const std::size_t colon = text.find(':', at + 8);
    const std::size_t close = text.find('}', colon == std::string::npos ? at : colon);
    if (colon == std::string::npos || close == std::string::npos) break;
    const int count = std::stoi(text.substr(at + 8, colon - at - 8));
    const std::string unit = text.substr(colon + 1, close - colon - 1);
    std::string repeated;
    repeated.reserve(unit.size() * static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) repeated += unit;
    text.replace(at, close + 1 - at, repeated);
    at += repeated.size();
  }
  // {hex:HH} -> the byte 0xHH (invalid UTF-8, control characters)
  for (std::size_t at = text.find("{hex:"); at != std::string::npos && at + 8 <= text.size();
       at = text.find("{hex:", at + 1))
    text.replace(at, 8, 1, static_cast<char>(std::stoi(text.substr(at + 5, 2), nullptr, 16)));
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{dir}", dir.string()}, {"{source}", LINKAGE_SOURCE_DIR}})
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  return text;
}

int signal_number(const std::string& name) {
  if (name == "SIGINT") return SIGINT;
  if (name == "SIGTERM") return SIGTERM;
  if (name == "SIGHUP") return SIGHUP;
  throw std::runtime_error("signal '" + name + "' is not SIGINT, SIGTERM or SIGHUP");
}

std::vector<std::string> strings(const toml::table& t, const char* key) {
  std::vector<std::string> out;
  const toml::node* n = t.get(key);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) throw std::runtime_error(std::string("'") + key + "' must be a list of strings");
  for (const toml::node& e : *a) {
    if (!e.is_string()) throw std::runtime_error(std::string("'") + key + "' must be a list of strings");
    out.push_back(e.as_string()->get());
  }
  return out;
}

SetupEntry setup_entry(const toml::table& t) {
  SetupEntry e;
  if (auto f = t["file"].value<std::string>()) {
    e.name = *f;
    e.text = t["text"].value_or(std::string());
  } else if (auto d = t["folder"].value<std::string>()) {
    e.kind = SetupEntry::Kind::folder;
    e.name = *d;
  } else if (auto l = t["symlink"].value<std::string>()) {
    e.kind = SetupEntry::Kind::symlink;
    e.name = *l;
    e.target = t["to"].value_or(std::string());
  } else if (auto p = t["fifo"].value<std::string>()) {
    e.kind = SetupEntry::Kind::fifo;
    e.name = *p;
  } else {
    throw std::runtime_error("a setup entry needs file, folder, symlink or fifo");
  }
  return e;
}

const std::set<std::string> kCaseKeys{"name",        "args",   "stdin",   "stdin_open",  "stdout_to",
                                      "setup",       "exit",   "stderr",  "stdout",      "after",
                                      "changed",     "files",  "signal",  "when_entry",  "when_stdout",
                                      "when_stderr", "within", "timeout", "fifo_reader", "fifo_content"};

Case read_case(const toml::table& t, const std::string& where) {
  for (const auto& [key, value] : t)
    if (!kCaseKeys.contains(std::string(key.str())))
      throw std::runtime_error("unknown key '" + std::string(key.str()) + "'");
  Case c;
  c.where = where;
  c.name = t["name"].value_or(std::string());
  if (c.name.empty() || !std::all_of(c.name.begin(), c.name.end(),
                                     [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }))
    throw std::runtime_error("'name' must be letters, digits and '_'");
  if (!t.contains("args")) throw std::runtime_error("'args' is missing");
  c.args = strings(t, "args");
  c.input = t["stdin"].value_or(std::string());
  c.stdin_open = t["stdin_open"].value_or(false);
  const std::string to = t["stdout_to"].value_or(std::string("pipe"));
  if (to == "/dev/full")
    c.stdout_to = RunOptions::Stdout::dev_full;
  else if (to == "terminal")
    c.stdout_to = RunOptions::Stdout::terminal;
  else if (to != "pipe")
    throw std::runtime_error("'stdout_to' must be pipe, /dev/full or terminal");
  if (const toml::array* setup = t["setup"].as_array())
    for (const toml::node& e : *setup) {
      if (!e.is_table()) throw std::runtime_error("'setup' must be a list of tables");
      c.setup.push_back(setup_entry(*e.as_table()));
    }
  const auto code = t["exit"].value<int64_t>();
  if (!code) throw std::runtime_error("'exit' is missing");
  c.exit_code = static_cast<int>(*code);
  const auto pattern = t["stderr"].value<std::string>();
  if (!pattern) throw std::runtime_error("'stderr' is missing");
  c.stderr_pattern = *pattern;
  if (auto s = t["stdout"].value<std::string>()) c.stdout_pattern = *s;
  if (t.contains("after")) c.after = strings(t, "after");
  for (const std::string& name : strings(t, "changed")) c.changed.insert(name);
  if (const toml::table* files = t["files"].as_table())
    for (const auto& [name, value] : *files) c.files[std::string(name.str())] = value.value_or(std::string());
  c.fifo_reader = t["fifo_reader"].value_or(std::string());
  if (auto s = t["fifo_content"].value<std::string>()) c.fifo_pattern = *s;
  if (auto s = t["signal"].value<std::string>()) {
    c.signal = signal_number(*s);
    c.when_entry = t["when_entry"].value_or(std::string());
    c.when_stdout = t["when_stdout"].value_or(std::string());
    c.when_stderr = t["when_stderr"].value_or(std::string());
    if (c.when_entry.empty() && c.when_stdout.empty() && c.when_stderr.empty())
      throw std::runtime_error("a signal case needs when_entry, when_stdout or when_stderr");
  }
  c.within = t["within"].value_or(c.within);
  c.timeout = t["timeout"].value_or(c.timeout);
  return c;
}

struct CaseList {
  std::vector<Case> cases;
  std::vector<std::string> problems;  // catalogue files or cases that could not be read
};

const CaseList& catalogue() {
  static const CaseList loaded = [] {
    CaseList c;
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(kCatalogueDir, ec))
      if (entry.path().extension() == ".toml") files.push_back(entry.path());
    if (ec) c.problems.push_back("cannot list " + kCatalogueDir.string() + ": " + ec.message());
    std::sort(files.begin(), files.end());
    std::set<std::string> names;
    for (const fs::path& file : files) {
      toml::table root;
      try {
        root = toml::parse_file(file.string());
      } catch (const toml::parse_error& e) {
        c.problems.push_back(file.filename().string() + ": " + std::string(e.description()));
        continue;
      }
      const toml::array* list = root["case"].as_array();
      if (list == nullptr) {
        c.problems.push_back(file.filename().string() + ": no [[case]] tables");
        continue;
      }
      for (const toml::node& node : *list) {
        const std::string where = file.filename().string() + ":" + std::to_string(node.source().begin.line);
        try {
          if (!node.is_table()) throw std::runtime_error("not a table");
          Case one = read_case(*node.as_table(), where);
          if (!names.insert(one.name).second) throw std::runtime_error("the name '" + one.name + "' is taken");
          c.cases.push_back(std::move(one));
        } catch (const std::exception& e) {
          c.problems.push_back(where + ": " + e.what());
        }
      }
    }
    return c;
  }();
  return loaded;
}

// ---------------------------------------------------------------------------------------
// The folder before and after

/// "name" a file, "name/" a folder (its entries follow as "name/entry"), "name -> target"
/// a symlink, "name|" a FIFO, "name?" anything else; sorted.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().lexically_relative(dir).string();  // not through symlinks
    const fs::file_status status = it->symlink_status(ec);
    if (fs::is_symlink(status))
      out.push_back(name + " -> " + fs::read_symlink(it->path(), ec).string());
    else if (fs::is_directory(status))
      out.push_back(name + "/");
    else if (fs::is_fifo(status))
      out.push_back(name + "|");
    else if (fs::is_regular_file(status))
      out.push_back(name);
    else
      out.push_back(name + "?");
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::map<std::string, std::string> make_setup(const Case& c, const fs::path& dir) {
  std::map<std::string, std::string> contents;  // each file made, with its bytes
  for (const SetupEntry& e : c.setup) {
    const fs::path path = dir / e.name;
    fs::create_directories(path.parent_path());
    switch (e.kind) {
      case SetupEntry::Kind::file:
        contents[e.name] = substitute(e.text, dir);
        write_text(path, contents[e.name]);
        break;
      case SetupEntry::Kind::folder:
        fs::create_directories(path);
        break;
      case SetupEntry::Kind::symlink:
        fs::create_symlink(substitute(e.target, dir), path);
        break;
      case SetupEntry::Kind::fifo:
        if (::mkfifo(path.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
        break;
    }
  }
  return contents;
}

/// Reads a FIFO on its own thread while the case runs, until its writer closes it or the
/// case is over (a program that never opens it, or replaces it, must not hang the test).
class FifoReader {
 public:
  explicit FifoReader(const fs::path& path) : fd_(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)) {
    if (fd_ < 0) throw std::runtime_error("cannot open the FIFO " + path.string());
    thread_ = std::thread([this] {
      char buffer[65536];
      bool written = false;  // a writer came: its end of file ends the reading
      while (!done_) {
        pollfd p{fd_, POLLIN, 0};
        if (::poll(&p, 1, 20) <= 0) continue;
        const ssize_t n = ::read(fd_, buffer, sizeof buffer);
        if (n > 0) {
          written = true;
          const std::lock_guard lock(mutex_);
          text_.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 && (written || (p.revents & POLLHUP))) {
          break;
        } else if (n == 0) {
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
      }
      const std::lock_guard lock(mutex_);  // what is left once the case is over
      for (ssize_t n; (n = ::read(fd_, buffer, sizeof buffer)) > 0;) text_.append(buffer, static_cast<std::size_t>(n));
    });
  }
  FifoReader(const FifoReader&) = delete;
  FifoReader& operator=(const FifoReader&) = delete;
  /// Everything read (called once the program has ended).
  std::string finish() {
    done_ = true;
    if (thread_.joinable()) thread_.join();
    const std::lock_guard lock(mutex_);
    return text_;
  }
  ~FifoReader() {
    (void)finish();
    ::close(fd_);
  }

 private:
  int fd_;
  std::atomic<bool> done_{false};
  std::thread thread_;
  std::mutex mutex_;
  std::string text_;
};

// ---------------------------------------------------------------------------------------
// Totals by kind of failure, for holding one build against another

enum Fault { crash, hang, non_finite, leftover, multi_line, long_line, other, kFaults };
constexpr const char* kFaultNames[kFaults] = {
    "crashes",         "hangs", "non-finite values printed", "leftovers", "multi-line errors", "over-long error lines",
    "other mismatches"};

struct Tally {
  int cases = 0, passed = 0;
  int faults[kFaults] = {};
  std::string binary = linkage_binary();  // a copy: it outlives the function's own static
  ~Tally() {
    if (cases < 2) return;  // one case per process under ctest: nothing to add up
    std::printf("\ncatalogue against %s:\n", binary.c_str());
    for (int f = 0; f < kFaults; ++f) std::printf("  %-26s %d\n", kFaultNames[f], faults[f]);
    std::printf("catalogue: %d passed, %d failed\n", passed, cases - passed);
  }
};
Tally tally;

bool has_non_finite(const std::string& text) {
  static const std::regex word(R"((^|[^A-Za-z0-9_.])[-+]?(nan|inf|infinity)([^A-Za-z0-9_]|$))",
                               std::regex::icase | std::regex::optimize);
  return std::regex_search(text, word);
}

std::string shown(const std::string& text, std::size_t limit = 600) {
  std::string out;
  for (char ch : text.substr(0, limit)) out += ch == '\n' ? std::string("\\n\n    ") : std::string(1, ch);
  if (text.size() > limit) out += "...(" + std::to_string(text.size() - limit) + " more bytes)";
  return out;
}

// ---------------------------------------------------------------------------------------

/// A case as GoogleTest names it in messages.
void PrintTo(const Case& c, std::ostream* out) { *out << c.name << " (" << c.where << ")"; }

class Catalogue : public ::testing::TestWithParam<Case> {};

TEST_P(Catalogue, Case) {
  const Case& c = GetParam();
  SCOPED_TRACE(c.where);
  TempDir dir;
  const std::map<std::string, std::string> before = make_setup(c, dir.path());
  const std::vector<std::string> listed_before = listing(dir.path());

  RunOptions options;
  for (const std::string& a : c.args) options.args.push_back(substitute(a, dir.path()));
  options.input = substitute(c.input, dir.path());
  options.keep_stdin_open = c.stdin_open;
  options.stdout_to = c.stdout_to;
  options.cwd = dir.path();
  options.timeout_seconds = c.timeout;
  std::optional<std::regex> when_out, when_err;
  if (!c.when_stdout.empty()) when_out.emplace(c.when_stdout);
  if (!c.when_stderr.empty()) when_err.emplace(c.when_stderr);
  const std::regex when_entry(c.when_entry.empty() ? "$^" : c.when_entry);
  if (c.signal != 0) {
    options.signal = c.signal;
    options.ready = [&](const std::string& out, const std::string& err) {
      if (when_out && std::regex_search(out, *when_out)) return true;
      if (when_err && std::regex_search(err, *when_err)) return true;
      if (c.when_entry.empty()) return false;
      for (const std::string& entry : listing(dir.path()))
        if (std::regex_search(entry, when_entry)) return true;
      return false;
    };
  }
  std::optional<FifoReader> reader;
  if (!c.fifo_reader.empty()) reader.emplace(dir / c.fifo_reader);
  const RunResult r = run_linkage(options);
  const std::string fifo_text = reader ? reader->finish() : std::string();

  bool faults[kFaults] = {};
  const auto fault = [&](Fault kind, const std::string& what) {
    faults[kind] = true;
    ADD_FAILURE() << kFaultNames[kind] << ": " << what;
  };
  const std::string context = "\n  stderr: " + shown(r.err) + "\n  stdout: " + shown(r.out);

  // How it ended.
  if (r.timed_out)
    fault(hang, "still running after " + std::to_string(c.timeout) + " s" + context);
  else if (r.killed_by != 0 && r.killed_by == c.signal)
    fault(other, "ended by the signal it was sent, unhandled" + context);
  else if (r.killed_by != 0)
    fault(crash, "ended by signal " + std::to_string(r.killed_by) + context);
  if (r.err.find("internal error") != std::string::npos || r.err.find("Sanitizer") != std::string::npos ||
      r.err.find("runtime error:") != std::string::npos)
    fault(crash, "an internal or sanitizer error" + context);
  if (c.signal != 0) {
    if (!r.signal_sent)
      fault(other, "the moment to send the signal never came" + context);
    else if (!r.timed_out && r.seconds_after_signal > c.within)
      fault(hang, "took " + std::to_string(r.seconds_after_signal) + " s to end after the signal" + context);
  }
  if (!r.timed_out && r.killed_by == 0 && r.exit_code != c.exit_code)
    fault(other, "exit code " + std::to_string(r.exit_code) + ", expected " + std::to_string(c.exit_code) + context);

  // What it said.
  const long lines = std::count(r.err.begin(), r.err.end(), '\n');
  if (c.exit_code != 0 && !r.timed_out && r.killed_by == 0) {
    if (r.err.empty())
      fault(other, "failed without a word on stderr" + context);
    else if (lines != 1 || r.err.back() != '\n')
      fault(multi_line, std::to_string(lines) + " lines on stderr" + context);
  }
  std::istringstream err_lines(r.err);
  for (std::string line; std::getline(err_lines, line);)
    if (line.size() > kLongestLine) fault(long_line, "a stderr line of " + std::to_string(line.size()) + " characters");
  if (!std::regex_search(r.err, std::regex(c.stderr_pattern)))
    fault(other, "stderr does not match /" + c.stderr_pattern + "/" + context);
  if (c.stdout_pattern) {
    if (!std::regex_search(r.out, std::regex(*c.stdout_pattern)))
      fault(other, "stdout does not match /" + *c.stdout_pattern + "/" + context);
  } else if (c.exit_code != 0 && !r.out.empty() && c.stdout_to == RunOptions::Stdout::pipe) {
    fault(other, "printed on stdout although it failed" + context);
  }
  if (has_non_finite(r.out)) fault(non_finite, "inf or nan on stdout" + context);

  // What it left.
  std::vector<std::string> expected = c.after.value_or(listed_before);
  for (std::string& e : expected) e = substitute(e, dir.path());
  std::sort(expected.begin(), expected.end());
  const std::vector<std::string> listed = listing(dir.path());
  if (listed != expected) {
    const auto some = [](const std::vector<std::string>& entries) {
      std::string text;
      for (std::size_t i = 0; i < entries.size() && i < 20; ++i) text += "'" + entries[i] + "' ";
      return entries.size() > 20 ? text + "... (" + std::to_string(entries.size()) + " entries)" : text;
    };
    const std::string both = "\n  folder:   " + some(listed) + "\n  expected: " + some(expected);
    fault(leftover, "the folder is not as expected" + both + context);
  }
  for (const auto& [name, text] : before) {
    if (c.changed.contains(name)) continue;
    std::error_code ec;
    if (!fs::is_regular_file(dir / name, ec) || read_text(dir / name) != text)
      fault(leftover, "'" + name + "', there before the run, was changed or removed");
  }
  for (const auto& [name, pattern] : c.files) {
    std::error_code ec;
    if (!fs::is_regular_file(dir / name, ec)) {
      fault(other, "no file '" + name + "'");
      continue;
    }
    const std::string text = read_text(dir / name);
    if (!std::regex_search(text, std::regex(pattern)))
      fault(other, "'" + name + "' does not match /" + pattern + "/:\n  " + shown(text, 300));
    const bool binary = std::any_of(text.begin(), text.end(), [](char ch) { return ch >= 0 && ch < '\t'; });
    if (!binary && has_non_finite(text)) fault(non_finite, "inf or nan in '" + name + "'");
  }
  if (c.fifo_pattern) {
    if (!std::regex_search(fifo_text, std::regex(*c.fifo_pattern)))
      fault(other, "what came through the FIFO does not match /" + *c.fifo_pattern + "/:\n  " + shown(fifo_text, 300));
    if (has_non_finite(fifo_text)) fault(non_finite, "inf or nan through the FIFO");
  }

  ++tally.cases;
  bool any = false;
  for (int f = 0; f < kFaults; ++f) {
    tally.faults[f] += faults[f] ? 1 : 0;
    any = any || faults[f];
  }
  tally.passed += any ? 0 : 1;
}

INSTANTIATE_TEST_SUITE_P(Cases, Catalogue, ::testing::ValuesIn(catalogue().cases),
                         [](const ::testing::TestParamInfo<Case>& param) { return param.param.name; });

TEST(CatalogueFiles, AreValidAndHoldEnoughCases) {
  for (const std::string& problem : catalogue().problems) ADD_FAILURE() << problem;
  EXPECT_GE(catalogue().cases.size(), static_cast<std::size_t>(kMinimumCases));
  RecordProperty("cases", static_cast<int>(catalogue().cases.size()));
}

}  // namespace
}  // namespace linkage::test
