#pragma once
// A compare step's numbers: each run's final error against a reference run, its energy
// and constraint errors and its cost, as a table, a CSV text and a cost plot.
#include <cstdint>
#include <string>
#include <vector>

#include "core/result_table.hpp"
#include "pipeline/run.hpp"
#include "render/plot.hpp"

namespace linkage {

/// The figures of one run in a compare table.
struct RunFigures {
  double final_error = 0;       // largest |error| of a body's x, y, theta or a slider's travel at the end
  double energy_error = 0;      // largest energy-balance error over the samples, of the energy scale
  double constraint_error = 0;  // largest |C| over the samples, m (rad for a slider's angle)
  std::int64_t steps = 0, rejected = 0, rhs_evaluations = 0;
  double run_time = 0;  // s
};

/// Runs compared: their figures (in the runs' order), the table and CSV of `columns`,
/// and a warning "run 'LABEL': ..." for each run whose numbers do not describe the motion.
struct Comparison {
  std::vector<RunFigures> figures;
  std::vector<std::string> warnings;
  ResultTable table;  // headers in words, figures to 3 significant digits
  std::string csv;    // the column names, then round-trip numbers
};

/// Runs every run (sampling its errors every `every` s) and the reference of each
/// distinct start and duration (see run_samples.hpp), once.
[[nodiscard]] Comparison compare_runs(const std::vector<Run>& runs, const std::vector<CompareColumn>& columns,
                                      double every);

/// Final error against right-hand-side evaluations, log-log, one curve per series of
/// runs; titled "`title`: accuracy against cost".
[[nodiscard]] plot::Plot cost_plot(const std::vector<Run>& runs, const std::vector<RunFigures>& figures,
                                   const std::string& title);

/// What the final and energy errors measure, for the table's caption.
[[nodiscard]] std::string final_error_note();

}  // namespace linkage
