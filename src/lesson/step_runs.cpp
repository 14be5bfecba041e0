// The steps that run simulations: simulate (a summary and a trajectory), plot (series
// against time for several runs) and compare (a table of figures, and plots). What they
// compute is pipeline's; here: the cache, the files and the writers.
#include "core/atomic_file.hpp"
#include "core/deriving.hpp"
#include "lesson/runner_context.hpp"
#include "pipeline/run_compare.hpp"
#include "pipeline/run_plot.hpp"
#include "pipeline/run_samples.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/simulate_rows.hpp"
#include "render/plot.hpp"

namespace linkage::lesson {
namespace {

/// Runs a simulate step, writing its trajectory (if any) as `linkage simulate` would.
nlohmann::json simulate(const RunContext& c, const SimulateStep& s) {
  const Run& run = s.run;
  const TrajectoryRows rows(run.options.duration, s.every);
  std::string csv;
  const auto add_row = [&csv](double, const std::vector<double>& values) { csv += joined_values(values, ",") + "\n"; };
  nlohmann::json results;
  Deriving deriving;
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  deriving.done();
  csv = joined_names(written_columns(s.mechanism_columns, AngleUnit::rad).names) + "\n";
  const Eigen::VectorXd end =
      mechanism_trajectory(sim, run.options.case_id, rows, s.mechanism_columns, AngleUnit::rad, add_row);
  results["table"] = to_json(mechanism_summary(run, sim.stats(), end));
  const std::string warning = mechanism_result_warning(run.options, sim.stats());
  if (!warning.empty()) results["warnings"] = {warning};
  if (!s.trajectory.empty()) write_file_atomically(c.options.out_dir / s.trajectory, csv, "out");
  return results;
}

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

nlohmann::json compare(const RunContext& c, const Step& step, const CompareStep& s) {
  const Comparison comparison = compare_runs(s.runs, s.columns, s.every);
  write_file_atomically(c.options.out_dir / (s.out + ".csv"), comparison.csv, step.where);
  if (s.plot) write_plot(c, step, figure_plot(*s.plot, s.runs), s.out, s.width, s.height);
  if (s.cost_plot)
    write_plot(c, step, cost_plot(s.runs, comparison.figures, s.title), s.out + "-cost", s.width, s.height);
  nlohmann::json results = {{"table", to_json(comparison.table)}};
  if (!comparison.warnings.empty()) results["warnings"] = comparison.warnings;
  return results;
}

}  // namespace

void run_simulate(RunContext& c, const Step& step, const SimulateStep& s) {
  const nlohmann::json results = s.trajectory.empty() ? simulate(c, s) : c.cached(step, [&] { return simulate(c, s); });
  c.warn(step, results);
  const ResultTable table = table_from_json(results.at("table"));
  // The summary's method: the integrator's, or kinematic analysis when the drivers fix the motion.
  std::string method = method_text(s.run.options);
  for (const auto& row : table.rows)
    if (row.size() == 2 && row[0] == "method") method = row[1];
  c.both([&](Writer& w) { w.table(table, "Simulated with " + method + "."); });
  if (!s.trajectory.empty())
    c.both([&](Writer& w) {
      w.figure(c.figure(s.trajectory, FigureRef::Kind::file, "the trajectory (CSV, as `linkage simulate`)"));
    });
}

void run_plot(RunContext& c, const Step& step, const PlotStep& s) {
  c.cached(step, [&] {
    write_plot(c, step, runs_plot(s.figure, s.runs), s.out, s.figure.width, s.figure.height);
    return nlohmann::json::object();
  });
  c.both([&](Writer& w) { w.figure(c.figure(s.out + ".png", FigureRef::Kind::image, s.caption)); });
}

void run_compare(RunContext& c, const Step& step, const CompareStep& s) {
  const nlohmann::json results = c.cached(step, [&] { return compare(c, step, s); });
  c.warn(step, results);
  const ResultTable table = table_from_json(results.at("table"));
  const std::string note = final_error_note();
  c.both([&](Writer& w) { w.table(table, s.caption.empty() ? note : s.caption + " " + note); });
  if (s.plot) c.both([&](Writer& w) { w.figure(c.figure(s.out + ".png", FigureRef::Kind::image, "")); });
  if (s.cost_plot) c.both([&](Writer& w) { w.figure(c.figure(s.out + "-cost.png", FigureRef::Kind::image, "")); });
  c.both([&](Writer& w) { w.figure(c.figure(s.out + ".csv", FigureRef::Kind::file, "the table (CSV)")); });
}

}  // namespace linkage::lesson
