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

double parse_number(const std::string& text, const std::string& origin, const std::string& unit) {
  double value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last)
    throw Error::input(origin + ": '" + text + "' is outside the range of double precision (about 1e-308 to 1e308)");
  if (text.empty() || ec != std::errc() || ptr != last)
    throw Error::input(origin + ": '" + text + "' is not a number" + (unit.empty() ? "" : " (" + unit + ")"));
  if (!std::isfinite(value))
    throw Error::input(origin + ": '" + text + "' is not a finite number; give a finite value" +
                       (unit.empty() ? "" : " in " + unit));
  return value;
}

std::string flag_name(std::string_view setting) {
  std::string flag = "--" + std::string(setting);
  std::replace(flag.begin() + 2, flag.end(), '_', '-');
  return flag;
}

std::string describe(const Error& error) {
  const std::string& setting = error.setting();
  const bool identifier = !setting.empty() && std::all_of(setting.begin(), setting.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  return identifier ? flag_name(setting) + ": " + error.detail() : error.what();
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

std::vector<std::string> split_commas(const std::string& list) {
  std::vector<std::string> items;
  std::size_t at = 0;
  while (!list.empty() && at <= list.size()) {
    const std::size_t comma = std::min(list.find(',', at), list.size());
    items.push_back(list.substr(at, comma - at));
    at = comma + 1;
  }
  return items;
}

}  // namespace linkage::cli
