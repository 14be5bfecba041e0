#include "lesson/canonical.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/number_format.hpp"

namespace linkage::lesson {
namespace {

// A string in double quotes with JSON's escapes.
void quote(std::string& out, std::string_view s) { out += nlohmann::json(s).dump(); }

void write(std::string& out, const toml::node& node, const std::vector<std::string_view>& skip) {
  if (const auto* t = node.as_table()) {
    std::vector<std::string_view> keys;
    for (const auto& [key, value] : *t)
      if (std::find(skip.begin(), skip.end(), key.str()) == skip.end()) keys.push_back(key.str());
    std::sort(keys.begin(), keys.end());
    out += '{';
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (i > 0) out += ',';
      quote(out, keys[i]);
      out += '=';
      write(out, *t->get(keys[i]), {});
    }
    out += '}';
  } else if (const auto* a = node.as_array()) {
    out += '[';
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i > 0) out += ',';
      write(out, *a->get(i), {});
    }
    out += ']';
  } else if (const auto* s = node.as_string()) {
    quote(out, s->get());
  } else if (const auto* i = node.as_integer()) {
    out += std::to_string(i->get());  // 3 and 3.0 differ in text, but not in effect: both re-render safely
  } else if (const auto* f = node.as_floating_point()) {
    out += format_roundtrip(f->get());
  } else if (const auto* b = node.as_boolean()) {
    out += b->get() ? "true" : "false";
  } else {
    out += "?";  // dates and times are not lesson values
  }
}

}  // namespace

std::string canonical_text(const toml::node& node, const std::vector<std::string_view>& skip) {
  std::string out;
  write(out, node, skip);
  return out;
}

std::string canonical_text(const Inputs& inputs) {
  std::string out;
  for (const InputKey& key : kInputKeys) {
    if (!out.empty()) out += ';';
    out += std::string(key.key) + "=" + format_roundtrip(inputs.value(key));
  }
  return out;
}

std::string content_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  std::array<char, 17> hex{};
  std::snprintf(hex.data(), hex.size(), "%016llx", static_cast<unsigned long long>(h));
  return {hex.data(), 16};
}

}  // namespace linkage::lesson
