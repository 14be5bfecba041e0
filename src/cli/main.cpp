// linkage: worked solutions, simulation and animation of two pinned blocks.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "linkage/version.hpp"

int main(int argc, char** argv) {
  using namespace linkage;
  CLI::App app{"linkage: two identical blocks joined by a frictionless pin, free in the vertical plane.\n"
               "Worked solutions of the equations of motion, simulation, and lecture animations."};
  app.set_version_flag("--version", std::string("linkage ") + kVersion);
  app.require_subcommand(1);
  app.fallthrough(false);

  cli::register_commands(app);
  install_interrupt_handler();
  try {
    app.parse(argc, argv);
    cli::run_selected(app);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "linkage: error: %s (see 'linkage --help')\n", e.what());
    return static_cast<int>(ExitCode::bad_input);
  } catch (const Error& e) {
    std::fprintf(stderr, "linkage: error: %s\n", e.what());
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "linkage: internal error: %s\n", e.what());
    return static_cast<int>(ExitCode::failure);
  }
  return 0;
}
