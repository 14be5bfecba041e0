#include "pipeline/run_compare.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/number_format.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "pipeline/run_samples.hpp"

namespace linkage {
namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string column_header(CompareColumn column) {
  switch (column) {
    case CompareColumn::final_error:
      return "final error";
    case CompareColumn::energy_error:
      return "energy error";
    case CompareColumn::constraint_error:
      return "constraint error (m)";  // a slider's angle error is in rad, as small
    case CompareColumn::steps:
      return "steps";
    case CompareColumn::rejected:
      return "rejected";
    case CompareColumn::rhs_evaluations:
      return "RHS evaluations";
    case CompareColumn::run_time:
      return "run time (ms)";
  }
  return "";
}

double figure_value(const RunFigures& f, CompareColumn column) {
  switch (column) {
    case CompareColumn::final_error:
      return f.final_error;
    case CompareColumn::energy_error:
      return f.energy_error;
    case CompareColumn::constraint_error:
      return f.constraint_error;
    case CompareColumn::steps:
      return static_cast<double>(f.steps);
    case CompareColumn::rejected:
      return static_cast<double>(f.rejected);
    case CompareColumn::rhs_evaluations:
      return static_cast<double>(f.rhs_evaluations);
    case CompareColumn::run_time:
      return f.run_time * 1e3;
  }
  return 0;
}

std::string figure_text(const RunFigures& f, CompareColumn column) {
  switch (column) {
    case CompareColumn::steps:
      return std::to_string(f.steps);
    case CompareColumn::rejected:
      return std::to_string(f.rejected);
    case CompareColumn::rhs_evaluations:
      return std::to_string(f.rhs_evaluations);
    case CompareColumn::final_error:
    case CompareColumn::energy_error:
    case CompareColumn::constraint_error:
    case CompareColumn::run_time:
      return format_significant(figure_value(f, column), 3);
  }
  return format_significant(figure_value(f, column), 3);
}

// A compare row from a run's counters and its final error.
RunFigures run_figures(double error, const MechanismStats& stats) {
  RunFigures f;
  f.final_error = error;
  f.energy_error = stats.max_energy_error;
  f.constraint_error = stats.max_constraint_error;
  f.steps = stats.steps_accepted;
  f.rejected = stats.steps_rejected;
  f.rhs_evaluations = stats.rhs_evaluations;
  f.run_time = stats.wall_seconds;
  return f;
}

/// A mechanism run's figures: its final generalized coordinates against the reference run's,
/// its energy-balance and constraint errors over the samples, its cost.
RunFigures mechanism_figures(const Run& run, double every, std::map<std::string, std::vector<double>>& references,
                             std::vector<std::string>& warnings) {
  const std::vector<MechanismColumn> columns = mechanism_final_columns(*run.built->system);
  const MechanismSampledRun data = sample_mechanism_run(run, run_sample_times(run.options, every), columns);
  const std::string warning = mechanism_result_warning(run.options, data.stats);
  if (!warning.empty()) warnings.push_back("run '" + run.label + "': " + warning);
  std::string key = run.built->spec + ";" + format_roundtrip(run.options.duration);
  for (const std::string& setting : run.built->settings) key += ";" + setting;
  if (!references.count(key)) references[key] = mechanism_reference_final(run);
  double final = 0;
  for (std::size_t j = 0; j < columns.size(); ++j)
    final = std::max(final, std::fabs(data.columns[j].back() - references[key][j]));
  return run_figures(final, data.stats);
}

}  // namespace

Comparison compare_runs(const std::vector<Run>& runs, const std::vector<CompareColumn>& columns, double every) {
  Comparison out;
  std::map<std::string, std::vector<double>> references;  // by mechanism, settings and duration
  for (const Run& run : runs) out.figures.push_back(mechanism_figures(run, every, references, out.warnings));
  out.table.headers = {"run"};
  out.csv = "run";
  for (CompareColumn column : columns) {
    out.table.headers.push_back(column_header(column));
    out.csv += ',';
    out.csv += kCompareColumnNames[static_cast<std::size_t>(column)];
  }
  out.csv += "\n";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::vector<std::string> row{runs[r].label};
    out.csv += csv_field(runs[r].label);
    for (CompareColumn column : columns) {
      row.push_back(figure_text(out.figures[r], column));
      out.csv += ',';
      out.csv += format_roundtrip(figure_value(out.figures[r], column));
    }
    out.csv += "\n";
    out.table.rows.push_back(std::move(row));
  }
  return out;
}

plot::Plot cost_plot(const std::vector<Run>& runs, const std::vector<RunFigures>& figures, const std::string& title) {
  plot::Plot p;
  p.title = title.empty() ? "Accuracy against cost" : title + ": accuracy against cost";
  p.x.label = "right-hand-side evaluations";
  p.y.label = "final error (largest difference of a body's x, y, θ or a slider's travel)";
  p.x.scale = plot::Scale::log;
  p.y.scale = plot::Scale::log;
  std::vector<std::string> order;
  std::map<std::string, plot::Series> groups;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const std::string& key = runs[r].series;
    if (!groups.count(key)) {
      order.push_back(key);
      groups[key].name = key;
      groups[key].style = plot::Style::line_and_markers;
    }
    groups[key].points.push_back({static_cast<double>(figures[r].rhs_evaluations), figures[r].final_error});
  }
  for (const std::string& key : order) {
    plot::Series& series = groups[key];
    std::sort(series.points.begin(), series.points.end(),
              [](const plot::Point& a, const plot::Point& b) { return a.x < b.x; });
    p.series.push_back(std::move(series));
  }
  return p;
}

std::string final_error_note() {
  return "Final error: largest difference of the generalized coordinates (a floating body's x, y, θ, a pin's "
         "angle, a slider's travel) at the end from Case 3 by DOP853 at rtol = atol = " +
         format_significant(kReferenceTolerance, 1) +
         "; energy error: the energy balance E − E(0) − W relative to the energy scale.";
}

}  // namespace linkage
