#pragma once
// A plot or compare step's figure as a plot description (internal to the runner's files).
#include <vector>

#include "lesson/lesson.hpp"
#include "render/plot.hpp"

namespace linkage::lesson {

/// The figure's series (or a mechanism's columns) for every run, sampled: runs by
/// colour, series by dash, axes and legends in words and units; angles and angular
/// rates in `f.angles` (values and units, on both axes).
[[nodiscard]] plot::Plot figure_plot(const Figure& f, const std::vector<Run>& runs);

}  // namespace linkage::lesson
