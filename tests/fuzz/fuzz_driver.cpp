// A small deterministic driver for a libFuzzer-style target (LLVMFuzzerTestOneInput),
// for machines without clang: the seed corpus first, then mutations of it (bit flips,
// insertions of characters that open nesting or strings, repeated insertions, deletions,
// duplications, splices of two seeds) from a fixed seed, until --inputs inputs or
// --seconds seconds, whichever comes first. The target may only return; an exception
// escaping it is a finding: the input is saved and printed hex-escaped, exit code 1. A
// crash or an input that runs for --hang seconds names the saved input and exits too.
//
//   fuzz_NAME [--inputs N] [--seconds S] [--seed N] [--hang S] [--expect-finding] SEED_FILE_OR_FOLDER... (a folder: its
//   *.toml files)
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "fuzz/fuzz_support.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kLargestInput = 1 << 16;

/// splitmix64: the same sequence on every machine and standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// In [0, n) for n > 0.
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t state_;
};

// What readers of TOML, Markdown, LaTeX and expressions treat specially.
constexpr std::array<std::string_view, 40> kTokens{"{",
                                                   "}",
                                                   "[",
                                                   "]",
                                                   "[[",
                                                   "]]",
                                                   "\\sqrt{",
                                                   "\\frac{",
                                                   "{{",
                                                   "}}",
                                                   "\"",
                                                   "'",
                                                   "\"\"\"",
                                                   "'''",
                                                   "\\",
                                                   "\\u",
                                                   "$",
                                                   "$$",
                                                   "^",
                                                   "_",
                                                   "(",
                                                   ")",
                                                   "=",
                                                   ".",
                                                   ",",
                                                   "\n",
                                                   "#",
                                                   "- ",
                                                   "* ",
                                                   "|",
                                                   "nan",
                                                   "inf",
                                                   "-inf",
                                                   "1e400",
                                                   "1/0",
                                                   "sqrt(-1)",
                                                   std::string_view("\0", 1),
                                                   "\xff",
                                                   "\t",
                                                   "[[step]]\n"};

using Bytes = std::string;

void mutate(Bytes& input, const std::vector<Bytes>& seeds, Random& random) {
  const std::size_t at = input.empty() ? 0 : random.below(input.size() + 1);
  switch (random.below(8)) {
    case 0:  // flip a bit
      if (!input.empty()) input[random.below(input.size())] ^= static_cast<char>(1 << random.below(8));
      break;
    case 1:  // a token
      input.insert(at, kTokens[random.below(kTokens.size())]);
      break;
    case 2: {  // a token many times: deep nesting, long runs
      static constexpr std::array<std::size_t, 6> counts{2, 10, 63, 65, 200, 2000};
      const std::string_view token = kTokens[random.below(kTokens.size())];
      const std::size_t count = counts[random.below(counts.size())];
      Bytes run;
      for (std::size_t i = 0; i < count; ++i) run += token;
      input.insert(at, run);
      break;
    }
    case 3:  // delete a few bytes
      if (!input.empty()) input.erase(random.below(input.size()), 1 + random.below(16));
      break;
    case 4:  // duplicate a slice elsewhere
      if (!input.empty()) {
        const std::size_t from = random.below(input.size());
        input.insert(at, input.substr(from, 1 + random.below(64)));
      }
      break;
    case 5: {  // splice: this input's start, another seed's end
      const Bytes& other = seeds[random.below(seeds.size())];
      input = input.substr(0, at) + other.substr(other.empty() ? 0 : random.below(other.size()));
      break;
    }
    case 6:  // any byte
      if (!input.empty()) input[random.below(input.size())] = static_cast<char>(random.below(256));
      break;
    default:  // a line from another seed
      if (const Bytes& other = seeds[random.below(seeds.size())]; !other.empty()) {
        const std::size_t start = other.rfind('\n', random.below(other.size()));
        const std::size_t begin = start == Bytes::npos ? 0 : start + 1;
        input.insert(at, other.substr(begin, other.find('\n', begin) - begin) + "\n");
      }
      break;
  }
  if (input.size() > kLargestInput) input.resize(kLargestInput);
}

std::string hex_escaped(const Bytes& input, std::size_t limit = 4000) {
  std::string out;
  for (const char c : input.substr(0, limit)) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    }
  }
  if (input.size() > limit) out += "...(" + std::to_string(input.size() - limit) + " more bytes)";
  return out;
}

std::vector<Bytes> load_seeds(const std::vector<std::string>& paths) {
  std::vector<fs::path> files;
  for (const std::string& p : paths) {
    if (fs::is_directory(p)) {
      std::vector<fs::path> in_folder;
      for (const auto& entry : fs::directory_iterator(p))
        if (entry.is_regular_file() && entry.path().extension() == ".toml") in_folder.push_back(entry.path());
      std::sort(in_folder.begin(), in_folder.end());
      files.insert(files.end(), in_folder.begin(), in_folder.end());
    } else {
      files.emplace_back(p);
    }
  }
  std::vector<Bytes> seeds;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw std::runtime_error("cannot read the seed " + f.string());
    seeds.push_back(text.str());
  }
  return seeds;
}

