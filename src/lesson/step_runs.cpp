// The steps that run simulations: simulate (a summary and a trajectory), plot (series
// against time for several runs) and compare (a table of figures, and plots).
#include <algorithm>
#include <map>
#include <optional>

#include "core/atomic_file.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "lesson/figure_plot.hpp"
#include "lesson/plot_difference.hpp"
#include "lesson/runner_context.hpp"
#include "lesson/runs.hpp"
#include "model/inputs.hpp"
#include "render/plot.hpp"

namespace linkage::lesson {
namespace {

std::string method_text(const SimulationOptions& o) {
  const IntegratorInfo& i = info(o.integrator);
  std::string text = std::string(i.name) + (i.adaptive ? " (rtol " + format_significant(o.rtol, 3) + ", atol " +
                                                             format_significant(o.atol, 3) + ")"
                                                       : " (dt " + format_significant(o.dt, 3) + " s)");
  if (o.case_id == 1) text += ", stabilization " + std::string(name(o.stabilization));
  return text;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// --- simulate ------------------------------------------------------------------------

// The rows every run's summary opens with: case, method, simulated time, steps, right-hand sides.
template <class Stats>
ResultTable run_summary(const SimulationOptions& o, const Stats& st) {
  ResultTable t;
  t.headers = {"quantity", "value"};
  t.rows = {
      {"case", std::to_string(o.case_id)},
      {"method", method_text(o)},
      {"simulated time", format_significant(o.duration, 6) + " s"},
      {"steps", std::to_string(st.steps_accepted) + " accepted, " + std::to_string(st.steps_rejected) + " rejected"},
      {"right-hand sides", std::to_string(st.rhs_evaluations)},
  };
  return t;
}

ResultTable simulate_summary(const SimulateStep& s, const SimulationStats& st, const BodyState& end) {
  const SimulationOptions& o = s.run.options;
  ResultTable t = run_summary(o, st);
  t.rows.insert(t.rows.end(),
                {
                    {"largest energy error", format_significant(st.max_energy_error, 3) + " of the energy scale"},
                    {"largest constraint error", format_significant(st.max_constraint_error, 3) + " m"},
                    {"final x1, y1", format_significant(end.x1, 6) + " m, " + format_significant(end.y1, 6) + " m"},
                    {"final theta1, theta2",
                     format_significant(end.theta1, 6) + " rad, " + format_significant(end.theta2, 6) + " rad"},
                    {"run time", format_significant(st.wall_seconds * 1e3, 3) + " ms"},
                });
  return t;
}

/// "angle of body 2 (2.theta)" for a generalized coordinate, from its column's meaning.
std::string coordinate_words(const std::vector<MechanismColumn>& all, const std::string& key, std::string& unit) {
  for (const MechanismColumn& c : all)
    if (c.name == key) {
      unit = c.unit;
      std::string words = c.meaning;  // without a closing remark such as "(not wrapped)"
      if (!words.empty() && words.back() == ')') words.erase(words.rfind(" ("));
      return words + " (" + key + ")";
    }
  unit.clear();
  return key;
}

ResultTable mechanism_summary(const SimulateStep& s, const MechanismStats& st, const Eigen::VectorXd& end) {
  const SimulationOptions& o = s.run.options;
  const sym::System& system = *s.run.built->system;
  ResultTable t = run_summary(o, st);
  t.rows.insert(t.rows.begin(), {"mechanism", system.mechanism().name});
  t.rows.insert(t.rows.end(), {
                                  {"largest energy-balance error",
                                   format_significant(st.max_energy_error, 3) + " of the energy scale"},
                                  {"largest constraint error",
                                   format_significant(st.max_constraint_error, 3) + " m (rad for a slider's angle)"},
                              });
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  const auto& coordinates = system.coordinates();
  for (std::size_t i = 0; i < coordinates.size() && static_cast<Eigen::Index>(i) < end.size(); ++i) {
    std::string unit;
    const std::string words = coordinate_words(all, coordinates[i].coordinate.key, unit);
    t.rows.push_back({"final " + words,
                      format_significant(end[static_cast<Eigen::Index>(i)], 6) + (unit.empty() ? "" : " " + unit)});
  }
  t.rows.push_back({"run time", format_significant(st.wall_seconds * 1e3, 3) + " ms"});
  return t;
}

/// A mechanism's simulate step: the rows and trajectory of `linkage simulate --mechanism`.
nlohmann::json simulate_mechanism(const RunContext& c, const SimulateStep& s) {
  const Run& run = s.run;
  const std::vector<double> times = trajectory_times(run.options.duration, s.every);
  const MechanismSampledRun data = sample_mechanism_run(run, times, s.mechanism_columns);
  if (!s.trajectory.empty()) {
    std::string csv;
    for (std::size_t j = 0; j < s.mechanism_columns.size(); ++j) csv += (j ? "," : "") + s.mechanism_columns[j].name;
    csv += "\n";
    for (std::size_t k = 0; k < times.size(); ++k) {
      for (std::size_t j = 0; j < data.columns.size(); ++j) {
        if (j > 0) csv += ',';
        csv += format_roundtrip(data.columns[j][k]);
      }
      csv += "\n";
    }
    write_file_atomically(c.options.out_dir / s.trajectory, csv, "out");
  }
  nlohmann::json results = {{"table", to_json(mechanism_summary(s, data.stats, data.final_state))}};
  const std::string warning = mechanism_result_warning(run.options, data.stats);
  if (!warning.empty()) results["warnings"] = {warning};
  return results;
}

/// Runs a simulate step, writing its trajectory (if any) as `linkage simulate` would.
nlohmann::json simulate(const RunContext& c, const SimulateStep& s) {
  if (s.run.built) return simulate_mechanism(c, s);
  const Run& run = s.run;
  Simulation sim(run.inputs.params(), run.inputs.state(), run.options);
  const std::vector<double> times = sample_times(run.options.duration, s.every);
  std::optional<AtomicFile> file;
  if (!s.trajectory.empty()) {
    file.emplace(c.options.out_dir / s.trajectory, "out");
    std::string header;
    for (const Column column : s.columns) {
      if (!header.empty()) header += ',';
      header += info(column).name;
    }
    file->stream() << header << "\n";
  }
  std::vector<double> values;
  values.reserve(s.columns.size());
  std::string line;
  BodyState state;
  for (const double t : times) {
    throw_if_interrupted();
    state = sim.state_at(t);
    if (!file) continue;
    compute_row(sim, t, state, s.columns, values);
    line.clear();
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (i > 0) line += ',';
      line += format_roundtrip(values[i]);
    }
    file->stream() << line << "\n";
  }
  if (file) file->commit();
  nlohmann::json results = {{"table", to_json(simulate_summary(s, sim.stats(), state))}};
  const std::string warning = result_warning(run.options, run.inputs.params(), sim.stats());
  if (!warning.empty()) results["warnings"] = {warning};
  return results;
}

// --- plots ---------------------------------------------------------------------------

/// Writes `name`.png and `name`.svg. Points dropped from a log axis (exact zeros, e.g.
/// an error at t = 0) are expected; points that are not finite are worth a word.
void write_plot(const RunContext& c, const Step& step, const plot::Plot& p, const std::string& name, int width,
                int height) {
  plot::Canvas canvas;
  canvas.width = width;
  canvas.height = height;
  for (const char* ext : {".png", ".svg"}) {
    const plot::Report report = plot::write(p, c.options.out_dir / (name + ext), canvas, step.where);
    if (report.skipped_nonfinite > 0) c.status << "lesson: step " << step.number << ": " << report.warning() << "\n";
  }
}

// --- compare -------------------------------------------------------------------------

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
    default:
      return format_significant(figure_value(f, column), 3);
  }
}

