#pragma once
// What a --panel plots, by name: the homework's quantities (integrate/series.hpp, the
// names a lesson's plot step takes) and any mechanism's trajectory columns
// (columns/mechanism_columns.hpp), each with its words and unit for the axes.
#include <string>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "integrate/simulation.hpp"
#include "render/panel.hpp"
#include "scene/motion.hpp"

namespace linkage {

/// Error::invalid("panel", ...) naming the first unknown or repeated name and the valid ones.
void validate_homework_panel(const std::vector<std::string>& names);

/// The homework's panel over `motion`'s samples; `sim` answers the accelerations and pin
/// force (only when a chosen quantity needs them), `initial` is the state at t = 0.
[[nodiscard]] PanelData homework_panel(const std::vector<std::string>& names, Simulation& sim, const Motion& motion,
                                       const Params& params, const BodyState& initial, double t_end);

/// The chosen columns of a mechanism; Error::invalid("panel", ...) for an unknown name.
[[nodiscard]] std::vector<MechanismColumn> mechanism_panel_columns(const std::vector<MechanismColumn>& all,
                                                                   const std::vector<std::string>& names);

/// An empty panel for `columns` (words and units), its values to be appended.
[[nodiscard]] PanelData mechanism_panel(const std::vector<MechanismColumn>& columns, double t_end);

}  // namespace linkage
