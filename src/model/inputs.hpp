#pragma once
// The thirteen inputs of the linkage (five parameters, eight state values), where each
// came from, and their validation. One table drives the CLI flags, the TOML keys, the
// lesson `set` step and the error messages, so they cannot disagree.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace linkage {

struct InputKey {
  std::string_view key;              // TOML key and JSON name, e.g. "theta1_dot"
  std::string_view unit;             // e.g. "rad/s"
  std::string_view description;      // e.g. "angular velocity of block 1"
  bool parameter = false;            // one of the five parameters, else a state value
  double default_value = 0;          // the spec's example, as mechanisms/two-blocks.toml has it
  std::string_view mechanism_key{};  // the same value in mechanisms/two-blocks.toml, e.g. "2.theta_dot"
};

inline constexpr std::array<InputKey, 13> kInputKeys{{
    {"L", "m", "block length", true, 0.3, "L"},
    {"w", "m", "block width", true, 0.1, "w"},
    {"b", "m", "pin distance from one end of each block, in [0, L]", true, 0.04, "b"},
    {"m", "kg", "mass of each block", true, 0.1, "m"},
    {"g", "m/s^2", "gravitational acceleration along -y", true, 9.81, "g"},
    {"x1", "m", "x of block 1's centre of mass", false, 1, "1.x"},
    {"y1", "m", "y of block 1's centre of mass", false, 2, "1.y"},
    {"theta1", "rad", "angle of block 1 from +x", false, 0.1, "1.theta"},
    {"theta2", "rad", "angle of block 2 from +x", false, 0.2, "2.theta"},
    {"x1_dot", "m/s", "x velocity of block 1's centre of mass", false, 0.15, "1.x_dot"},
    {"y1_dot", "m/s", "y velocity of block 1's centre of mass", false, 0.25, "1.y_dot"},
    {"theta1_dot", "rad/s", "angular velocity of block 1", false, 0.35, "1.theta_dot"},
    {"theta2_dot", "rad/s", "angular velocity of block 2", false, 0.45, "2.theta_dot"},
}};

/// The input named `key` (TOML spelling), or nullptr.
[[nodiscard]] const InputKey* find_input_key(std::string_view key);
/// "L, w, b, m, g, x1, ..." for error messages.
[[nodiscard]] std::string input_key_list();
/// The valid key closest to a misspelt one (edit distance), if any is close.
[[nodiscard]] std::optional<std::string_view> closest_input_key(std::string_view key);

/// Parameters and state together with where each value came from ("default", a flag,
/// "run.toml:3:5"), so errors can name the source.
class Inputs {
 public:
  Inputs();
  [[nodiscard]] double value(const InputKey& key) const;
  [[nodiscard]] const std::string& origin(const InputKey& key) const;

  /// Sets one value; throws Error::input if it is not finite.
  void set(const InputKey& key, double value, std::string origin);
  /// Loads a TOML config file of inputs.
  void apply_file(const std::filesystem::path& path);

  /// Checks the ranges (m > 0, L > 0, w > 0, 0 <= b <= L, 0 <= g finite); throws
  /// Error::input naming the first bad value, its origin and the valid range.
  void validate() const;

 private:
  std::array<double, kInputKeys.size()> values_;
  std::array<std::string, kInputKeys.size()> origins_;
};

/// "L=0.3;w=0.1;...;theta2_dot=0.45" in round-trip form (for content hashes).
[[nodiscard]] std::string canonical_text(const Inputs& inputs);

}  // namespace linkage
