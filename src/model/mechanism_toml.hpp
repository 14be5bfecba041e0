#pragma once
// Reading a mechanism file (mechanisms/README.md is the format): every structural mistake
// is one line "FILE:LINE:COLUMN: TABLE: what is wrong; valid ..." thrown as Error::input,
// worded by toml/toml_table.hpp as a lesson file's errors are.
// Expressions are kept as text; the symbolic layer parses them and checks their values.
#include <cmath>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/mechanism.hpp"

namespace linkage {

/// Reads a mechanism from TOML text; `source_name` is the file name the positions name.
/// Calls validate_initial.
[[nodiscard]] Mechanism read_mechanism(std::string_view toml_text, const std::string& source_name);
/// Reads a mechanism file (a regular file; otherwise Error::invalid("mechanism", ...)).
[[nodiscard]] Mechanism read_mechanism_file(const std::filesystem::path& path);
/// A shipped mechanism by NAME (no '/' and no ".toml": built into the program), or else a
/// file path.
[[nodiscard]] Mechanism load_mechanism(const std::string& name_or_file);
/// Whether load_mechanism reads `name_or_file` as a file (it has a '/' or ends in .toml)
/// rather than a shipped mechanism's name.
[[nodiscard]] bool is_mechanism_file(std::string_view name_or_file);
/// The mechanism a command runs without --mechanism: the homework, two-blocks.toml.
inline constexpr const char* kDefaultMechanism = "two-blocks";
/// The default mechanism at its named inputs (the homework's flags, --config): every value
/// not at its default is set there with its origin, so the general derivation takes them.
class Inputs;
[[nodiscard]] Mechanism default_mechanism(const Inputs& inputs);
/// The shipped mechanisms' names, sorted.
[[nodiscard]] std::vector<std::string> shipped_mechanism_names();

/// Checks [initial] against the spanning tree: every key a generalized coordinate or
/// rate, every coordinate given (rates default to 0), `independent` naming coordinates.
void validate_initial(const Mechanism& mechanism);

/// `--set NAME=VALUE`: a parameter ("L") or an initial coordinate or rate ("2.theta",
/// "1.x_dot", "slider.s"); `origin` says where the setting came from. Throws
/// A parameter's or initial value's magnitude: 0 or a normal double. A subnormal one
/// (5e-324) has lost its digits already and trapped in CLN's arithmetic; a huge one is
/// refused where it overflows, naming it (likely_causes).
inline constexpr const char* kMagnitudeRange =
    "0 or a magnitude of at least 2.2250738585072014e-308 (double's normal range)";
[[nodiscard]] inline bool in_magnitude_range(double v) {
  return v == 0 || !(std::fabs(v) < std::numeric_limits<double>::min());
}

/// Error::invalid("set", ...) for an unknown name or a value that is not finite or out of range.
void set_value(Mechanism& mechanism, const std::string& name, double value, const std::string& origin);
/// The same from "NAME=VALUE" text (a --set flag, a lesson's `set` list); Error::invalid
/// ("set", ...) naming `origin` when the text is not NAME=NUMBER.
void apply_setting(Mechanism& mechanism, const std::string& setting, const std::string& origin);

/// For a number that overflowed: the parameters and initial values far outside physical
/// sizes (|v| >= 1e50 or <= 1e-50), else every value set from outside the file, each
/// with where it came from ("L = 1e+200 (--L)", "m = 2 (pendulum.toml:7:5)"); empty
/// when there is none of either.
[[nodiscard]] std::string likely_causes(const Mechanism& mechanism);

/// One key of a mechanism file: the table it belongs to, its name, type, default and
/// meaning. The reader accepts exactly these and mechanisms/README.md documents them.
struct MechanismKey {
  std::string_view table;  // "top level", "[[body]]", "[initial.BODY]", ...
  std::string_view name;
  std::string_view type;
  std::string_view default_text;
  std::string_view doc;
};
[[nodiscard]] std::span<const MechanismKey> mechanism_keys();

}  // namespace linkage
