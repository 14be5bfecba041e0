#include "report/json_layout.hpp"

#include <algorithm>

namespace linkage {

using nlohmann::ordered_json;

namespace {

bool all_scalars(const ordered_json& container) {
  return std::none_of(container.begin(), container.end(), [](const ordered_json& v) { return v.is_structured(); });
}

// The container on one line: [1, 2] or {"a": 1, "b": 2}.
std::string one_line(const ordered_json& container) {
  std::string out(1, container.is_array() ? '[' : '{');
  bool first = true;
  for (const auto& [key, value] : container.items()) {
    if (!first) out += ", ";
    first = false;
    if (container.is_object()) out += ordered_json(key).dump() + ": ";
    out += value.dump();
  }
  return out + (container.is_array() ? ']' : '}');
}

void layout(const ordered_json& value, std::size_t indent, std::size_t used, std::string& out) {
  if (!value.is_structured() || value.empty()) {
    out += value.dump();
    return;
  }
  if (all_scalars(value)) {
    const std::string line = one_line(value);
    if (value.is_array() || used + line.size() <= 80) {
      out += line;
      return;
    }
  }
  const std::string inner(indent + 2, ' ');
  out += value.is_array() ? "[\n" : "{\n";
  bool first = true;
  for (const auto& [key, item] : value.items()) {
    if (!first) out += ",\n";
    first = false;
    out += inner;
    std::size_t prefix = inner.size();
    if (value.is_object()) {
      const std::string name = ordered_json(key).dump() + ": ";
      out += name;
      prefix += name.size();
    }
    layout(item, indent + 2, prefix, out);
  }
  out += '\n';
  out.append(indent, ' ');
  out += value.is_array() ? ']' : '}';
}

}  // namespace

std::string json_layout(const ordered_json& value) {
  std::string out;
  layout(value, 0, 0, out);
  return out + "\n";
}

}  // namespace linkage
