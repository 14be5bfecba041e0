#pragma once
// Subcommand registry: each subcommand lives in its own file and registers a CLI11
// subcommand plus the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>

namespace linkage::cli {

/// Adds every subcommand to `app`.
void register_commands(CLI::App& app);
/// Runs the subcommand the user chose (after parsing).
void run_selected(const CLI::App& app);

/// Called by each subcommand's register function.
void add_runner(CLI::App* subcommand, std::function<void()> run);

// One register function per subcommand file.
void register_solve(CLI::App& app);
void register_render(CLI::App& app);
void register_bench(CLI::App& app);
void register_lesson(CLI::App& app);
void register_simulate(CLI::App& app);
void register_mechanisms(CLI::App& app);
void register_modes(CLI::App& app);

}  // namespace linkage::cli
