#include "lesson/plot_difference.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace linkage::lesson {

plot::Plot difference_from_first(plot::Plot plot, const std::vector<std::string>& labels, std::size_t per_run) {
  const std::size_t runs = labels.size();
  if (runs < 2 || per_run == 0 || plot.series.size() != runs * per_run)
    throw Error::invalid("difference", "needs two runs or more, each with the same series");
  std::vector<plot::Series> differences;
  for (std::size_t r = 1; r < runs; ++r)
    for (std::size_t k = 0; k < per_run; ++k) {
      const plot::Series& reference = plot.series[k];
      plot::Series series = plot.series[r * per_run + k];
      const std::size_t n = std::min(series.points.size(), reference.points.size());
      series.points.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        if (series.points[i].x != reference.points[i].x)
          throw Error::invalid("difference", "run '" + labels[r] + "' is sampled at other times than run '" +
                                                 labels[0] + "'; give the runs the same step and duration");
        series.points[i].y = std::abs(series.points[i].y - reference.points[i].y);
      }
      // "θ₁ + 1e-6 − θ₁" for one series; with several, the series' own name follows.
      std::string name = labels[r];
      name += " \u2212 ";
      name += labels[0];
      if (per_run > 1) {
        std::string own = series.name;
        const std::size_t colon = own.rfind(": ");
        if (colon != std::string::npos) own.erase(0, colon + 2);
        name += ": ";
        name += own;
      }
      series.name = name;
      series.color = (r - 1) % plot::palette_size;
      differences.push_back(std::move(series));
    }
  plot.series = std::move(differences);
  std::string label = "difference in ";
  label += plot.y.label;
  plot.y.label = label;
  return plot;
}

}  // namespace linkage::lesson
