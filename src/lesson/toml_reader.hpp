#pragma once
// Typed, position-aware reading of one TOML table of a lesson. Every error is one line
// "FILE:LINE:COLUMN: CONTEXT: problem; valid choices", pointing at the offending key
// or value, with the closest valid spelling for a typo.
#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/inputs_toml.hpp"

namespace linkage::lesson {

/// One allowed key of a table: its name, type, default and meaning (also the source of
/// lessons/README.md's tables, which a test keeps in step).
struct KeySpec {
  std::string_view name;
  std::string_view type;          // e.g. "string", "number", "list of strings"
  std::string_view default_text;  // e.g. "3", "(required)"
  std::string_view doc;
};

/// "file:line:column" of a node.
[[nodiscard]] std::string position(const std::string& file, const toml::source_region& where);

class TableReader {
 public:
  /// `context` names the table in messages, e.g. "step 4 (render)". `extra_keys` are
  /// allowed besides `keys` (e.g. the thirteen input names).
  TableReader(const toml::table& table, std::string file, std::string context, std::span<const KeySpec> keys,
              std::vector<std::string_view> extra_keys = {});

  /// Throws for the first key (in file order) that is not allowed, suggesting the
  /// closest allowed one and listing them all.
  void reject_unknown_keys() const;

  [[nodiscard]] bool has(std::string_view key) const;
  [[nodiscard]] const toml::node* node(std::string_view key) const;
  [[nodiscard]] const toml::table& table() const { return table_; }
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& context() const { return context_; }

  /// "file:line:column" of the key's value (of the table itself when absent).
  [[nodiscard]] std::string where(std::string_view key) const;
  /// "file:line:column: context: " for messages about `key`.
  [[nodiscard]] std::string prefix(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  /// Fails unless `key` is present.
  void require(std::string_view key) const;

  [[nodiscard]] std::optional<std::string> string(std::string_view key) const;
  /// A number (integer or float), finite, within [lo, hi]; `rule` words the range.
  [[nodiscard]] std::optional<double> number(std::string_view key, double lo, double hi, std::string_view rule) const;
  [[nodiscard]] std::optional<std::int64_t> integer(std::string_view key, std::int64_t lo, std::int64_t hi) const;
  [[nodiscard]] std::optional<bool> boolean(std::string_view key) const;
  /// A string or a list of strings.
  [[nodiscard]] std::optional<std::vector<std::string>> strings(std::string_view key) const;
  /// A string that must be one of `choices`.
  [[nodiscard]] std::optional<std::string> choice(std::string_view key,
                                                  const std::vector<std::string_view>& choices) const;
  /// The array of tables (inline or [[...]]) under `key`.
  [[nodiscard]] std::vector<const toml::table*> tables(std::string_view key) const;

 private:
  const toml::table& table_;
  std::string file_;
  std::string context_;
  std::span<const KeySpec> keys_;
  std::vector<std::string_view> extra_keys_;
};

using linkage::type_phrase;  // model/inputs_toml.hpp

}  // namespace linkage::lesson
