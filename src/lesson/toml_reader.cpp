#include "lesson/toml_reader.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "model/name_match.hpp"

namespace linkage::lesson {
namespace {
// 'key', built by appending ("literal" + std::string trips GCC 12's -Wrestrict, bug 105329).
std::string q(std::string_view key) {
  std::string out(1, '\'');
  out += key;
  out += '\'';
  return out;
}
}  // namespace

std::string position(const std::string& file, const toml::source_region& where) {
  return file + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

TableReader::TableReader(const toml::table& table, std::string file, std::string context, std::span<const KeySpec> keys,
                         std::vector<std::string_view> extra_keys)
    : table_(table),
      file_(std::move(file)),
      context_(std::move(context)),
      keys_(keys),
      extra_keys_(std::move(extra_keys)) {}

void TableReader::reject_unknown_keys() const {
  std::vector<std::string> allowed;
  for (const KeySpec& k : keys_) allowed.emplace_back(k.name);
  allowed.insert(allowed.end(), extra_keys_.begin(), extra_keys_.end());
  const toml::key* first = nullptr;
  for (const auto& [key, value] : table_) {
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key.str();
    if (known) continue;
    const auto& b = key.source().begin;
    if (first == nullptr || b.line < first->source().begin.line ||
        (b.line == first->source().begin.line && b.column < first->source().begin.column))
      first = &key;
  }
  if (first == nullptr) return;
  throw Error::input(position(file_, first->source()) + ": " + context_ + ": unknown key '" +
                     std::string(first->str()) + "'" + did_you_mean(first->str(), allowed) +
                     "; valid keys: " + join_names(allowed));
}

bool TableReader::has(std::string_view key) const { return table_.contains(key); }

const toml::node* TableReader::node(std::string_view key) const { return table_.get(key); }

std::string TableReader::where(std::string_view key) const {
  const toml::node* n = node(key);
  return position(file_, n != nullptr ? n->source() : table_.source());
}

std::string TableReader::prefix(std::string_view key) const { return where(key) + ": " + context_ + ": "; }

void TableReader::fail(std::string_view key, const std::string& problem) const {
  throw Error::input(prefix(key) + problem);
}

void TableReader::require(std::string_view key) const {
  if (has(key)) return;
  throw Error::input(position(file_, table_.source()) + ": " + context_ + ": the key '" + std::string(key) +
                     "' is required");
}

std::optional<std::string> TableReader::string(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* s = n->as_string()) return s->get();
  fail(key, q(key) + " must be a string, got " + type_phrase(*n));
}

std::optional<double> TableReader::number(std::string_view key, double lo, double hi, std::string_view rule) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  double value = 0;
  if (const auto* f = n->as_floating_point())
    value = f->get();
  else if (const auto* i = n->as_integer())
    value = static_cast<double>(i->get());
  else
    fail(key, q(key) + " must be a number, got " + type_phrase(*n));
  if (!std::isfinite(value)) fail(key, q(key) + " must be a finite number");
  if (value < lo || value > hi)
    fail(key, q(key) + " = " + format_roundtrip(value) + " is out of range; " + std::string(rule));
  return value;
}

std::optional<std::int64_t> TableReader::integer(std::string_view key, std::int64_t lo, std::int64_t hi) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  const auto* i = n->as_integer();
  if (i == nullptr) fail(key, q(key) + " must be an integer, got " + type_phrase(*n));
  const std::int64_t value = i->get();
  if (value < lo || value > hi)
    fail(key, q(key) + " = " + std::to_string(value) + " is out of range; valid: " + std::to_string(lo) + " to " +
                  std::to_string(hi));
  return value;
}

std::optional<bool> TableReader::boolean(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* b = n->as_boolean()) return b->get();
  fail(key, q(key) + " must be true or false, got " + type_phrase(*n));
}

std::optional<std::vector<std::string>> TableReader::strings(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* s = n->as_string()) return std::vector<std::string>{s->get()};
  const auto* array = n->as_array();
  if (array == nullptr) fail(key, q(key) + " must be a string or a list of strings, got " + type_phrase(*n));
  std::vector<std::string> out;
  for (const toml::node& element : *array) {
    const auto* s = element.as_string();
    if (s == nullptr)
      throw Error::input(position(file_, element.source()) + ": " + context_ + ": every entry of '" + std::string(key) +
                         "' must be a string, got " + type_phrase(element));
    out.push_back(s->get());
  }
  return out;
}

std::optional<std::string> TableReader::choice(std::string_view key,
                                               const std::vector<std::string_view>& choices) const {
  auto value = string(key);
  if (!value) return value;
  for (std::string_view c : choices)
    if (c == *value) return value;
  const std::vector<std::string> names(choices.begin(), choices.end());
  fail(key,
       q(key) + " = '" + *value + "' is not valid" + did_you_mean(*value, names) + "; valid: " + join_names(names));
}

std::vector<const toml::table*> TableReader::tables(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return {};
  const auto* array = n->as_array();
  if (array == nullptr) fail(key, q(key) + " must be a list of tables, got " + type_phrase(*n));
  std::vector<const toml::table*> out;
  for (const toml::node& element : *array) {
    const auto* t = element.as_table();
    if (t == nullptr)
      throw Error::input(position(file_, element.source()) + ": " + context_ + ": every entry of '" + std::string(key) +
                         "' must be a table like { label = \"...\", ... }, got " + type_phrase(element));
    out.push_back(t);
  }
  return out;
}

}  // namespace linkage::lesson
