// A plot or compare step's figure: its runs sampled and put into a plot description,
// axes and legends in words and units, angles in the step's unit; and how far runs part.
#include "pipeline/run_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/angle_unit.hpp"
#include "core/error.hpp"
#include "pipeline/run_samples.hpp"
#include "render/panel.hpp"

namespace linkage {
namespace {

constexpr std::array<plot::Dash, 4> kDashes{plot::Dash::solid, plot::Dash::dashed, plot::Dash::dotted,
                                            plot::Dash::dash_dot};

// Run r's curves, one per y quantity (columns[0] is x, columns[k + 1] the k-th y), each
// scaled by its factor: named by the run, by the quantity, or by both when both vary;
// coloured by run, or by quantity when there is one run.
void add_run_series(plot::Plot& p, std::size_t runs, std::size_t r, const std::string& label,
                    const std::vector<std::string>& y_names, const std::vector<std::vector<double>>& columns,
                    const std::vector<double>& factors) {
  for (std::size_t k = 0; k < y_names.size(); ++k) {
    plot::Series series;
    series.name = y_names.size() == 1 ? label : runs == 1 ? y_names[k] : label + ": " + y_names[k];
    // One run: each quantity its own colour as well as its dash (four dashes read alike small).
    series.color = (runs == 1 ? k : r) % plot::palette_size;
    series.dash = kDashes[k % kDashes.size()];
    series.points.reserve(columns[0].size());
    for (std::size_t i = 0; i < columns[0].size(); ++i)
      series.points.push_back({factors[0] * columns[0][i], factors[k + 1] * columns[k + 1][i]});
    p.series.push_back(std::move(series));
  }
}

std::string with_unit_markup(const std::string& words, const std::string& unit) {
  return unit.empty() ? words : words + " (" + unit + ")";
}

}  // namespace

plot::Plot figure_plot(const Figure& f, const std::vector<Run>& runs) {
  plot::Plot p;
  p.title = f.title;
  p.x.label = with_unit_markup(column_words(f.x), angle_unit_text(column_unit_markup(f.x), f.angles));
  std::vector<std::string> labels, units;
  for (const MechanismColumn& c : f.y) {
    labels.push_back(column_words(c));
    units.push_back(angle_unit_text(column_unit_markup(c), f.angles));
  }
  p.y.label = labels.size() == 1 ? with_unit_markup(labels[0], units[0]) : shared_axis_label(labels, units);
  p.x.scale = f.log_x ? plot::Scale::log : plot::Scale::linear;
  p.y.scale = f.log_y ? plot::Scale::log : plot::Scale::linear;
  std::vector<MechanismColumn> columns{f.x};
  columns.insert(columns.end(), f.y.begin(), f.y.end());
  std::vector<double> factors;  // 180/π for an angle plotted in degrees
  for (const MechanismColumn& c : columns) factors.push_back(angle_factor(c.unit, f.angles));
  p.x.degrees = angle_unit_text(columns.front().unit, f.angles) == "deg";
  p.y.degrees = std::all_of(f.y.begin(), f.y.end(),
                            [&](const MechanismColumn& c) { return angle_unit_text(c.unit, f.angles) == "deg"; });
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const MechanismSampledRun data = sample_mechanism_run(runs[r], run_sample_times(runs[r].options, f.every), columns);
    add_run_series(p, runs.size(), r, runs[r].label, labels, data.columns, factors);
  }
  return p;
}

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

plot::Plot runs_plot(const Figure& f, const std::vector<Run>& runs) {
  plot::Plot p = figure_plot(f, runs);
  p.equal_scale = f.equal_axes;
  if (!f.difference) return p;
  std::vector<std::string> labels;
  for (const Run& run : runs) labels.push_back(run.label);
  const std::size_t per_run = p.series.size() / runs.size();
  return difference_from_first(std::move(p), labels, per_run);
}

}  // namespace linkage
