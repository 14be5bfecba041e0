#pragma once
// A canonical text of a TOML value for content hashes: keys sorted, numbers in
// shortest round-trip form, strings quoted with escapes, so equal options give equal
// text and any change of a value changes it.
#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

#include "model/inputs.hpp"

namespace linkage::lesson {

/// The node as canonical text; keys of a table listed in `skip` are left out (only at
/// the top level).
[[nodiscard]] std::string canonical_text(const toml::node& node, const std::vector<std::string_view>& skip = {});

/// "L=0.3;w=0.1;...;theta2_dot=0.45" in round-trip form.
[[nodiscard]] std::string canonical_text(const Inputs& inputs);

/// 64-bit FNV-1a of `text`, as 16 lowercase hex digits.
[[nodiscard]] std::string content_hash(std::string_view text);

}  // namespace linkage::lesson
