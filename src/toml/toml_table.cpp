#include "toml/toml_table.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/character_text.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"

namespace linkage {

std::string source_position(const std::string& file, long line, long column) {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string type_phrase(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      return "nothing";
  }
  return "nothing";
}

namespace {
// 'key', built by appending ("literal" + std::string trips GCC 12's -Wrestrict, bug 105329).
std::string q(std::string_view key) {
  std::string out(1, '\'');
  out += key;
  out += '\'';
  return out;
}

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

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
    out += std::to_string(i->get());  // 3 and 3.0 both print 3: one value, one text
  } else if (const auto* f = node.as_floating_point()) {
    out += format_roundtrip(f->get());
  } else if (const auto* b = node.as_boolean()) {
    out += b->get() ? "true" : "false";
  } else {
    out += "?";  // dates and times are no values of ours
  }
}
}  // namespace

std::string position(const std::string& file, const toml::source_region& where) {
  if (where.begin.line == 0) return source_position(file, 1, 1);
  return source_position(file, static_cast<long>(where.begin.line), static_cast<long>(where.begin.column));
}

std::string canonical_text(const toml::node& node, const std::vector<std::string_view>& skip) {
  std::string out;
  write(out, node, skip);
  return out;
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
  for (const auto& [key, value] : entries()) {
    if (std::find(allowed.begin(), allowed.end(), key->str()) != allowed.end()) continue;
    throw Error::input(position(file_, key->source()) + ": " + context_ + ": unknown key " + q(key->str()) +
                       did_you_mean(key->str(), allowed) + "; valid keys: " + join_names(allowed));
  }
}

bool TableReader::has(std::string_view key) const { return table_.contains(key); }

const toml::node* TableReader::node(std::string_view key) const { return table_.get(key); }

std::string TableReader::where(std::string_view key) const {
  const toml::node* n = node(key);
  return position(file_, n != nullptr ? n->source() : table_.source());
}

std::string TableReader::prefix(std::string_view key) const { return where(key) + ": " + context_ + ": "; }

// A value echoed in `problem` may hold a NUL (TOML's \u0000): written \0, or the message
// would end there.
void TableReader::fail(std::string_view key, const std::string& problem) const {
  throw Error::input(prefix(key) + visible_nul(problem));
}

void TableReader::fail_at(const toml::node& node, const std::string& problem) const {
  throw Error::input(position(file_, node.source()) + ": " + context_ + ": " + visible_nul(problem));
}

void TableReader::require(std::string_view key, std::string_view example) const {
  if (has(key)) return;
  std::string problem = "the key " + q(key) + " is required";
  if (!example.empty()) problem += ", e.g. " + std::string(example);
  fail_at(table_, problem);
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
  if (!std::isfinite(value)) fail(key, q(key) + " = " + format_roundtrip(value) + " is not a finite number");
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
    if (s == nullptr) fail_at(element, "every entry of " + q(key) + " must be a string, got " + type_phrase(element));
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
       q(key) + " = " + q(*value) + " is not valid" + did_you_mean(*value, names) + "; valid: " + join_names(names));
}

std::vector<std::size_t> TableReader::choice_list(std::string_view key,
                                                  const std::vector<std::string_view>& choices) const {
  std::vector<std::size_t> out;
  const auto values = strings(key);  // type-checks
  if (!values) return out;
  const auto* array = node(key)->as_array();
  for (std::size_t i = 0; i < values->size(); ++i) {
    const std::string& v = (*values)[i];
    const auto it = std::find(choices.begin(), choices.end(), v);
    if (it != choices.end()) {
      out.push_back(static_cast<std::size_t>(it - choices.begin()));
      continue;
    }
    const std::vector<std::string> names(choices.begin(), choices.end());
    fail_at(array != nullptr ? *array->get(i) : *node(key),
            q(v) + " in " + q(key) + " is not valid" + did_you_mean(v, names) + "; valid: " + join_names(names));
  }
  return out;
}

const toml::table* TableReader::subtable(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return nullptr;
  if (const auto* t = n->as_table()) return t;
  fail(key, q(key) + " must be a table, got " + type_phrase(*n));
}

std::vector<const toml::table*> TableReader::tables(std::string_view key, std::string_view written) const {
  const toml::node* n = node(key);
  if (n == nullptr) return {};
  const auto* array = n->as_array();
  const std::string how = written.empty() ? std::string() : ", each written " + std::string(written);
  if (array == nullptr) fail(key, q(key) + " must be a list of tables" + how + ", got " + type_phrase(*n));
  std::vector<const toml::table*> out;
  for (const toml::node& element : *array) {
    const auto* t = element.as_table();
    if (t == nullptr)
      fail_at(element, "every entry of " + q(key) + " must be a table" + how + ", got " + type_phrase(element));
    out.push_back(t);
  }
  return out;
}

std::vector<std::pair<const toml::key*, const toml::node*>> TableReader::entries() const {
  std::vector<std::pair<const toml::key*, const toml::node*>> out;
  for (const auto& [key, value] : table_) out.emplace_back(&key, &value);
  // std::sort (keys of a table stand at distinct places; the name breaks a tie of unrecorded
  // places): std::stable_sort's temporary buffer trips AddressSanitizer's alloc-dealloc
  // check with GCC 12's libstdc++.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const auto &pa = a.first->source().begin, &pb = b.first->source().begin;
    if (before(pa, pb) || before(pb, pa)) return before(pa, pb);
    return a.first->str() < b.first->str();
  });
  return out;
}

std::vector<std::string> TableReader::keys_in_file_order(const std::function<bool(std::string_view)>& keep) const {
  std::vector<std::string> out;
  for (const auto& [key, value] : entries())
    if (keep(key->str())) out.emplace_back(key->str());
  return out;
}

}  // namespace linkage
