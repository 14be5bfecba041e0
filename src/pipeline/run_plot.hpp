#pragma once
// A plot or compare step's figure as a plot description: its runs sampled, and with
// `difference` how far nearby runs part.
#include <cstddef>
#include <string>
#include <vector>

#include "pipeline/run.hpp"
#include "render/plot.hpp"

namespace linkage {

/// The figure's columns for every run, sampled (as simulate computes them): runs by
/// colour, series by dash, axes and legends in words and units; angles and angular
/// rates in `f.angles` (values and units, on both axes).
[[nodiscard]] plot::Plot figure_plot(const Figure& f, const std::vector<Run>& runs);

/// A plot step's `difference`: each run after the first drawn as abs(its value - the
/// first run's value) at the same sample, so exponential growth is a straight line on a
/// log axis. Replaces a plot of `labels.size()` runs x `per_run` series (run-major, as
/// figure_plot draws them, every run sampled at the same x) by the runs after the first,
/// each series named "label - first label"; the y axis label gets "difference in ".
/// Requires two runs or more and equal x samples.
[[nodiscard]] plot::Plot difference_from_first(plot::Plot plot, const std::vector<std::string>& labels,
                                               std::size_t per_run);

/// A plot step's picture: figure_plot, then difference_from_first when `f.difference`.
[[nodiscard]] plot::Plot runs_plot(const Figure& f, const std::vector<Run>& runs);

}  // namespace linkage
