// `linkage modes`: a mechanism's small vibrations about its equilibrium (issue 26).
#include <memory>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/write_stdout.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "formulations/linearization.hpp"
#include "report/modes_report.hpp"

namespace linkage::cli {
namespace {

constexpr int kMinDigits = 1, kMaxDigits = 17;

struct ModesOptions {
  MechanismOptions mechanism;
  InputOptions inputs;  // not offered: chosen_mechanism reads it empty
  std::string format = "text";
  std::string digits = "6";
  bool at_initial = false;
  bool verify = false;
  bool ascii = false;
};

void run_modes(const ModesOptions& options) {
  if (options.format != "text" && options.format != "latex" && options.format != "markdown" && options.format != "json")
    throw Error::input("--format: '" + options.format +
                       "' is not a format of modes; valid: text, latex, markdown, json");
  const double digits = parse_number(options.digits, "--digits", "");
  if (digits != static_cast<int>(digits) || digits < kMinDigits || digits > kMaxDigits)
    throw Error::input("--digits: '" + options.digits + "' is out of range; valid: a whole number from " +
                       std::to_string(kMinDigits) + " to " + std::to_string(kMaxDigits));
  if (!options.mechanism.chosen())
    throw Error::input(
        "--mechanism: modes needs a mechanism with an equilibrium (the homework's two blocks fall "
        "freely); e.g. --mechanism double-pendulum");
  const sym::System system(chosen_mechanism(options.mechanism, options.inputs));
  const ModesAnalysis a = analyse_modes(system, options.at_initial, options.verify);
  ReportOptions report;
  report.digits = static_cast<int>(digits);
  report.text_style = options.ascii ? Style::ascii : text_style_from_locale();
  const std::string text = options.format == "json"    ? modes_json(system, a.linear, a.modes, a.checked())
                           : options.format == "latex" ? modes_latex(system, a.linear, a.modes, report, a.checked())
                           : options.format == "markdown"
                               ? modes_markdown(system, a.linear, a.modes, report, a.checked())
                               : modes_text(system, a.linear, a.modes, report, a.checked());
  write_stdout(text, "the modes");
}

}  // namespace

void register_modes(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* sub = app.add_subcommand(
      "modes",
      "Small vibrations of a mechanism: its static equilibrium (Newton's method from [initial]), the equations "
      "linearized about it in the independent coordinates (a closed loop reduced exactly through its "
      "constraints), M z'' + C z' + K z = 0, and its modes: natural frequencies, damping ratios, mode shapes; an "
      "unstable equilibrium with its growth rates");
  add_mechanism_options(sub, options->mechanism);
  sub->add_option("--format", options->format,
                  "Output: text, latex (a fragment needing amsmath), markdown or json (default text)")
      ->type_name("text|latex|markdown|json");
  sub->add_option("--digits", options->digits, "Significant digits in text, LaTeX and Markdown, 1 to 17 (default 6)")
      ->type_name("N");
  sub->add_flag("--at-initial", options->at_initial,
                "Linearize at the file's [initial] coordinates (rates zero) instead of the equilibrium found from "
                "them; the text says how far from an equilibrium that is");
  sub->add_flag("--verify", options->verify,
                "Check each oscillating mode against the full equations: start them at rest on the mode's shape "
                "(small amplitude) and compare the frequency of the motion's zero crossings with the computed one");
  sub->add_flag("--ascii", options->ascii, "Text in plain ASCII whatever the locale");
  add_runner(sub, [options] { run_modes(*options); });
}

}  // namespace linkage::cli
