#pragma once
// What a --panel plots, by name: a mechanism's trajectory columns
// (columns/mechanism_columns.hpp), each with its words and unit for the axes.
#include <string>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "render/panel.hpp"

namespace linkage {

/// The chosen columns of a mechanism, each named or defined (NAME=EXPRESSION over `all`
/// and `system`'s parameters); Error::invalid("panel", ...) for an unknown name.
[[nodiscard]] std::vector<MechanismColumn> mechanism_panel_columns(const std::vector<MechanismColumn>& all,
                                                                   const std::vector<std::string>& names,
                                                                   const sym::System* system = nullptr);

/// An empty panel for `columns` (words and units), its values to be appended.
[[nodiscard]] PanelData mechanism_panel(const std::vector<MechanismColumn>& columns, double t_end);

}  // namespace linkage
