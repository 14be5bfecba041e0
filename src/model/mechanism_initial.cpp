// The initial state of a mechanism against its generalized coordinates, and --set.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/character_text.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "model/mechanism_toml.hpp"
#include "model/spanning_tree.hpp"

namespace linkage {
namespace {

constexpr std::string_view kRate = "_dot";

std::string q(std::string_view text) {
  std::string out(1, '\'');
  out += text;
  out += '\'';
  return out;
}

std::vector<std::string> coordinate_keys(const SpanningTree& tree) {
  std::vector<std::string> keys;
  for (const Coordinate& c : tree.coordinates) keys.push_back(c.key);
  return keys;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// "1.theta_dot" -> "1.theta"; anything else unchanged.
std::string without_rate(const std::string& key) {
  if (key.size() > kRate.size() && key.compare(key.size() - kRate.size(), kRate.size(), kRate) == 0)
    return key.substr(0, key.size() - kRate.size());
  return key;
}

bool is_coordinate_or_rate(const std::vector<std::string>& coordinates, const std::string& key) {
  return contains(coordinates, key) || (without_rate(key) != key && contains(coordinates, without_rate(key)));
}

// Why a body's or slider's key is not a coordinate: what the tree makes of that part.
std::string reason(const Mechanism& mechanism, const SpanningTree& tree, const std::string& key) {
  const std::string part = key.substr(0, key.find('.'));
  for (std::size_t i = 0; i < mechanism.bodies.size(); ++i) {
    const Body& body = mechanism.bodies[i];
    if (body.name != part) continue;
    const TreeBody& node = tree.bodies[i];
    std::vector<std::string> own;
    for (const Coordinate& c : tree.coordinates)
      if (c.body == static_cast<int>(i)) own.push_back(c.key);
    std::string how = "a floating base";
    if (!node.floating) {
      const Joint& joint = mechanism.joints[static_cast<std::size_t>(node.joint)];
      how = "carried by " + std::string(kJointTypeNames[static_cast<std::size_t>(joint.type)]) + " " + q(joint.name);
    }
    if (!body_rotates(body)) how += ", a point mass with no angle";
    return " (body " + q(part) + " is " + how + ": its coordinates: " + join_names(own) + ")";
  }
  for (int j : tree.loop_joints)
    if (mechanism.joints[static_cast<std::size_t>(j)].name == part)
      return " (slider " + q(part) + " closes a loop: it adds no coordinate)";
  return {};
}

std::string valid_coordinates(const std::vector<std::string>& coordinates) {
  if (coordinates.empty()) return "none (this mechanism has no generalized coordinates)";
  return join_names(coordinates) + " and their rates (" + coordinates.front() + std::string(kRate) + ", ...)";
}

}  // namespace

void validate_initial(const Mechanism& mechanism) {
  const SpanningTree tree = spanning_tree(mechanism);
  const std::vector<std::string> coordinates = coordinate_keys(tree);
  for (const InitialValue& value : mechanism.initial)
    if (!is_coordinate_or_rate(coordinates, value.key))
      throw Error::input(where(value.pos) + "[initial] " + value.key +
                         " is not a generalized coordinate or rate of this mechanism" +
                         reason(mechanism, tree, value.key) + "; valid: " + valid_coordinates(coordinates));
  std::vector<std::string> missing;
  for (const std::string& key : coordinates) {
    const bool given = std::any_of(mechanism.initial.begin(), mechanism.initial.end(),
                                   [&](const InitialValue& v) { return v.key == key; });
    if (!given) missing.push_back(key);
  }
  if (!missing.empty())
    throw Error::input(where(mechanism.initial_pos) + "[initial] misses " + join_names(missing) +
                       "; give every generalized coordinate: " + join_names(coordinates) + " (rates default to 0)");
  for (const std::string& key : mechanism.independent)
    if (!contains(coordinates, key))
      throw Error::input(where(mechanism.independent_pos) + "[initial] independent names " + q(key) +
                         ", which is not a generalized coordinate" + did_you_mean(key, coordinates) +
                         "; valid: " + join_names(coordinates));
}

void set_value(Mechanism& mechanism, const std::string& name, double value, const std::string& origin) {
  if (!std::isfinite(value))
    throw Error::invalid("set", name + " = " + format_roundtrip(value) + " (" + origin + ") is not a finite number");
  if (!in_magnitude_range(value))
    throw Error::invalid(
        "set", name + " = " + format_roundtrip(value) + " (" + origin + ") is out of range; valid: " + kMagnitudeRange);
  const SourcePos from{origin, 0, 0};
  for (Parameter& parameter : mechanism.parameters) {
    if (parameter.name != name) continue;
    parameter.value = value;
    parameter.pos = from;
    return;
  }
  const std::vector<std::string> coordinates = coordinate_keys(spanning_tree(mechanism));
  if (is_coordinate_or_rate(coordinates, name)) {
    for (InitialValue& initial : mechanism.initial) {
      if (initial.key != name) continue;
      initial.value = value;
      initial.pos = from;
      return;
    }
    mechanism.initial.push_back({name, value, from});
    return;
  }
  for (const Definition& definition : mechanism.definitions)
    if (definition.name == name)
      throw Error::invalid("set", q(name) + " (" + origin + ") is a definition (" + name + " = " +
                                      definition.value.text + "), not a parameter; set the parameters it uses");
  std::vector<std::string> parameters;
  for (const Parameter& parameter : mechanism.parameters) parameters.push_back(parameter.name);
  std::vector<std::string> candidates = parameters;
  candidates.insert(candidates.end(), coordinates.begin(), coordinates.end());
  throw Error::invalid("set", q(name) + " (" + origin + ") is not a parameter or initial coordinate of " +
                                  q(mechanism.name) + did_you_mean(name, candidates) + "; valid parameters: " +
                                  join_names(parameters) + "; coordinates: " + valid_coordinates(coordinates));
}

std::string likely_causes(const Mechanism& mechanism) {
  struct Given {
    std::string name;
    double value;
    const SourcePos* pos;
  };
  std::vector<Given> all;
  for (const Parameter& p : mechanism.parameters) all.push_back({p.name, p.value, &p.pos});
  for (const InitialValue& v : mechanism.initial) all.push_back({v.key, v.value, &v.pos});
  const auto where = [](const SourcePos& pos) {
    return pos.line == 0 ? pos.file : pos.file + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
  };
  const auto list = [&](auto&& keep) {
    std::string out;
    for (const Given& g : all) {
      if (!keep(g)) continue;
      out += out.empty() ? "" : ", ";
      out += mechanism.named(g.name) + " = " + format_roundtrip(g.value) + " (" + where(*g.pos) + ")";
    }
    return out;
  };
  const std::string extreme = list([](const Given& g) {
    const double v = std::fabs(g.value);
    return v >= 1e50 || (v > 0 && v <= 1e-50);
  });
  if (!extreme.empty()) return extreme;
  // Nothing extreme on its own: the combination overflowed; name what was set.
  return list([](const Given& g) { return g.pos->line == 0 && !g.pos->file.empty(); });
}

void apply_setting(Mechanism& mechanism, const std::string& setting, const std::string& origin) {
  const auto equals = setting.find('=');
  if (equals == std::string::npos || equals == 0)
    throw Error::invalid("set", q(setting) + " (" + origin + ") is not NAME=VALUE; e.g. L=0.4 or 2.theta=0.3");
  const std::string name = setting.substr(0, equals), text = setting.substr(equals + 1);
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || at != end)
    throw Error::invalid("set", q(text) + " (" + origin + ") is not a number" + lookalike_advice(text) +
                                    "; give NAME=VALUE with a number");
  set_value(mechanism, name, value, origin);
}

}  // namespace linkage
