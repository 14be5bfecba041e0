#pragma once
// Typed, position-aware reading of one TOML table (a lesson's, a mechanism file's). Every
// error is one line "FILE:LINE:COLUMN: CONTEXT: problem; valid ...", pointing at the
// offending key, value or list entry, with the closest valid spelling for a typo.
#include <toml++/toml.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace linkage {

/// One allowed key of a table: its name, type and default, as a format's README lists
/// them (tests keep the README's rows in step; the README says what each means).
struct KeySpec {
  std::string_view name;
  std::string_view type;          // e.g. "string", "number", "list of strings"
  std::string_view default_text;  // e.g. "3", "(required)"
};

/// "file:line:column" for a source position.
[[nodiscard]] std::string source_position(const std::string& file, long line, long column);

/// "a string", "an integer", "a table", ... for "must be a number, got ..." messages.
[[nodiscard]] std::string type_phrase(const toml::node& node);

/// "file:line:column" of a node; a region toml++ did not record (line 0) is 1:1, the
/// file as a whole.
[[nodiscard]] std::string position(const std::string& file, const toml::source_region& where);

/// A canonical text of a TOML value for content hashes: keys sorted, numbers in shortest
/// round-trip form, strings quoted with escapes, so equal tables give equal text and any
/// change of a value changes it. Keys of a table listed in `skip` are left out (only at
/// the top level).
[[nodiscard]] std::string canonical_text(const toml::node& node, const std::vector<std::string_view>& skip = {});

class TableReader {
 public:
  /// `context` names the table in messages, e.g. "step 4 (render)" or "body '1'".
  /// `extra_keys` are allowed besides `keys` (e.g. the thirteen input names).
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
  /// Fails at `node` (a list entry, a nested value) in this table's context.
  [[noreturn]] void fail_at(const toml::node& node, const std::string& problem) const;
  /// Fails unless `key` is present; `example` (e.g. "[\"O\", \"A\"]") shows a value.
  void require(std::string_view key, std::string_view example = {}) const;

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
  /// A string or list of strings, each one of `choices`: their indices (empty when the
  /// key is absent). An error points at the offending entry.
  [[nodiscard]] std::vector<std::size_t> choice_list(std::string_view key,
                                                     const std::vector<std::string_view>& choices) const;
  /// The table under `key`, or null when absent.
  [[nodiscard]] const toml::table* subtable(std::string_view key) const;
  /// The array of tables (inline or [[...]]) under `key`; `written` shows how one is
  /// written in messages (e.g. "[[body]]").
  [[nodiscard]] std::vector<const toml::table*> tables(std::string_view key, std::string_view written = {}) const;

  /// The entries in file order (toml++ keeps them sorted by name).
  [[nodiscard]] std::vector<std::pair<const toml::key*, const toml::node*>> entries() const;
  /// The names of the keys `keep` accepts, in file order.
  [[nodiscard]] std::vector<std::string> keys_in_file_order(const std::function<bool(std::string_view)>& keep) const;

 private:
  const toml::table& table_;
  std::string file_;
  std::string context_;
  std::span<const KeySpec> keys_;
  std::vector<std::string_view> extra_keys_;
};

}  // namespace linkage
