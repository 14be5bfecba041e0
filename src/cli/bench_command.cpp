// `linkage bench`: measured speed and accuracy. `accuracy` is the work-precision study
// against a long double reference and the peer libraries (SUNDIALS, Boost.Odeint; each
// when the build found it),
// `stress` the numerical stability tests, `render` the rendering throughput. The
// studies live in bench/ (library linkage_bench); a build without it
// (-DLINKAGE_BUILD_BENCH=OFF) says so.
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "core/error.hpp"

#ifdef LINKAGE_WITH_BENCH
#include "bench/accuracy.hpp"
#include "bench/accuracy_report.hpp"
#include "bench/derive_bench.hpp"
#include "bench/mechanisms_bench.hpp"
#include "bench/render_bench.hpp"
#include "bench/stress.hpp"
#include "bench/targets.hpp"
#endif

namespace linkage::cli {
namespace {

#ifdef LINKAGE_WITH_BENCH

/// "a,b,c" -> {"a", "b", "c"}; empty items are an error naming `origin`.
std::vector<std::string> split_list(const std::string& text, const std::string& origin) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (item.empty())
      throw Error::input(origin + ": '" + text + "' has an empty item; give a comma-separated list");
    else
      out.push_back(item);
  if (out.empty()) throw Error::input(origin + ": empty list");
  return out;
}

struct AccuracyFlags {
  std::string mechanism;
  CLI::Option* scenario_option = nullptr;
  CLI::Option* integrators_option = nullptr;
  std::string scenario = "fast";
  std::string cases = "1,2,3";
  std::string integrators = "all";
  std::string duration;
  std::string out = "bench-accuracy";
  bool quick = false;
  bool quiet = false;
};

bench::AccuracyOptions accuracy_options(const AccuracyFlags& f) {
  bench::AccuracyOptions o;
  o.scenarios.clear();
  for (const std::string& s : split_list(f.scenario, "--scenario")) {
    if (s == "all") {
      for (const bench::Scenario& each : bench::scenarios()) o.scenarios.push_back(each.name);
    } else {
      o.scenarios.push_back(s);
    }
  }
  o.cases.clear();
  for (const std::string& c : split_list(f.cases, "--cases")) {
    if (c != "1" && c != "2" && c != "3") throw Error::input("--cases: '" + c + "' is not a case; valid: 1, 2, 3");
    o.cases.push_back(c[0] - '0');
  }
  if (f.integrators != "all") o.integrators = split_list(f.integrators, "--integrators");
  if (!f.duration.empty()) o.duration = parse_number(f.duration, "--duration", "s");
  o.out = f.out;
  o.quick = f.quick;
  o.quiet = f.quiet;
  return o;
}

void run_mechanism_accuracy(const AccuracyFlags& flags) {
  if (flags.scenario_option->count() > 0 || flags.integrators_option->count() > 0)
    throw Error::input("--scenario and --integrators are the homework's; with --mechanism every integrator runs");
  bench::MechanismAccuracyOptions o;
  o.mechanism = flags.mechanism;
  o.cases.clear();
  for (const std::string& c : split_list(flags.cases, "--cases")) {
    if (c != "1" && c != "2" && c != "3") throw Error::input("--cases: '" + c + "' is not a case; valid: 1, 2, 3");
    o.cases.push_back(c[0] - '0');
  }
  if (!flags.duration.empty()) {
    o.duration = parse_number(flags.duration, "--duration", "s");
    if (!(o.duration > 0 && o.duration <= 1000))
      throw Error::input("--duration: " + flags.duration + " s is out of range; valid: 0 < duration <= 1000 s");
  }
  o.out = flags.out;
  o.quick = flags.quick;
  o.quiet = flags.quiet;
  const bench::MechanismAccuracyResult result = bench::run_mechanism_accuracy(o);
  for (const std::string& line : result.lines) std::printf("%s\n", line.c_str());
  for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
}

void run_accuracy(const AccuracyFlags& flags) {
  if (!flags.mechanism.empty()) {
    run_mechanism_accuracy(flags);
    return;
  }
  const bench::AccuracyOptions options = accuracy_options(flags);
  bench::validate(options);
  // A named integrator of a missing peer is an error (validate); all of them: a note.
  if (options.integrators.empty())
    for (const bench::PeerLibrary& peer : bench::peer_libraries())
      if (!peer.built) std::fprintf(stderr, "linkage: note: %s\n", peer.not_built_note().c_str());
  const bench::AccuracyResult result = bench::run_accuracy(options);
  std::printf(
      "Right-hand side, ns per evaluation (thread CPU time): Case 3 closed form %.1f, Case 3 definition "
      "%.1f, Case 3 user (Eigen partialPivLu) %.1f, Case 2 %.1f, Case 1 %.1f, Case 3 general path %.1f (%s)\n",
      result.rhs.case3_fast.cpu_ns, result.rhs.case3_definition.cpu_ns, result.rhs.case3_user.cpu_ns,
      result.rhs.case2.cpu_ns, result.rhs.case1.cpu_ns, result.rhs.case3_general.cpu_ns,
      result.rhs.general_evaluator.c_str());
  if (result.busy())
    std::printf("The machine is busy (load %.1f on %u cores): targets judged by thread CPU time\n", result.load_average,
                result.cores);
  std::printf("%s\n", bench::peers_line(result).c_str());
  for (const bench::ScenarioResult& s : result.scenarios) {
    std::printf("Scenario %s (%g s): %zu runs; reference good to %.1f digits (DOP853 vs Dopri5 in long double: %.2g)\n",
                s.scenario.name.c_str(), s.scenario.duration, s.points.size(), s.reference.digits,
                s.reference.check_difference);
    if (s.scenario.name != "fast") continue;
    for (const bench::TargetRow& row :
         bench::evaluate_targets(s, result.rhs, bench::judging_clock(result), result.peers_not_built)) {
      std::string verdict = row.met ? (*row.met ? "met" : "MISSED") : "";
      if (row.note.rfind("not measured", 0) == 0) verdict = row.note;
      std::printf("  %-75s %10s  goal %-8s %s\n", row.target.c_str(), row.measured.c_str(), row.goal.c_str(),
                  verdict.c_str());
    }
  }
  for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
}

void add_accuracy(CLI::App* bench) {
  auto flags = std::make_shared<AccuracyFlags>();
  CLI::App* sub = bench->add_subcommand(
      "accuracy", "Work-precision study: run time against error for every case and integrator, ours and the peers'");
  sub->add_option("--mechanism", flags->mechanism,
                  "Any mechanism (a shipped name or a file): every integrator of ours in each case against a "
                  "reference at 1e-14 checked by Case 2 and Gauss-Legendre; writes accuracy-NAME.csv/.md/.png")
      ->type_name("NAME|FILE");
  flags->scenario_option =
      sub->add_option("--scenario", flags->scenario,
                      "Scenario(s), comma-separated: " + bench::scenario_names() + ", or all (default fast)")
          ->type_name("LIST");
  sub->add_option("--cases", flags->cases, "Cases to run, comma-separated (default 1,2,3)")->type_name("LIST");
  std::string ids;
  for (const std::string& id : bench::method_ids()) {
    if (!ids.empty()) ids += ", ";
    ids += id;
  }
  flags->integrators_option =
      sub->add_option("--integrators", flags->integrators, "Integrators, comma-separated, or all (default): " + ids)
          ->type_name("LIST");
  sub->add_option("--duration", flags->duration, "Simulated time in s (default: each scenario's own, 10 s mostly)")
      ->type_name("T");
  sub->add_option("--out", flags->out, "Folder for accuracy.csv, accuracy.md and the plots (default bench-accuracy)")
      ->type_name("DIR");
  sub->add_flag("--quick", flags->quick, "Few settings, one repeat each: checks the report, not the timings (CI)");
  sub->add_flag("--quiet", flags->quiet, "No progress line on stderr");
  add_runner(sub, [flags] { run_accuracy(*flags); });
}

struct StressFlags {
  std::string out = "bench-stress";
  bool quick = false;
  bool quiet = false;
};

void add_stress(CLI::App* bench) {
  auto flags = std::make_shared<StressFlags>();
  CLI::App* sub = bench->add_subcommand(
      "stress", "Numerical stability: long runs, largest stable steps, extreme parameters, Case 1 drift");
  sub->add_option("--out", flags->out, "Folder for stress.md, the CSV files and the plots (default bench-stress)")
      ->type_name("DIR");
  sub->add_flag("--quick", flags->quick, "Short runs, few bisection steps: checks the report, not the findings (CI)");
  sub->add_flag("--quiet", flags->quiet, "No progress line on stderr");
  add_runner(sub, [flags] {
    bench::StressOptions options;
    options.out = flags->out;
    options.quick = flags->quick;
    options.quiet = flags->quiet;
    const bench::StressSummary summary = bench::run_stress(options);
    for (const std::string& line : summary.lines) std::printf("%s\n", line.c_str());
    for (const auto& file : summary.files) std::printf("wrote %s\n", file.string().c_str());
  });
}

void add_render(CLI::App* bench) {
  auto flags = std::make_shared<bench::RenderBenchOptions>();
  CLI::App* sub = bench->add_subcommand(
      "render", "Rendering throughput: MP4 pipeline against encoding alone, PNG writer against Cairo's");
  sub->add_option("--out", flags->out, "Folder for render.csv and render.md (default bench-render)")->type_name("DIR");
  sub->add_flag("--quick", flags->quick, "Two small sizes, 2 s, one run each: checks the report, not the timings (CI)");
  sub->add_flag("--quiet", flags->quiet, "No progress line on stderr");
  add_runner(sub, [flags] {
    bench::RenderBenchOptions options = *flags;
    options.assets = assets_dir(LINKAGE_ASSETS_DIR);
    const bench::RenderBenchResult result = bench::run_render_bench(options);
    for (const std::string& line : bench::render_bench_lines(result)) std::printf("%s\n", line.c_str());
    for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
  });
}

void add_derive(CLI::App* bench) {
  auto flags = std::make_shared<bench::DeriveBenchOptions>();
  CLI::App* sub = bench->add_subcommand(
      "derive", "Symbolic derivation time per shipped mechanism, and the homework's solve against a baseline build");
  sub->add_option("--out", flags->out, "Folder for derive.csv and derive.md (default bench-derive)")->type_name("DIR");
  sub->add_flag("--quick", flags->quick, "One or two repeats: checks the report, not the timings (CI)");
  sub->add_option("--baseline", flags->baseline,
                  "Another linkage binary (an earlier build) whose `solve` this one's is timed against, "
                  "interleaved in the same run (default: none, the ratio is not measured)")
      ->type_name("BINARY")
      ->check(CLI::ExistingFile);
  add_runner(sub, [flags] {
    const bench::DeriveBenchResult result = bench::run_derive_bench(*flags);
    for (const std::string& line : result.lines) std::printf("%s\n", line.c_str());
    for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
  });
}

void add_mechanisms(CLI::App* bench) {
  auto flags = std::make_shared<bench::MechanismsBenchOptions>();
  CLI::App* sub = bench->add_subcommand(
      "mechanisms",
      "Any mechanism's motion: ns per right-hand side for every shipped mechanism and case on the evaluator and the "
      "compiled path, a pendulum chain of 2 to 64 links against MuJoCo, work against precision on the double "
      "pendulum against Odeint and MuJoCo");
  sub->add_option("--out", flags->out,
                  "Folder for mechanisms.csv, work-precision.csv, mechanisms.md and the plots (default "
                  "bench-mechanisms)")
      ->type_name("DIR");
  sub->add_flag("--quick", flags->quick,
                "Chains to 8 links, few settings, short batches: checks the report, not the timings (CI)");
  sub->add_flag("--quiet", flags->quiet, "No progress line on stderr");
  add_runner(sub, [flags] {
    const bench::MechanismsBenchResult result = bench::run_mechanisms_bench(*flags);
    for (const std::string& line : result.lines) std::printf("%s\n", line.c_str());
    for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
  });
}

#endif  // LINKAGE_WITH_BENCH

}  // namespace

void register_bench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Measure speed and accuracy: work-precision, stability, rendering, derivation, mechanisms");
#ifdef LINKAGE_WITH_BENCH
  bench->require_subcommand(1);
  add_accuracy(bench);
  add_stress(bench);
  add_render(bench);
  add_derive(bench);
  add_mechanisms(bench);
#else
  add_runner(bench, [] {
    throw Error::input("bench: this build has no benchmarks; configure with -DLINKAGE_BUILD_BENCH=ON");
  });
#endif
}

}  // namespace linkage::cli
