#pragma once
// Files of `linkage bench accuracy`: accuracy.csv (every run), accuracy.md (reference,
// per-method summary, targets) and the log-log work-precision plots
// work_precision_<scenario>.{png,svg} (every curve) and, when Case 3 and peers ran,
// work_precision_<scenario>_case3.{png,svg} (Case 3 against the peers).
#include <filesystem>
#include <string>

#include "bench/accuracy.hpp"
#include "bench/targets.hpp"

namespace linkage::bench {

/// Creates `dir` if it is missing (its parent must exist); throws Error::input naming
/// `origin` when it cannot be used.
void prepare_output_folder(const std::filesystem::path& dir, const std::string& origin);

/// The command line that reproduces a run with these options.
[[nodiscard]] std::string accuracy_command(const AccuracyOptions& options);

/// Writes every file into options.out and appends their paths to result.files.
void write_accuracy_report(const AccuracyOptions& options, AccuracyResult& result);

/// "Peers run: Boost.Odeint; peer SUNDIALS (CVODE, IDA) not built: install ...": which
/// peer libraries ran, and why the others did not.
[[nodiscard]] std::string peers_line(const AccuracyResult& result);

/// The clock the targets are judged by: the thread's CPU time on a busy machine.
[[nodiscard]] Clock judging_clock(const AccuracyResult& result);

/// Formats a number for CSV: shortest round-trip text, empty for NaN.
[[nodiscard]] std::string csv_number(double value);

}  // namespace linkage::bench
