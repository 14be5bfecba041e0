#include "model/inputs.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
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
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string toml_type_name(const toml::node& node) {
  std::ostringstream name;
  name << node.type();
  const std::string type = name.str();
  return (std::string("aeiou").find(type.front()) != std::string::npos ? "an " : "a ") + type;
}

std::size_t index_of(const InputKey& key) { return static_cast<std::size_t>(&key - kInputKeys.data()); }
}  // namespace

std::optional<std::string_view> closest_input_key(std::string_view key) {
  std::optional<std::string_view> best;
  std::size_t best_distance = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (const auto& k : kInputKeys) {
    const std::size_t d = edit_distance(key, k.key);
    if (d < best_distance) {
      best_distance = d;
      best = k.key;
    }
  }
  return best;
}

std::string source_position(const std::string& file, long line, long column) {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string canonical_text(const Inputs& inputs) {
  std::string out;
  for (const InputKey& key : kInputKeys) {
    if (!out.empty()) out += ';';
    out += std::string(key.key) + "=" + format_roundtrip(inputs.value(key));
  }
  return out;
}

Inputs::Inputs() { origins_.fill("default"); }

double Inputs::value(const InputKey& key) const {
  return key.param != nullptr ? params_.*key.param : state_.*key.state;
}

const std::string& Inputs::origin(const InputKey& key) const { return origins_[index_of(key)]; }

void Inputs::set(const InputKey& key, double value, std::string origin) {
  if (!std::isfinite(value))
    throw Error::invalid(origin, std::string(key.key) + " = " + format_roundtrip(value) + " is not a finite number");
  if (key.param != nullptr)
    params_.*key.param = value;
  else
    state_.*key.state = value;
  origins_[index_of(key)] = std::move(origin);
}

std::string likely_causes(const Inputs& inputs) {
  std::string list;
  for (const InputKey& key : kInputKeys) {
    const double v = std::fabs(inputs.value(key));
    if (v >= 1e50 || (v > 0 && v <= 1e-50)) {
      list += list.empty() ? "" : ", ";
      list += std::string(key.key) + " = " + format_roundtrip(inputs.value(key)) + " (" + inputs.origin(key) + ")";
    }
  }
  if (!list.empty()) return list;
  // Nothing extreme on its own: the combination overflowed; name what was given.
  for (const InputKey& key : kInputKeys) {
    if (inputs.origin(key) == "default") continue;
    list += list.empty() ? "" : ", ";
    list += std::string(key.key) + " = " + format_roundtrip(inputs.value(key)) + " (" + inputs.origin(key) + ")";
  }
  return list;
}

void Inputs::validate() const {
  auto fail = [&](const char* key, const std::string& rule) {
    const InputKey& k = *find_input_key(key);
    // About the value's origin (a flag, a file position): the reader that recorded it.
    throw Error::invalid(origin(k), std::string(k.key) + " = " + format_roundtrip(value(k)) + " " +
                                        std::string(k.unit) + " is out of range; " + rule);
  };
  if (!(params_.L > 0)) fail("L", "the block length must be > 0");
  if (!(params_.w > 0)) fail("w", "the block width must be > 0");
  if (!(params_.m > 0)) fail("m", "the mass must be > 0");
  if (!(params_.g >= 0)) fail("g", "g must be >= 0 (gravity points along -y)");
  if (!(params_.b >= 0 && params_.b <= params_.L)) {
    // b was left at its default: the L given is what made it invalid.
    if (origin(*find_input_key("b")) == "default" && origin(*find_input_key("L")) != "default")
      fail("L", "the default b = " + format_roundtrip(params_.b) + " m must lie in [0, L] = [0, " +
                    format_roundtrip(params_.L) + "] m; give a smaller b too");
    fail("b", "b must lie in [0, L] = [0, " + format_roundtrip(params_.L) + "] m");
  }
}

void Inputs::apply_file(const std::filesystem::path& path) {
  const toml::table table = parse_toml_file(path.string(), "config");
  apply_toml(*this, table, path.string());
}

void apply_toml(Inputs& inputs, const toml::table& table, const std::string& file) {
  for (const auto& [name, node] : table) {
    const auto& where = node.source().begin;
    const std::string position = source_position(file, where.line, where.column);
    const InputKey* key = find_input_key(name.str());
    if (key == nullptr) {
      const auto& key_where = name.source().begin;
      std::string message =
          source_position(file, key_where.line, key_where.column) + ": unknown key '" + std::string(name.str()) + "'";
      if (auto close = closest_input_key(name.str())) message += " (did you mean '" + std::string(*close) + "'?)";
      throw Error::input(message + "; valid keys: " + input_key_list());
    }
    std::optional<double> number;
    if (const auto* f = node.as_floating_point()) number = f->get();
    if (const auto* i = node.as_integer()) number = static_cast<double>(i->get());
    if (!number)
      throw Error::input(position + ": " + std::string(key->key) + " must be a number in " + std::string(key->unit) +
                         ", got " + toml_type_name(node));
    inputs.set(*key, *number, position);
  }
}

namespace {

// toml++ builds the tables of a dotted key (a.b.c = 1, [a.b.c]) recursively, so a key of
// tens of thousands of parts overflows the stack. The offset of the first key run with
// more than kMaxNesting dots outside strings and comments, if any. (A value has one dot
// at most, so only a key, or broken TOML, gets that far.)
std::optional<std::size_t> overly_nested_key(std::string_view text) {
  constexpr std::size_t none = std::string_view::npos;
  std::size_t run = none;  // where the current run of key characters, dots and quoted parts began
  int dots = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      if (text.substr(i, 3) == std::string(3, c)) {  // a multi-line string: never part of a key
        std::size_t end = i + 3;
        while (end < text.size() && text.substr(end, 3) != std::string(3, c))
          end += c == '"' && text[end] == '\\' ? 2 : 1;
        i = std::min(end + 2, text.size());
        run = none;
        dots = 0;
        continue;
      }
      if (run == none) run = i;  // a quoted part of a key, or a string value
      for (++i; i < text.size() && text[i] != c && text[i] != '\n'; ++i)
        if (c == '"' && text[i] == '\\') ++i;
      if (i < text.size() && text[i] == '\n') --i;  // unclosed: the line end still ends the run
      continue;
    }
    if (c == '.') {
      if (run == none) run = i;
      if (++dots > kMaxNesting) return run;
      continue;
    }
    const bool key_character = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
    if (key_character && run == none) run = i;
    if (key_character || c == ' ' || c == '\t') continue;
    if (c == '#') i = std::min(text.find('\n', i), text.size());
    run = none;
    dots = 0;
  }
  return std::nullopt;
}

}  // namespace

toml::table parse_toml_file(const std::string& path, const std::string& origin) {
  require_regular_file(path, origin);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error::invalid(origin, "cannot read '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_toml_text(text.str(), path, origin);
}

toml::table parse_toml_text(std::string_view toml_text, const std::string& path, const std::string& origin) {
  if (const auto at = overly_nested_key(toml_text)) {
    long line = 1, column = 1;
    for (std::size_t i = 0; i < *at; ++i) {
      if (toml_text[i] == '\n') {
        ++line;
        column = 1;
      } else if ((static_cast<unsigned char>(toml_text[i]) & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
        ++column;
      }
    }
    throw Error::input(source_position(path, line, column) + ": the key is nested more than " +
                       std::to_string(kMaxNesting) + " levels deep (each '.' is a level)");
  }
  try {
    return toml::parse(toml_text, path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    if (where.line == 0) throw Error::invalid(origin, "cannot read '" + path + "': " + std::string(e.description()));
    throw Error::input(source_position(path, where.line, where.column) + ": " + std::string(e.description()));
  }
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
    default:
      return "nothing";
  }
}

}  // namespace linkage
