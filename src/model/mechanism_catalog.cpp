// The shipped mechanisms (mechanisms/*.toml, built into the program) and mechanism files.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/name_match.hpp"
#include "linkage/embedded_mechanisms.hpp"
#include "model/inputs.hpp"
#include "model/mechanism_toml.hpp"

namespace linkage {

std::vector<std::string> shipped_mechanism_names() {
  std::vector<std::string> names;
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) names.emplace_back(shipped.name);
  std::sort(names.begin(), names.end());
  return names;
}

Mechanism default_mechanism(const Inputs& inputs) {
  Mechanism mechanism = load_mechanism(kDefaultMechanism);
  for (const InputKey& key : kInputKeys)
    if (inputs.origin(key) != "default")
      set_value(mechanism, std::string(key.mechanism_key), inputs.value(key), inputs.origin(key));
  return mechanism;
}

Mechanism read_mechanism_file(const std::filesystem::path& path) {
  require_regular_file(path, "mechanism");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error::invalid("mechanism", "cannot read " + quoted(path) + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error::invalid("mechanism", "cannot read " + quoted(path) + ": " + std::strerror(errno));
  return read_mechanism(text.str(), path.string());
}

bool is_mechanism_file(std::string_view name_or_file) {
  return name_or_file.find('/') != std::string_view::npos || name_or_file.ends_with(".toml");
}

Mechanism load_mechanism(const std::string& name_or_file) {
  const std::string suffix = ".toml";
  if (is_mechanism_file(name_or_file)) return read_mechanism_file(name_or_file);
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    if (shipped.name != name_or_file) continue;
    Mechanism mechanism = read_mechanism(shipped.toml, name_or_file + suffix);
    mechanism.source = "built-in " + name_or_file + suffix;
    return mechanism;
  }
  const std::vector<std::string> names = shipped_mechanism_names();
  throw Error::invalid("mechanism", "'" + name_or_file + "' is not a shipped mechanism" +
                                        did_you_mean(name_or_file, names) + "; valid: " + join_names(names) +
                                        ", or a file path (with '/' or ending in .toml)");
}

}  // namespace linkage
