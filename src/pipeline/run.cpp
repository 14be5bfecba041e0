#include "pipeline/run.hpp"

#include "core/number_format.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {

std::shared_ptr<const BuiltMechanism> build_mechanism(const std::string& spec, const std::vector<std::string>& settings,
                                                      const std::string& origin, bool aliased) {
  Mechanism mechanism = load_mechanism(spec);
  for (const std::string& setting : settings) apply_setting(mechanism, setting, origin);
  auto made = std::make_shared<BuiltMechanism>();
  made->spec = spec;
  made->settings = settings;
  made->system = std::make_shared<const sym::System>(mechanism);
  made->initial = sym::checked_initial_state(*made->system).state;
  made->aliased = aliased;
  return made;
}

std::vector<std::string> default_mechanism_settings(const Inputs& inputs) {
  std::vector<std::string> out;
  for (const InputKey& key : kInputKeys)
    out.push_back(std::string(key.mechanism_key) + "=" + format_roundtrip(inputs.value(key)));
  return out;
}

std::vector<MechanismColumn> BuiltMechanism::named_columns() const {
  std::vector<MechanismColumn> out = mechanism_columns(*system);
  for (MechanismColumn& c : out) c.name = named(c.name);
  return out;
}

}  // namespace linkage
