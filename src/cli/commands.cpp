#include "cli/commands.hpp"

#include <utility>
#include <vector>

namespace linkage::cli {
namespace {
std::vector<std::pair<CLI::App*, std::function<void()>>>& runners() {
  static std::vector<std::pair<CLI::App*, std::function<void()>>> list;
  return list;
}
}  // namespace

void add_runner(CLI::App* subcommand, std::function<void()> run) { runners().emplace_back(subcommand, std::move(run)); }

void register_commands(CLI::App& app) {
  register_solve(app);
  register_render(app);
  register_bench(app);
  register_lesson(app);
  register_simulate(app);
}

void run_selected(const CLI::App& /*app*/) {
  for (auto& [subcommand, run] : runners())
    if (subcommand->parsed()) run();
}

}  // namespace linkage::cli
