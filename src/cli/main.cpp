// linkage: worked solutions, simulation and animation of two pinned blocks.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/native_shipped.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/name_match.hpp"
#include "evaluate/native_builtin.hpp"
#include "linkage/version.hpp"

namespace {

/// Everything written to standard output must have arrived: a full disk or a closed
/// pipe is an error, not a silent loss.
int finish_standard_output() {
  errno = 0;
  std::cout.flush();
  const bool ok = static_cast<bool>(std::cout) && std::fflush(stdout) == 0 && std::ferror(stdout) == 0;
  if (ok) return 0;
  int error_number = errno;
  // A long text (a command's help) fails while it is written, and errno is gone by now:
  // one more byte asks the output why.
  if (error_number == 0 && ::write(STDOUT_FILENO, "\n", 1) < 0) error_number = errno;
  std::fprintf(stderr, "linkage: error: cannot write standard output: %s\n",
               error_number != 0 ? std::strerror(error_number) : "write error");
  return static_cast<int>(linkage::ExitCode::failure);
}

/// A message as one readable line: control characters escaped (a value with a newline
/// stays on the line) and a very long quoted value shortened in the middle.
std::string one_line(const std::string& message) {
  constexpr std::size_t kLongest = 120;
  std::string escaped;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n')
      escaped += "\\n";
    else if (c == '\t')
      escaped += "\\t";
    else if (c == '\r')
      escaped += "\\r";
    else if (u < 0x20 || u == 0x7f) {
      static constexpr char hex[] = "0123456789abcdef";
      escaped += "\\x";
      escaped += hex[u >> 4];
      escaped += hex[u & 15];
    } else {
      escaped += c;
    }
  }
  std::string out;
  std::size_t start = 0;
  while (start < escaped.size()) {
    const std::size_t open = escaped.find('\'', start);
    const std::size_t close = open == std::string::npos ? std::string::npos : escaped.find('\'', open + 1);
    if (close == std::string::npos) {
      out += escaped.substr(start);
      break;
    }
    out += escaped.substr(start, open + 1 - start);
    const std::string value = escaped.substr(open + 1, close - open - 1);
    if (value.size() > kLongest)
      out += value.substr(0, kLongest / 2) + "...(" + std::to_string(value.size() - kLongest) + " more characters)..." +
             value.substr(value.size() - kLongest / 2);
    else
      out += value;
    out += '\'';
    start = close + 1;
  }
  return out;
}

void print_error(const std::string& message, const char* tail = "") {
  std::fprintf(stderr, "linkage: error: %s%s\n", one_line(message).c_str(), tail);
}

/// "linkage solv", "linkage bench acuracy", "linkage --frobnicate": name the unknown word
/// and the nearest command (CLI11 would only say that a subcommand is required).
void check_command_words(const CLI::App& app, int argc, char** argv) {
  const CLI::App* level = &app;
  std::string path = "linkage";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    std::vector<std::string> names;
    const CLI::App* chosen = nullptr;
    for (const CLI::App* sub : level->get_subcommands({})) {
      if (sub->get_name() == word) chosen = sub;
      names.push_back(sub->get_name());
    }
    if (names.empty()) return;  // a command's own arguments: CLI11 checks them
    if (word.size() > 1 && word[0] == '-' && word != "--") {
      const std::string flag = word.substr(0, word.find('='));
      for (const CLI::Option* option : level->get_options())
        if (option->check_name(flag)) return;  // --help, --version
      throw linkage::Error::input("'" + flag + "' is not an option of '" + path +
                                  "'; give a command first; valid: " + linkage::join_names(names));
    }
    if (chosen != nullptr) {
      level = chosen;
      path += " " + word;
      continue;
    }
    throw linkage::Error::input("'" + word + "' is not a " +
                                (level == &app ? std::string() : "'" + level->get_name() + "' ") + "command" +
                                linkage::did_you_mean(word, names) + "; valid: " + linkage::join_names(names));
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace linkage;
  CLI::App app{
      "linkage: planar multibody dynamics for teaching. For any planar mechanism of rigid bodies, pins,\n"
      "sliders, springs and loads (a shipped one, see 'linkage mechanisms', or your own .toml): worked\n"
      "solutions of its equations of motion in three formulations, simulation, lecture animations and\n"
      "lessons. The first example and the default: the homework, two identical blocks joined by a\n"
      "frictionless pin, free in the vertical plane (mechanisms/two-blocks.toml)."};
  app.set_version_flag("--version", std::string("linkage ") + kVersion);
  app.require_subcommand(1);
  app.fallthrough(false);

  cli::register_commands(app);
  install_interrupt_handler();
  eval::use_builtin_native({eval::kShippedNative, eval::kShippedNativeCount});
  try {
    check_command_words(app, argc, argv);
    app.parse(argc, argv);
    cli::run_selected(app);
    // A signal while the run ended (freeing a long chain's expressions takes a while after
    // its output is whole) still ends it with 128 + the signal.
    if (interrupt_requested()) {
      const int written = finish_standard_output();
      print_error(interrupted_error().what());
      return written != 0 ? written : interrupted_error().exit_status();
    }
    end_by_default_on_signal();  // what is left polls nothing
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {
      const int code = app.exit(e);  // --help, --version
      return code != 0 ? code : finish_standard_output();
    }
    print_error(e.what(), " (see 'linkage --help')");
    return static_cast<int>(ExitCode::bad_input);
  } catch (const Error& e) {
    // A signal can make a blocked call fail first: report the signal, not its echo.
    const Error& reported = interrupt_requested() ? interrupted_error() : e;
    print_error(cli::describe(reported));
    return reported.exit_status();
  } catch (const std::exception& e) {
    if (interrupt_requested()) {
      print_error(interrupted_error().what());
      return interrupted_error().exit_status();
    }
    std::fprintf(stderr, "linkage: internal error: %s\n", one_line(e.what()).c_str());
    return static_cast<int>(ExitCode::failure);
  }
  return finish_standard_output();
}