// For the signal handlers: a message made before any input runs.
std::string crash_message;
std::string hang_message;

extern "C" void on_crash(int signal) {
  (void)!::write(STDERR_FILENO, crash_message.data(), crash_message.size());
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

extern "C" void on_hang(int) {
  (void)!::write(STDERR_FILENO, hang_message.data(), hang_message.size());
  ::_exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  long inputs = 5000;
  double seconds = 20;
  std::uint64_t seed = 20240611;
  unsigned hang_seconds = 10;
  bool expect_finding = false;  // a test of the driver: report the finding, keep nothing, exit 0
  std::vector<std::string> corpus;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--inputs" && has_value)
      inputs = std::stol(argv[++i]);
    else if (arg == "--seconds" && has_value)
      seconds = std::stod(argv[++i]);
    else if (arg == "--seed" && has_value)
      seed = std::stoull(argv[++i]);
    else if (arg == "--expect-finding")
      expect_finding = true;
    else if (arg == "--hang" && has_value)
      hang_seconds = static_cast<unsigned>(std::stoul(argv[++i]));
    else
      corpus.push_back(arg);
  }
  const char* name = argv[0];
  const std::vector<Bytes> seeds = load_seeds(corpus);
  if (seeds.empty()) {
    std::fprintf(stderr, "%s: no seed inputs given\n", name);
    return 2;
  }

  const fs::path current = linkage::fuzz::scratch_folder() / "current-input";
  crash_message = std::string(name) + ": CRASH; the input is saved in " + current.string() + "\n";
  hang_message = std::string(name) + ": HANG (over " + std::to_string(hang_seconds) + " s); the input is saved in " +
                 current.string() + "\n";
  for (int s : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(s, on_crash);
  std::signal(SIGALRM, on_hang);

  Random random(seed);
  constexpr std::size_t kAcceptedPool = 64;
  std::vector<Bytes> accepted;  // mutants the reader accepted, to mutate further
  const auto start = std::chrono::steady_clock::now();
  long ran = 0;
  std::size_t largest = 0;
  for (; ran < inputs; ++ran) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > seconds) break;
    // The seeds as they are, then mutants of a seed or of a mutant the reader accepted.
    const bool seed_run = static_cast<std::size_t>(ran) < seeds.size();
    Bytes input = seed_run                                    ? seeds[static_cast<std::size_t>(ran)]
                  : !accepted.empty() && random.below(2) == 0 ? accepted[random.below(accepted.size())]
                                                              : seeds[random.below(seeds.size())];
    if (!seed_run)
      for (std::size_t m = 1 + random.below(4); m > 0; --m) mutate(input, seeds, random);
    const std::size_t accepted_before = linkage::fuzz::accepted_count();
    largest = std::max(largest, input.size());
    linkage::fuzz::write_input("current-input", reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    ::alarm(hang_seconds);
    try {
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    } catch (const std::exception& e) {
      ::alarm(0);
      const fs::path kept = linkage::fuzz::scratch_folder() / ("failure-" + std::to_string(ran));
      fs::copy_file(current, kept, fs::copy_options::overwrite_existing);
      std::fprintf(stderr, "%s: input %ld (%zu bytes) threw %s: %s\nsaved in %s\ninput: %s\n", name, ran, input.size(),
                   typeid(e).name(), e.what(), kept.string().c_str(), hex_escaped(input).c_str());
      if (expect_finding) fs::remove_all(linkage::fuzz::scratch_folder());  // the driver's own test
      return expect_finding ? 0 : 1;
    } catch (...) {
      ::alarm(0);
      std::fprintf(stderr, "%s: input %ld (%zu bytes) threw a non-standard exception; saved in %s\ninput: %s\n", name,
                   ran, input.size(), current.string().c_str(), hex_escaped(input).c_str());
      return 1;
    }
    ::alarm(0);
    if (!seed_run && linkage::fuzz::accepted_count() > accepted_before) {
      if (accepted.size() < kAcceptedPool)
        accepted.push_back(input);
      else
        accepted[random.below(kAcceptedPool)] = input;
    }
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%s: %ld inputs (%zu seeds, seed %llu, largest %zu bytes), %zu accepted, the rest refused, in %.1f s; no crash, "
      "hang or unexpected error\n",
      name, ran, seeds.size(), static_cast<unsigned long long>(seed), largest, linkage::fuzz::accepted_count(),
      elapsed);
  std::error_code ec;
  fs::remove_all(linkage::fuzz::scratch_folder(), ec);
  return 0;
}
