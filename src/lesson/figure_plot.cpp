// A plot or compare step's figure: its runs sampled and put into a plot description,
// axes and legends in words and units, angles in the step's unit.
#include "lesson/figure_plot.hpp"

#include <algorithm>
#include <array>

#include "core/angle_unit.hpp"
#include "integrate/series.hpp"
#include "lesson/runs.hpp"
#include "render/panel.hpp"

namespace linkage::lesson {
namespace {

constexpr std::array<plot::Dash, 4> kDashes{plot::Dash::solid, plot::Dash::dashed, plot::Dash::dotted,
                                            plot::Dash::dash_dot};

// Run r's curves, one per y quantity (columns[0] is x, columns[k + 1] the k-th y), each
// scaled by its factor: named by the run, by the quantity, or by both when both vary.
void add_run_series(plot::Plot& p, std::size_t runs, std::size_t r, const std::string& label,
                    const std::vector<std::string>& y_names, const std::vector<std::vector<double>>& columns,
                    const std::vector<double>& factors) {
  for (std::size_t k = 0; k < y_names.size(); ++k) {
    plot::Series series;
    series.name = y_names.size() == 1 ? label : runs == 1 ? y_names[k] : label + ": " + y_names[k];
    series.color = r % plot::palette_size;
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

/// A series' axis label with its angles in `angles` ("θ_{1} (deg)").
std::string series_label(std::size_t i, AngleUnit angles) {
  return with_unit_markup(std::string(kSeries[i].label), angle_unit_text(kSeries[i].unit, angles));
}

std::string y_label(const std::vector<std::size_t>& y, AngleUnit angles) {
  if (y.size() == 1) return series_label(y.front(), angles);
  std::vector<std::string> labels, units;  // words, never the raw series names
  for (std::size_t i : y) {
    labels.emplace_back(kSeries[i].label);
    units.push_back(angle_unit_text(kSeries[i].unit, angles));
  }
  return shared_axis_label(labels, units);
}

/// A mechanism's columns for every run: axes and legends in words and units.
plot::Plot mechanism_plot(const Figure& f, const std::vector<Run>& runs) {
  plot::Plot p;
  p.title = f.title;
  p.x.label =
      with_unit_markup(column_words(*f.mechanism_x), angle_unit_text(column_unit_markup(*f.mechanism_x), f.angles));
  std::vector<std::string> labels, units;
  for (const MechanismColumn& c : f.mechanism_y) {
    labels.push_back(column_words(c));
    units.push_back(angle_unit_text(column_unit_markup(c), f.angles));
  }
  p.y.label = labels.size() == 1 ? with_unit_markup(labels[0], units[0]) : shared_axis_label(labels, units);
  p.x.scale = f.log_x ? plot::Scale::log : plot::Scale::linear;
  p.y.scale = f.log_y ? plot::Scale::log : plot::Scale::linear;
  std::vector<MechanismColumn> columns{*f.mechanism_x};
  columns.insert(columns.end(), f.mechanism_y.begin(), f.mechanism_y.end());
  std::vector<double> factors;  // 180/π for an angle plotted in degrees
  for (const MechanismColumn& c : columns) factors.push_back(angle_factor(c.unit, f.angles));
  p.x.degrees = angle_unit_text(columns.front().unit, f.angles) == "deg";
  p.y.degrees = std::all_of(f.mechanism_y.begin(), f.mechanism_y.end(),
                            [&](const MechanismColumn& c) { return angle_unit_text(c.unit, f.angles) == "deg"; });
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const MechanismSampledRun data = sample_mechanism_run(runs[r], run_sample_times(runs[r].options, f.every), columns);
    add_run_series(p, runs.size(), r, runs[r].label, labels, data.columns, factors);
  }
  return p;
}

}  // namespace

plot::Plot figure_plot(const Figure& f, const std::vector<Run>& runs) {
  if (f.mechanism_x) return mechanism_plot(f, runs);
  plot::Plot p;
  p.title = f.title;
  p.x.label = series_label(f.x, f.angles);
  p.y.label = y_label(f.y, f.angles);
  p.x.scale = f.log_x ? plot::Scale::log : plot::Scale::linear;
  p.y.scale = f.log_y ? plot::Scale::log : plot::Scale::linear;
  std::vector<std::size_t> columns{f.x};
  columns.insert(columns.end(), f.y.begin(), f.y.end());
  std::vector<double> factors;  // 180/π for an angle plotted in degrees
  for (std::size_t c : columns) factors.push_back(angle_factor(kSeries[c].unit, f.angles));
  p.x.degrees = angle_unit_text(kSeries[f.x].unit, f.angles) == "deg";
  p.y.degrees = std::all_of(f.y.begin(), f.y.end(),
                            [&](std::size_t i) { return angle_unit_text(kSeries[i].unit, f.angles) == "deg"; });
  std::vector<std::string> y_names;
  for (std::size_t i : f.y) y_names.emplace_back(kSeries[i].label);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const SampledRun data = sample_run(runs[r], f.every, columns);
    add_run_series(p, runs.size(), r, runs[r].label, y_names, data.columns, factors);
  }
  return p;
}

}  // namespace linkage::lesson
