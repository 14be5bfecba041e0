// `linkage solve`: the worked solution of the spec at any parameters and state.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "core/error.hpp"
#include "report/json_report.hpp"
#include "report/worked_solution.hpp"

namespace linkage::cli {
namespace {

struct SolveOptions {
  InputOptions inputs;
  std::string which = "all";
  std::string format = "text";
};

std::vector<int> parse_case_selection(const std::string& which) {
  if (which == "all") return {1, 2, 3};
  if (which == "1" || which == "2" || which == "3") return {which[0] - '0'};
  throw Error::input("--case: '" + which + "' is not a case; valid: 1, 2, 3, all");
}

void run_solve(const SolveOptions& options) {
  const std::vector<int> cases = parse_case_selection(options.which);
  if (options.format != "text" && options.format != "latex" && options.format != "markdown" && options.format != "json")
    throw Error::input("--format: '" + options.format + "' is not a format; valid: text, latex, markdown, json");
  const Inputs inputs = resolve_inputs(options.inputs);
  const WorkedSolution worked = work_out(inputs, cases);
  std::string out;
  if (options.format == "json") out = json_report(worked);
  else throw Error::input("--format " + options.format + " is not implemented yet");
  std::fwrite(out.data(), 1, out.size(), stdout);
}

}  // namespace

void register_solve(CLI::App& app) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* sub = app.add_subcommand("solve", "Print the worked solution: derived quantities and every matrix of the selected case");
  sub->add_option("--case", options->which, "Which formulation: 1 (eight DAEs), 2 (six), 3 (four), or all (default all)")
      ->type_name("1|2|3|all");
  sub->add_option("--format", options->format, "Output format: text, latex, markdown or json (default text)")
      ->type_name("FORMAT");
  add_input_options(sub, options->inputs);
  add_runner(sub, [options] { run_solve(*options); });
}

}  // namespace linkage::cli
