#pragma once
// A plot step's `difference`: how far nearby runs part. Each run after the first is drawn
// as abs(its value - the first run's value) at the same sample, so exponential growth
// is a straight line on a log axis.
#include <cstddef>
#include <string>
#include <vector>

#include "render/plot.hpp"

namespace linkage::lesson {

/// Replaces a plot of `labels.size()` runs x `per_run` series (run-major, as the plot step
/// draws them, every run sampled at the same x) by the runs after the first, each series
/// the absolute difference from the first run's, named "label - first label"; the y axis
/// label gets "difference in ". Requires two runs or more and equal x samples.
[[nodiscard]] plot::Plot difference_from_first(plot::Plot plot, const std::vector<std::string>& labels,
                                               std::size_t per_run);

}  // namespace linkage::lesson
