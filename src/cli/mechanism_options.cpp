#include "cli/mechanism_options.hpp"

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"

namespace linkage::cli {

namespace {

// --set NAME=VALUE applied in order; each names itself in errors.
void apply_settings(Mechanism& mechanism, const std::vector<std::string>& settings) {
  for (const std::string& setting : settings) {
    const auto equals = setting.find('=');
    if (equals == std::string::npos || equals == 0)
      throw Error::input("--set: '" + setting + "' is not NAME=VALUE; e.g. --set L=0.4 or --set 2.theta=0.3");
    // The value as the command line reads numbers (its message names the flag).
    (void)parse_number(setting.substr(equals + 1), "--set " + setting.substr(0, equals), "");
    try {
      apply_setting(mechanism, setting, "--set " + setting);
    } catch (const Error& e) {
      throw Error::input(describe(e));
    }
  }
}

}  // namespace

void add_mechanism_options(CLI::App* sub, MechanismOptions& options) {
  options.mechanism_option =
      sub->add_option("--mechanism", options.mechanism,
                      "A shipped mechanism by name (linkage mechanisms lists them) or a mechanism file (.toml); "
                      "default: the homework, two blocks joined by a pin")
          ->type_name("NAME|FILE");
  sub->add_option("--set", options.settings,
                  "Set a parameter or an initial coordinate of the mechanism, repeatable: --set L=0.4 --set "
                  "2.theta=0.3")
      ->type_name("NAME=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

Mechanism chosen_mechanism(const MechanismOptions& options, const InputOptions& inputs) {
  if (!options.chosen()) {
    Mechanism mechanism = default_mechanism(resolve_inputs(inputs));
    apply_settings(mechanism, options.settings);
    return mechanism;
  }
  for (std::size_t i = 0; i < kInputKeys.size(); ++i)
    if (inputs.options[i] != nullptr && inputs.options[i]->count() > 0)
      throw Error::input(flag_name(kInputKeys[i].key) +
                         " is a flag of the built-in homework; with --mechanism use --set " +
                         std::string(kInputKeys[i].mechanism_key) + "=VALUE");
  if (inputs.config_option != nullptr && inputs.config_option->count() > 0)
    throw Error::input("--config is for the built-in homework; with --mechanism the file is the mechanism itself");
  Mechanism mechanism = load_mechanism(options.mechanism);
  apply_settings(mechanism, options.settings);
  return mechanism;
}

}  // namespace linkage::cli
