// `linkage solve`: the worked solution of the spec at any parameters and state.
#include <algorithm>
#include <memory>

#include "cli/angle_option.hpp"
#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/write_stdout.hpp"
#include "core/deriving.hpp"
#include "core/error.hpp"
#include "report/code_export.hpp"
#include "report/mechanism_latex.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"
#include "report/report_options.hpp"

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
  std::string angles = "rad";
  std::string form = "newton-euler";
  MechanismOptions mechanism;
};

std::vector<int> parse_case_selection(const std::string& which) {
  if (which == "all") return {1, 2, 3};
  if (which == "1" || which == "2" || which == "3") return {which[0] - '0'};
  throw Error::input("--case: '" + which + "' is not a case; valid: 1, 2, 3, all");
}

CaseForm parse_form(const std::string& form, const std::vector<int>& cases) {
  if (form != "newton-euler" && form != "lagrange")
    throw Error::input("--form: '" + form + "' is not a form; valid: newton-euler, lagrange");
  if (form == "newton-euler") return CaseForm::newton_euler;
  if (std::find(cases.begin(), cases.end(), 3) == cases.end())
    throw Error::input("--form lagrange writes Case 3, which --case " + std::to_string(cases.front()) +
                       " leaves out; valid with --case 3 or all");
  return CaseForm::lagrange;
}

int parse_digits(const std::string& text) {
  const double value = parse_number(text, "--digits", "");
  if (value != static_cast<int>(value) || value < kMinDigits || value > kMaxDigits)
    throw Error::input("--digits: '" + text + "' is out of range; valid: a whole number from " +
                       std::to_string(kMinDigits) + " to " + std::to_string(kMaxDigits));
  return static_cast<int>(value);
}

void run_solve(const SolveOptions& options) {
  const std::vector<int> cases = parse_case_selection(options.which);
  const std::string& format = options.format;
  if (format != "text" && format != "latex" && format != "markdown" && format != "json" && format != "matlab" &&
      format != "python")
    throw Error::input("--format: '" + format +
                       "' is not a format; valid: text, latex, markdown, json, matlab, python");
  if (options.ascii && options.unicode) throw Error::input("--ascii and --unicode exclude each other; give one");
  ReportOptions report;
  report.digits = parse_digits(options.digits);
  report.angles = parse_angle_unit(options.angles, "--angles");
  if (report.angles != AngleUnit::rad && format != "text")
    throw Error::input("--angles: deg applies to the text format; " + format + " keeps radians");
  report.text_style = options.ascii ? Style::ascii : options.unicode ? Style::unicode : text_style_from_locale();
  const CaseForm form = parse_form(options.form, cases);
  // The printed forms too: a long chain's take seconds, and nothing is written before them.
  Deriving deriving;
  const MechanismSolution solution =
      work_out_mechanism(chosen_mechanism(options.mechanism, options.inputs), case_ids(cases), form);
  std::string text;
  if (format == "json")  // the homework's interface keeps the spec's names (two-blocks.toml's [aliases])
    text = mechanism_json(solution, options.mechanism.chosen() ? JsonKeys::mechanism : JsonKeys::aliases);
  else if (format == "latex")
    text = mechanism_latex(solution, report);
  else if (format == "markdown")
    text = mechanism_markdown(solution, report);
  else if (format == "matlab")
    text = matlab_export(solution);
  else if (format == "python")
    text = python_export(solution);
  else
    text = mechanism_text(solution, report);
  deriving.done();
  write_stdout(text, "the worked solution");
}

}  // namespace

void register_solve(CLI::App& app) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* sub = app.add_subcommand(
      "solve",
      "Print the worked solution of a mechanism (default: the homework's two blocks): inputs, inertia, the "
      "joints' constraints, energy and momentum, then the symbolic and numeric A q = B of each selected case "
      "with its solution");
  sub->add_option("--case", options->which,
                  "Which formulation: 1 (maximal coordinates with every joint force; the homework's eight "
                  "DAEs), 2 (generalized coordinates with the joint forces; its six), 3 (joint forces "
                  "eliminated; its four), or all, which adds a table of how closely they agree (default all)")
      ->type_name("1|2|3|all");
  sub->add_option("--format", options->format,
                  "Output: text (aligned, 80 columns), latex (amsmath fragment: bmatrix, align*), markdown "
                  "(headings, tables, $$ math blocks), json (machine-readable, full precision), or code to continue "
                  "with: matlab (a function file, save it as NAME.m with NAME the mechanism's name, - for _) or "
                  "python (NumPy); each has a function per case returning A, B and the solution (default text)")
      ->type_name("FORMAT");
  sub->add_option("--digits", options->digits,
                  "Significant digits of the numbers in text, latex and markdown, 1 to 17; json always prints "
                  "full precision (default 6)")
      ->type_name("N");
  sub->add_flag("--ascii", options->ascii,
                "Text format in plain ASCII (th1'', x1'') whatever the locale (default: Unicode symbols when "
                "the locale uses UTF-8, else ASCII)");
  sub->add_flag("--unicode", options->unicode, "Text format with Unicode symbols whatever the locale");
  sub->add_option("--form", options->form,
                  "How Case 3 is written: newton-euler (the tree's joint forces eliminated from Newton-Euler, the "
                  "homework's (1.3) to (4.3)) or lagrange (the board's form: Lagrange's equations M(q) q'' = Q, one "
                  "row per generalized coordinate, M symmetric, trigonometry contracted; a closed loop adds its "
                  "forces as J^T lambda and its rows) (default newton-euler)")
      ->type_name("newton-euler|lagrange");
  add_angle_option(sub, options->angles, "angles, rates and angular accelerations in the text format's tables");
  add_mechanism_options(sub, options->mechanism);
  add_input_options(sub, options->inputs);
  add_runner(sub, [options] { run_solve(*options); });
}

}  // namespace linkage::cli
