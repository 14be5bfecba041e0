#include "model/inputs.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "model/inputs_toml.hpp"

namespace linkage {

const InputKey* find_input_key(std::string_view key) {
  for (const auto& k : kInputKeys)
    if (k.key == key) return &k;
  return nullptr;
}

std::string input_key_list() {
  std::string list;
  for (const auto& k : kInputKeys) {
    if (!list.empty()) list += ", ";
    list += k.key;
  }
  return list;
}

namespace {
std::size_t index_of(const InputKey& key) { return static_cast<std::size_t>(&key - kInputKeys.data()); }
}  // namespace

std::optional<std::string_view> closest_input_key(std::string_view key) {
  std::vector<std::string> names;
  for (const auto& k : kInputKeys) names.emplace_back(k.key);
  const auto close = closest_name(key, names);
  if (!close) return std::nullopt;
  return find_input_key(*close)->key;
}

std::string canonical_text(const Inputs& inputs) {
  std::string out;
  for (const InputKey& key : kInputKeys) {
    if (!out.empty()) out += ';';
    out += std::string(key.key) + "=" + format_roundtrip(inputs.value(key));
  }
  return out;
}

Inputs::Inputs() {
  for (std::size_t i = 0; i < kInputKeys.size(); ++i) values_[i] = kInputKeys[i].default_value;
  origins_.fill("default");
}

double Inputs::value(const InputKey& key) const { return values_[index_of(key)]; }

const std::string& Inputs::origin(const InputKey& key) const { return origins_[index_of(key)]; }

void Inputs::set(const InputKey& key, double value, std::string origin) {
  if (!std::isfinite(value))
    throw Error::invalid(origin, std::string(key.key) + " = " + format_roundtrip(value) + " is not a finite number");
  values_[index_of(key)] = value;
  origins_[index_of(key)] = std::move(origin);
}

void Inputs::validate() const {
  auto fail = [&](const char* key, const std::string& rule) {
    const InputKey& k = *find_input_key(key);
    // About the value's origin (a flag, a file position): the reader that recorded it.
    throw Error::invalid(origin(k), std::string(k.key) + " = " + format_roundtrip(value(k)) + " " +
                                        std::string(k.unit) + " is out of range; " + rule);
  };
  auto get = [&](const char* key) { return value(*find_input_key(key)); };
  const double L = get("L"), b = get("b");
  if (!(L > 0)) fail("L", "the block length must be > 0");
  if (!(get("w") > 0)) fail("w", "the block width must be > 0");
  if (!(get("m") > 0)) fail("m", "the mass must be > 0");
  if (!(get("g") >= 0)) fail("g", "g must be >= 0 (gravity points along -y)");
  if (!(b >= 0 && b <= L)) {
    // b was left at its default: the L given is what made it invalid.
    if (origin(*find_input_key("b")) == "default" && origin(*find_input_key("L")) != "default")
      fail("L", "the default b = " + format_roundtrip(b) + " m must lie in [0, L] = [0, " + format_roundtrip(L) +
                    "] m; give a smaller b too");
    fail("b", "b must lie in [0, L] = [0, " + format_roundtrip(L) + "] m");
  }
}

void Inputs::apply_file(const std::filesystem::path& path) {
  const toml::table table = parse_toml_file(path.string(), "config");
  apply_toml(*this, table, path.string(), "config");
}

}  // namespace linkage
