#include "cli/input_options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage::cli {

void add_input_options(CLI::App* sub, InputOptions& options) {
  options.config_option = sub->add_option("--config", options.config,
                                          "TOML file of inputs (keys: " + input_key_list() + "); flags override it")
                              ->type_name("FILE")
                              ->group("Inputs");
  const Inputs defaults;
  for (std::size_t i = 0; i < kInputKeys.size(); ++i) {
    const InputKey& key = kInputKeys[i];
    const std::string help = std::string(key.description) + ", " + std::string(key.unit) + " (default " +
                             format_roundtrip(defaults.value(key)) + ")";
    options.options[i] =
        sub->add_option(flag_name(key.key), options.values[i], help)->type_name("NUM")->group("Inputs");
  }
}

std::string flag_name(std::string_view setting) {
  std::string flag = "--" + std::string(setting);
  std::replace(flag.begin() + 2, flag.end(), '_', '-');
  return flag;
}

std::string describe(const Error& error) {
  return error.setting_is_name() ? flag_name(error.setting()) + ": " + error.detail() : error.what();
}

Inputs resolve_inputs(const InputOptions& options) {
  Inputs inputs;
  if (options.config_option != nullptr && options.config_option->count() > 0) {
    if (options.config.empty()) throw Error::input("--config: the file name is empty; give a TOML file of inputs");
    inputs.apply_file(options.config);
  }
  for (std::size_t i = 0; i < kInputKeys.size(); ++i) {
    if (options.options[i] == nullptr || options.options[i]->count() == 0) continue;
    const InputKey& key = kInputKeys[i];
    const std::string flag = flag_name(key.key);
    inputs.set(key, parse_number(options.values[i], flag, std::string(key.unit)), flag);
  }
  inputs.validate();
  return inputs;
}

}  // namespace linkage::cli
