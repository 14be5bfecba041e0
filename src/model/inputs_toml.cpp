#include "model/inputs_toml.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "core/character_text.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "toml/toml_table.hpp"

namespace linkage {

void apply_toml(Inputs& inputs, const toml::table& table, const std::string& file, const std::string& context) {
  std::vector<std::string_view> names;
  for (const InputKey& key : kInputKeys) names.push_back(key.key);
  const TableReader reader(table, file, context, {}, names);
  reader.reject_unknown_keys();
  for (const auto& [name, node] : reader.entries()) {
    const InputKey& key = *find_input_key(name->str());
    if (!node->is_number()) {
      std::string problem(1, '\'');  // appended: "literal" + std::string trips GCC 12's -Wrestrict
      problem += key.key;
      problem += "' must be a number in ";
      problem += key.unit;
      problem += ", got " + type_phrase(*node);
      reader.fail(key.key, problem);
    }
    const double value =
        *reader.number(key.key, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), "");
    inputs.set(key, value, reader.where(key.key));
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

/// The byte at `line`:`column` (both from 1; columns count UTF-8 characters), or npos.
std::size_t byte_offset(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t at = 0;
  for (std::size_t l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string_view::npos) return at;
    ++at;
  }
  for (std::size_t c = 1; at < text.size(); ++at)
    if ((static_cast<unsigned char>(text[at]) & 0xC0) != 0x80 && c++ == column) return at;
  return std::string_view::npos;
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
    const std::size_t at = byte_offset(toml_text, where.line, where.column);
    throw Error::input(source_position(path, where.line, where.column) + ": " + std::string(e.description()) +
                       (at == std::string_view::npos ? "" : lookalike_advice(toml_text, at)));
  }
}

}  // namespace linkage
