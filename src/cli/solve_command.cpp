// `linkage solve`: the worked solution of the spec at any parameters and state.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "core/error.hpp"
#include "report/json_report.hpp"
#include "report/latex_report.hpp"
#include "report/text_report.hpp"
#include "report/worked_solution.hpp"

namespace linkage::cli {
namespace {

constexpr int kMinDigits = 1, kMaxDigits = 17;

struct SolveOptions {
  InputOptions inputs;
  std::string which = "all";
  std::string format = "text";
  std::string digits = "6";
  bool ascii = false;
  bool unicode = false;
};

std::vector<int> parse_case_selection(const std::string& which) {
  if (which == "all") return {1, 2, 3};
  if (which == "1" || which == "2" || which == "3") return {which[0] - '0'};
  throw Error::input("--case: '" + which + "' is not a case; valid: 1, 2, 3, all");
}

int parse_digits(const std::string& text) {
  const double value = parse_number(text, "--digits", "");
  if (value != static_cast<int>(value) || value < kMinDigits || value > kMaxDigits)
    throw Error::input("--digits: '" + text + "' is out of range; valid: a whole number from " +
                       std::to_string(kMinDigits) + " to " + std::to_string(kMaxDigits));
  return static_cast<int>(value);
}

void write_stdout(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    throw Error::failure("cannot write the worked solution to standard output");
}

void run_solve(const SolveOptions& options) {
  const std::vector<int> cases = parse_case_selection(options.which);
  const std::string& format = options.format;
  if (format != "text" && format != "latex" && format != "markdown" && format != "json")
    throw Error::input("--format: '" + format + "' is not a format; valid: text, latex, markdown, json");
  if (options.ascii && options.unicode) throw Error::input("--ascii and --unicode exclude each other; give one");
  ReportOptions report;
  report.digits = parse_digits(options.digits);
  report.text_style = options.ascii     ? expr::Style::ascii
                      : options.unicode ? expr::Style::unicode
                                        : text_style_from_locale();
  const Inputs inputs = resolve_inputs(options.inputs);
  const WorkedSolution worked = work_out(inputs, cases);
  if (format == "json")
    write_stdout(json_report(worked));
  else if (format == "latex")
    write_stdout(latex_report(worked, report));
  else if (format == "markdown")
    write_stdout(markdown_report(worked, report));
  else
    write_stdout(text_report(worked, report));
}

}  // namespace

void register_solve(CLI::App& app) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* sub = app.add_subcommand(
      "solve",
      "Print the worked solution: inputs, inertia, the pin constraint, energy and momentum, then the "
      "symbolic and numeric A q = B of each selected case with its solution");
  sub->add_option("--case", options->which,
                  "Which formulation: 1 (eight DAEs, maximal coordinates), 2 (six, generalized coordinates with "
                  "the pin force), 3 (four, pin force eliminated), or all, which adds a table of how closely "
                  "they agree (default all)")
      ->type_name("1|2|3|all");
  sub->add_option("--format", options->format,
                  "Output: text (aligned, 80 columns), latex (amsmath fragment: bmatrix, align*), markdown "
                  "(headings, tables, $$ math blocks) or json (machine-readable, full precision) (default text)")
      ->type_name("FORMAT");
  sub->add_option("--digits", options->digits,
                  "Significant digits of the numbers in text, latex and markdown, 1 to 17; json always prints "
                  "full precision (default 6)")
      ->type_name("N");
  sub->add_flag("--ascii", options->ascii,
                "Text format in plain ASCII (th1'', x1'') whatever the locale (default: Unicode symbols when "
                "the locale uses UTF-8, else ASCII)");
  sub->add_flag("--unicode", options->unicode, "Text format with Unicode symbols whatever the locale");
  add_input_options(sub, options->inputs);
  add_runner(sub, [options] { run_solve(*options); });
}

}  // namespace linkage::cli