/// Final error against right-hand-side evaluations, log-log, one curve per series.
plot::Plot cost_plot(const CompareStep& s, const std::vector<RunFigures>& figures) {
  plot::Plot p;
  p.title = s.title.empty() ? "Accuracy against cost" : s.title + ": accuracy against cost";
  p.x.label = "right-hand-side evaluations";
  p.y.label = s.runs.front().built ? "final error (largest difference of a body's x, y, θ or a slider's travel)"
                                   : "final error (largest of |Δx_{1}|, |Δy_{1}|, |Δθ_{1}|, |Δθ_{2}|)";
  p.x.scale = plot::Scale::log;
  p.y.scale = plot::Scale::log;
  std::vector<std::string> order;
  std::map<std::string, plot::Series> groups;
  for (std::size_t r = 0; r < s.runs.size(); ++r) {
    const std::string& key = s.runs[r].series;
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

// A compare row from a run's counters (the homework's or a mechanism's) and its final error.
template <class Stats>
RunFigures run_figures(double error, const Stats& stats) {
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

/// A mechanism run's figures: its final body positions against the reference run's,
/// its energy-balance and constraint errors over the samples, its cost.
RunFigures mechanism_figures(const Run& run, double every, std::map<std::string, std::vector<double>>& references,
                             nlohmann::json& warnings) {
  const std::vector<MechanismColumn> columns = mechanism_final_columns(*run.built->system);
  const MechanismSampledRun data = sample_mechanism_run(run, run_sample_times(run.options, every), columns);
  const std::string warning = mechanism_result_warning(run.options, data.stats);
  if (!warning.empty()) warnings.push_back("run '" + run.label + "': " + warning);
  std::string key = run.mechanism + ";" + format_roundtrip(run.options.duration);
  for (const std::string& setting : run.settings) key += ";" + setting;
  if (!references.count(key)) references[key] = mechanism_reference_final(run);
  double final = 0;
  for (std::size_t j = 0; j < columns.size(); ++j)
    final = std::max(final, std::fabs(data.columns[j].back() - references[key][j]));
  return run_figures(final, data.stats);
}

nlohmann::json compare(const RunContext& c, const Step& step, const CompareStep& s) {
  std::map<std::string, State> references;  // by inputs and duration
  std::map<std::string, std::vector<double>> mechanism_references;
  std::vector<RunFigures> figures;
  nlohmann::json warnings = nlohmann::json::array();
  for (const Run& run : s.runs) {
    if (run.built) {
      figures.push_back(mechanism_figures(run, s.every, mechanism_references, warnings));
      continue;
    }
    const SampledRun data = sample_run(run, s.every, {});
    const std::string warning = result_warning(run.options, run.inputs.params(), data.stats);
    if (!warning.empty()) warnings.push_back("run '" + run.label + "': " + warning);
    const std::string key = canonical_text(run.inputs) + ";" + format_roundtrip(run.options.duration);
    if (!references.count(key)) references[key] = reference_final_state(run);
    figures.push_back(run_figures(final_error(data.final_state, references[key]), data.stats));
  }
  ResultTable table;
  table.headers = {"run"};
  std::string csv = "run";
  for (CompareColumn column : s.columns) {
    table.headers.push_back(column_header(column));
    csv += ',';
    csv += kCompareColumnNames[static_cast<std::size_t>(column)];
  }
  csv += "\n";
  for (std::size_t r = 0; r < s.runs.size(); ++r) {
    std::vector<std::string> row{s.runs[r].label};
    csv += csv_field(s.runs[r].label);
    for (CompareColumn column : s.columns) {
      row.push_back(figure_text(figures[r], column));
      csv += ',';
      csv += format_roundtrip(figure_value(figures[r], column));
    }
    csv += "\n";
    table.rows.push_back(std::move(row));
  }
  write_file_atomically(c.options.out_dir / (s.out + ".csv"), csv, step.where);
  if (s.plot) write_plot(c, step, figure_plot(*s.plot, s.runs), s.out, s.width, s.height);
  if (s.cost_plot) write_plot(c, step, cost_plot(s, figures), s.out + "-cost", s.width, s.height);
  nlohmann::json results = {{"table", to_json(table)}};
  if (!warnings.empty()) results["warnings"] = warnings;
  return results;
}

}  // namespace

void run_simulate(RunContext& c, const Step& step, const SimulateStep& s) {
  const nlohmann::json results = s.trajectory.empty() ? simulate(c, s) : c.cached(step, [&] { return simulate(c, s); });
  c.warn(step, results);
  const ResultTable table = table_from_json(results.at("table"));
  c.both([&](Writer& w) { w.table(table, "Simulated with " + method_text(s.run.options) + "."); });
  if (!s.trajectory.empty())
    c.both([&](Writer& w) {
      w.figure(c.figure(s.trajectory, FigureRef::Kind::file, "the trajectory (CSV, as `linkage simulate`)"));
    });
}

void run_plot(RunContext& c, const Step& step, const PlotStep& s) {
  c.cached(step, [&] {
    plot::Plot p = figure_plot(s.figure, s.runs);
    if (s.figure.difference) {
      std::vector<std::string> labels;
      for (const Run& run : s.runs) labels.push_back(run.label);
      p = difference_from_first(std::move(p), labels, p.series.size() / s.runs.size());
    }
    write_plot(c, step, p, s.out, s.figure.width, s.figure.height);
    return nlohmann::json::object();
  });
  c.both([&](Writer& w) { w.figure(c.figure(s.out + ".png", FigureRef::Kind::image, s.caption)); });
}

void run_compare(RunContext& c, const Step& step, const CompareStep& s) {
  const nlohmann::json results = c.cached(step, [&] { return compare(c, step, s); });
  c.warn(step, results);
  const ResultTable table = table_from_json(results.at("table"));
  const std::string note =
      s.runs.front().built
          ? "Final error: largest difference of every body's x, y, θ and every slider's travel at the end from Case 3 "
            "by DOP853 at rtol = atol = " +
                format_significant(kReferenceTolerance, 1) +
                "; energy error: the energy balance E − E(0) − W relative to the energy scale."
          : "Final error: largest difference of x1, y1, θ1, θ2 at the end from DOP853 at rtol = atol = " +
                format_significant(kReferenceTolerance, 1) + "; energy error relative to the energy scale.";
  c.both([&](Writer& w) { w.table(table, s.caption.empty() ? note : s.caption + " " + note); });
  if (s.plot) c.both([&](Writer& w) { w.figure(c.figure(s.out + ".png", FigureRef::Kind::image, "")); });
  if (s.cost_plot) c.both([&](Writer& w) { w.figure(c.figure(s.out + "-cost.png", FigureRef::Kind::image, "")); });
  c.both([&](Writer& w) { w.figure(c.figure(s.out + ".csv", FigureRef::Kind::file, "the table (CSV)")); });
}

}  // namespace linkage::lesson
