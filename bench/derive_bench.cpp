#include "bench/derive_bench.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "bench/accuracy_report.hpp"
#include "bench/timing.hpp"
#include "core/atomic_file.hpp"
#include "core/number_format.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism_toml.hpp"
#include "model/spanning_tree.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"

namespace linkage::bench {
namespace {

const std::vector<CaseId> kCases{CaseId::maximal, CaseId::generalized, CaseId::reduced};

std::string sig(double v) { return std::isfinite(v) ? format_significant(v, 3) : "-"; }

ReportOptions text_options() {
  ReportOptions o;
  o.text_style = Style::unicode;
  return o;
}

std::string verdict(bool met) { return met ? "met" : "MISSED"; }

extern "C" char** environ;

// Wall time of one run of `binary` with `args`, its output to /dev/null: what a user
// waits for, start-up included. NaN when it does not run or fails.
double command_seconds(const std::string& binary, const std::vector<std::string>& args) {
  std::vector<std::string> argv_text = {binary};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return std::nan("");
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DeriveBenchResult run_derive_bench(const DeriveBenchOptions& options) {
  ensure_directory(options.out, "out");
  const double min_total = options.quick ? 0.02 : 0.5;
  const int max_repeats = options.quick ? 2 : 200;
  DeriveBenchResult result;
  std::size_t sink = 0;  // keeps the work observable

  for (const std::string& name : shipped_mechanism_names()) {
    const Mechanism mechanism = load_mechanism(name);
    DeriveRow row;
    row.mechanism = name;
    row.bodies = static_cast<int>(mechanism.bodies.size());
    row.joints = static_cast<int>(mechanism.joints.size());
    row.degrees_of_freedom = degrees_of_freedom(mechanism);
    const Timing derive = time_repeated(
        [&] {
          const sym::System system(mechanism);
          for (CaseId id : kCases) sink += derive_case(system, id).A.size();
        },
        min_total, max_repeats);
    const Timing solve =
        time_repeated([&] { sink += mechanism_text(work_out_mechanism(mechanism, kCases), text_options()).size(); },
                      min_total, max_repeats);
    row.derive_seconds = derive.median_seconds;
    row.solve_seconds = solve.median_seconds;
    row.repeats = derive.repeats;
    result.rows.push_back(row);
  }

  // The homework's solve as a user runs it, this build against --baseline (an earlier
  // build, e.g. the one with the closed-form printer), interleaved in one run so machine
  // load affects both alike.
  std::vector<double> ours, baseline;
  const int rounds = options.quick ? 2 : 15;
  for (int r = 0; r < rounds; ++r) {
    ours.push_back(command_seconds("/proc/self/exe", {"solve", "--unicode"}));
    if (!options.baseline.empty()) baseline.push_back(command_seconds(options.baseline, {"solve", "--unicode"}));
  }
  result.command_seconds = median(ours);
  result.baseline_command_seconds = options.baseline.empty() ? std::nan("") : median(baseline);
  const double ratio = result.command_seconds / result.baseline_command_seconds;
  const std::string ratio_text = options.baseline.empty() ? "not measured (no --baseline)"
                                 : std::isfinite(ratio)   ? sig(ratio) + "x"
                                                          : "not measured (the baseline did not run)";
  const std::string ratio_verdict = std::isfinite(ratio) ? verdict(ratio <= kMaxSolveRatio) : "-";

  double four_bar = std::nan("");
  for (const DeriveRow& row : result.rows)
    if (row.mechanism == "four-bar") four_bar = row.derive_seconds;

  std::ostringstream md, csv;
  md << "# Deriving the equations: time per mechanism\n\n";
  md << "`linkage bench derive" << (options.quick ? " --quick" : "")
     << "`: medians of repeated runs on one core; ratios measured in the same run.\n\n";
  md << "| target | measured | goal | verdict |\n| :-- | --: | --: | :-- |\n";
  md << "| homework `linkage solve` wall time, this build / baseline | " << ratio_text << " | <= " << kMaxSolveRatio
     << "x | " << ratio_verdict << " |\n";
  md << "| four-bar, all three cases derived | " << sig(1e3 * four_bar) << " ms | < " << 1e3 * kMaxFourBarDeriveSeconds
     << " ms | " << verdict(four_bar < kMaxFourBarDeriveSeconds) << " |\n\n";
  md << "| mechanism | bodies | joints | DOF | derive, ms | worked solution (text), ms |\n"
        "| :-- | --: | --: | --: | --: | --: |\n";
  csv << "mechanism,bodies,joints,dof,derive_s,solve_s,repeats\n";
  for (const DeriveRow& row : result.rows) {
    md << "| " << row.mechanism << " | " << row.bodies << " | " << row.joints << " | " << row.degrees_of_freedom
       << " | " << sig(1e3 * row.derive_seconds) << " | " << sig(1e3 * row.solve_seconds) << " |\n";
    csv << row.mechanism << ',' << row.bodies << ',' << row.joints << ',' << row.degrees_of_freedom << ','
        << csv_number(row.derive_seconds) << ',' << csv_number(row.solve_seconds) << ',' << row.repeats << '\n';
  }
  md << "\nHomework `linkage solve` (all cases, text), the whole command: this build "
     << sig(1e3 * result.command_seconds) << " ms";
  if (!options.baseline.empty())
    md << ", baseline `" << options.baseline << "` " << sig(1e3 * result.baseline_command_seconds) << " ms";
  md << ".\n";
  write_file_atomically(options.out / "derive.md", md.str(), "out");
  write_file_atomically(options.out / "derive.csv", csv.str(), "out");
  result.files = {options.out / "derive.md", options.out / "derive.csv"};

  result.lines.push_back("homework solve wall time " + sig(1e3 * result.command_seconds) +
                         " ms; against the baseline " + ratio_text + " (goal <= 1.5x) " + ratio_verdict);
  result.lines.push_back("four-bar, three cases derived: " + sig(1e3 * four_bar) + " ms (goal < 200 ms) " +
                         verdict(four_bar < kMaxFourBarDeriveSeconds));
  for (const DeriveRow& row : result.rows)
    result.lines.push_back("  " + row.mechanism + ": derive " + sig(1e3 * row.derive_seconds) + " ms, solve " +
                           sig(1e3 * row.solve_seconds) + " ms");
  if (sink == 0) result.lines.push_back("(nothing derived)");
  return result;
}

}  // namespace linkage::bench
