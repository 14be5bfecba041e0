#include "cli/commands.hpp"

#include <string>
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

namespace {
/// An empty value (`--dt ""`) is a mistake, never a quiet "use the default": every
/// option that takes a value refuses it, but --title, where "" means no title.
void refuse_empty_values(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    refuse_empty_values(*sub);
    for (CLI::Option* option : sub->get_options()) {
      if (option->get_type_size() == 0 || option->get_name() == "--title") continue;
      const bool positional = option->get_positional();
      option->check(CLI::Validator(
          [positional](std::string& value) {
            if (!value.empty()) return std::string();
            return std::string(positional ? "the value is empty; give one"
                                          : "the value is empty; give a value, or leave the option out for its "
                                            "default");
          },
          ""));
    }
  }
}
}  // namespace

void register_commands(CLI::App& app) {
  register_solve(app);
  register_render(app);
  register_bench(app);
  register_lesson(app);
  register_simulate(app);
  register_mechanisms(app);
  register_modes(app);
  refuse_empty_values(app);
}

void run_selected(const CLI::App& /*app*/) {
  for (auto& [subcommand, run] : runners())
    if (subcommand->parsed()) run();
}

}  // namespace linkage::cli
