#include "bench/accuracy_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <system_error>

#include "bench/targets.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "render/plot.hpp"

namespace linkage::bench {
namespace fs = std::filesystem;
namespace {

std::string sig(double v, int digits = 3) { return std::isfinite(v) ? format_significant(v, digits) : "-"; }

std::string join_ints(const std::vector<int>& v) {
  std::string out;
  for (int x : v) {
    if (!out.empty()) out += ',';
    out += std::to_string(x);
  }
  return out;
}
std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& x : v) {
    if (!out.empty()) out += ',';
    out += x;
  }
  return out;
}

/// A CSV field: quoted when it holds a comma or a quote.
std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

std::string csv(const AccuracyResult& result) {
  std::ostringstream out;
  out << "scenario,case,method,library,rhs,kind,tolerance,step_count,time_s,time_min_s,cpu_time_s,repeats,rhs_"
         "evaluations,"
         "steps,rejected,error,energy_error,constraint_error,status\n";
  for (const ScenarioResult& s : result.scenarios)
    for (const AccuracyPoint& p : s.points) {
      out << s.scenario.name << ',' << p.case_id << ',' << p.method << ',' << csv_text(p.library) << ',' << name(p.rhs)
          << ',' << (p.adaptive ? "adaptive" : "fixed") << ',' << (p.adaptive ? csv_number(p.knob) : "") << ','
          << (p.adaptive ? "" : csv_number(p.knob)) << ',' << csv_number(p.timing.median_seconds) << ','
          << csv_number(p.timing.min_seconds) << ',' << csv_number(p.timing.cpu_median_seconds) << ','
          << p.timing.repeats << ',' << p.outcome.rhs_evaluations << ',' << p.outcome.steps << ','
          << (p.outcome.rejected ? std::to_string(*p.outcome.rejected) : "") << ',' << csv_number(p.error) << ','
          << csv_number(p.energy_error) << ',' << csv_number(p.constraint_error) << ','
          << csv_text(p.outcome.failure.empty() ? "ok" : p.outcome.failure) << '\n';
    }
  return out.str();
}

std::string reference_text(const ScenarioResult& s) {
  const Reference& r = s.reference;
  std::ostringstream out;
  out << "Reference: our DOP853 in long double at rtol = atol = " << sig(r.tolerance, 1) << " (" << r.steps
      << " steps); long double Dopri5 at " << sig(r.check_tolerance, 1) << " agrees to " << sig(r.check_difference, 2)
      << " (largest |difference| over x1, y1, theta1, theta2)";
  if (r.spec_difference)
    out << "; from the spec's decimal inputs it matches reference-example.json (25 digits) at t = 1, 2, 5, 10 s to "
        << sig(*r.spec_difference, 2);
  out << ". The reference has about **" << sig(r.digits, 3)
      << " significant digits** (relative to the largest of |x1|, |y1|, |theta|); computed in " << sig(r.seconds, 2)
      << " s.\n";
  return out.str();
}

std::string method_table(const ScenarioResult& s, Clock clock) {
  std::ostringstream out;
  out << "Times by " << (clock == Clock::wall ? "the steady clock" : "thread CPU time") << ".\n\n";
  out << "| curve | library | smallest error | time to 1e-6 | time to 1e-8 | time to 1e-10 | evaluations per ms |\n"
      << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Curve& c : curves(s)) {
    double best = std::numeric_limits<double>::infinity();
    double evals = 0, time = 0;
    for (const AccuracyPoint* p : c.points) {
      if (std::isfinite(p->error)) best = std::min(best, p->error);
      evals += static_cast<double>(p->outcome.rhs_evaluations);
      time += clock == Clock::wall ? p->timing.median_seconds : p->timing.cpu_median_seconds;
    }
    auto t = [&](double e) {
      const std::optional<double> v = time_to_error(c, e, clock);
      return v ? sig(*v * 1e3) + " ms" : std::string("-");
    };
    out << "| " << c.name() << " | " << c.library << " | " << sig(best, 2) << " | " << t(1e-6) << " | " << t(1e-8)
        << " | " << t(1e-10) << " | " << sig(time > 0 ? evals / time / 1e3 : 0.0) << " |\n";
  }
  return out.str();
}

std::string targets_table(const ScenarioResult& fast, const AccuracyResult& result) {
  std::ostringstream out;
  out << "| target | measured | goal | met | detail |\n| --- | --- | --- | --- | --- |\n";
  for (const TargetRow& row : evaluate_targets(fast, result.rhs, judging_clock(result), result.peers_not_built))
    out << "| " << row.target << " | " << row.measured << " | " << row.goal << " | "
        << (row.met ? (*row.met ? "yes" : "**no**") : "-") << " | " << row.note << " |\n";
  return out.str();
}

std::string rhs_row(const std::string& what, const PerCall& c) {
  return std::string("| ") + what + " | " + sig(c.wall_ns) + " | " + sig(c.cpu_ns) + " |\n";
}

}  // namespace

std::string peers_line(const AccuracyResult& result) {
  std::string ran, skipped;
  for (const PeerLibrary& peer : peer_libraries()) {
    const bool in_run = std::any_of(result.scenarios.begin(), result.scenarios.end(), [&](const ScenarioResult& s) {
      return std::any_of(s.points.begin(), s.points.end(),
                         [&](const AccuracyPoint& p) { return p.library == peer.library; });
    });
    const bool built = std::find(result.peers_not_built.begin(), result.peers_not_built.end(), peer.library) ==
                       result.peers_not_built.end();
    if (in_run) {
      ran += (ran.empty() ? "" : ", ") + peer.library;
    } else {
      skipped += (skipped.empty() ? "" : "; ") + (built ? peer.library + " not selected" : peer.not_built_note());
    }
  }
  return "Peers run: " + (ran.empty() ? std::string("none") : ran) + (skipped.empty() ? "" : "; " + skipped) + ".";
}

namespace {

std::string markdown(const AccuracyOptions& options, const AccuracyResult& result) {
  std::ostringstream out;
  out << "# Work-precision study\n\n"
      << "Reproduce with `" << accuracy_command(options) << "`.\n\n"
      << "Each point is one run to the scenario's end time, timed in-process with the steady clock"
      << (options.quick ? " once (--quick: timings are not meaningful)"
                        : ", repeated until 20 ms and reported as the median")
      << ". Error: the largest absolute error at the end over x1, y1 (m), theta1, theta2 (rad) against the "
         "reference. Adaptive methods run at rtol = atol = the tolerance; fixed-step ones at step counts doubling.\n\n"
      << "Machine: " << result.cores << " cores, 1-minute load average " << sig(result.load_average, 2)
      << " at the start. "
      << (result.busy() ? "The machine was busy (load above the cores): other processes shared the cores, so the "
                          "steady clock also counts their turns; the targets below are judged by this thread's CPU "
                          "time, with the steady-clock figure beside it.\n\n"
                        : "The targets are judged by the steady clock, with the thread CPU time beside it.\n\n")
      << peers_line(result) << "\n\n"
      << "## Right-hand side cost (ns per evaluation, this run)\n\n"
      << "| right-hand side | steady clock | thread CPU time |\n| --- | --- | --- |\n"
      << rhs_row("Case 3, closed form (ours, fastest)", result.rhs.case3_fast)
      << rhs_row("Case 3, general path (two-blocks.toml as simulate runs it, " + result.rhs.general_evaluator + ")",
                 result.rhs.case3_general)
      << rhs_row("Case 3, definition + block solve", result.rhs.case3_definition)
      << rhs_row("Case 3, user: hand-typed 4x4 + Eigen partialPivLu", result.rhs.case3_user)
      << rhs_row("Case 2, definition + block solve", result.rhs.case2)
      << rhs_row("Case 1, definition + block solve", result.rhs.case1)
      << rhs_row("Case 3 4x4 solve alone: block solve", result.rhs.solve_blocks)
      << rhs_row("Case 3 4x4 solve alone: Eigen partialPivLu", result.rhs.solve_lu)
      << rhs_row("4 uncoupled oscillators (the integrators' overhead is timed on it)", result.rhs.oscillators) << "\n";
  for (const ScenarioResult& s : result.scenarios) {
    out << "## Scenario `" << s.scenario.name << "`: " << s.scenario.description << ", " << sig(s.scenario.duration)
        << " s\n\n"
        << reference_text(s) << "\n"
        << "![work-precision](work_precision_" << s.scenario.name << ".svg)\n\n"
        << method_table(s, judging_clock(result)) << "\n";
    if (s.scenario.name == "fast") out << "### Targets (scenario fast)\n\n" << targets_table(s, result) << "\n";
    std::string failures;
    for (const AccuracyPoint& p : s.points)
      if (!p.outcome.failure.empty())
        failures += "- " + p.label + " (Case " + std::to_string(p.case_id) + ", " + name(p.rhs) + " RHS) at " +
                    (p.adaptive ? "tolerance " : "step count ") + sig(p.knob, 3) + ": " + p.outcome.failure + "\n";
    if (!failures.empty()) out << "Runs that did not reach the end:\n\n" << failures << "\n";
  }
  return out.str();
}

// --- plots --------------------------------------------------------------------------

int integrator_slot(const std::string& id) {
  static const char* order[] = {"euler",     "symplectic-euler", "rk4",          "dopri5",
                                "dop853",    "gauss-legendre",   "odeint-rkf78", "odeint-dopri5",
                                "odeint-bs", "cvode-adams",      "ida"};
  for (int i = 0; i < 11; ++i)
    if (id == order[i]) return i;
  return 0;
}

plot::Series series_of(const Curve& c) {
  plot::Series s;
  s.name = c.name();
  s.style = plot::Style::line_and_markers;
  for (const AccuracyPoint* p : c.points)
    if (std::isfinite(p->error) && p->error > 0) s.points.push_back({p->timing.median_seconds, p->error});
  const int slot = integrator_slot(c.method);
  s.color = static_cast<std::size_t>(slot) % plot::palette_size;
  if (c.ours()) {
    s.dash = c.case_id == 3   ? (c.rhs == RhsKind::definition ? plot::Dash::dash_dot
                                 : c.rhs == RhsKind::general  ? plot::Dash::dashed
                                                              : plot::Dash::solid)
             : c.case_id == 2 ? plot::Dash::dashed
                              : plot::Dash::dotted;
    s.marker = c.case_id == 3   ? (c.rhs == RhsKind::general ? plot::Marker::diamond : plot::Marker::circle)
               : c.case_id == 2 ? plot::Marker::square
                                : plot::Marker::triangle;
  } else {
    s.dash = c.rhs == RhsKind::user ? plot::Dash::dashed : plot::Dash::dotted;
    static const plot::Marker peer_markers[] = {plot::Marker::diamond, plot::Marker::cross, plot::Marker::plus,
                                                plot::Marker::square, plot::Marker::triangle};
    s.marker = peer_markers[(slot - 6) % 5];
  }
  return s;
}

void write_plot(const ScenarioResult& s, const std::vector<Curve>& chosen, const fs::path& stem,
                const std::string& title, AccuracyResult& result) {
  plot::Plot p;
  p.title = title;
  p.x = {"run time (s)", plot::Scale::log, std::nullopt, std::nullopt};
  p.y = {"error at t = " + sig(s.scenario.duration) + " s: max |Δ| of x_{1}, y_{1}, θ_{1}, θ_{2}", plot::Scale::log,
         std::nullopt, std::nullopt};
  for (const Curve& c : chosen) p.series.push_back(series_of(c));
  p.legend = plot::LegendPlace::outside_right;
  const plot::Canvas canvas{1250, 720, 14};
  for (const char* ext : {".png", ".svg"}) {
    fs::path target = stem;
    target += ext;
    (void)plot::write(p, target, canvas, "out");
    result.files.push_back(target);
  }
}

}  // namespace

std::string csv_number(double value) { return std::isfinite(value) ? format_roundtrip(value) : ""; }

Clock judging_clock(const AccuracyResult& result) { return result.busy() ? Clock::cpu : Clock::wall; }

void prepare_output_folder(const fs::path& dir, const std::string& origin) { ensure_directory(dir, origin); }

std::string accuracy_command(const AccuracyOptions& o) {
  std::string cmd = "linkage bench accuracy --scenario " + join(o.scenarios) + " --cases " + join_ints(o.cases);
  if (!o.integrators.empty()) cmd += " --integrators " + join(o.integrators);
  if (o.duration) cmd += " --duration " + format_roundtrip(*o.duration);
  cmd += " --out " + o.out.string();
  if (o.quick) cmd += " --quick";
  return cmd;
}

void write_accuracy_report(const AccuracyOptions& options, AccuracyResult& result) {
  const fs::path csv_path = options.out / "accuracy.csv";
  write_file_atomically(csv_path, csv(result), "out");
  result.files.push_back(csv_path);
  for (const ScenarioResult& s : result.scenarios) {
    const std::vector<Curve> all = curves(s);
    write_plot(s, all, options.out / ("work_precision_" + s.scenario.name),
               "Work-precision, scenario " + s.scenario.name, result);
    std::vector<Curve> case3;
    bool peers = false;
    for (const Curve& c : all)
      if (c.case_id == 3 || !c.ours()) {
        case3.push_back(c);
        peers = peers || !c.ours();
      }
    if (peers && case3.size() < all.size())
      write_plot(s, case3, options.out / ("work_precision_" + s.scenario.name + "_case3"),
                 "Work-precision, scenario " + s.scenario.name + ": Case 3 against the peers", result);
  }
  const fs::path md_path = options.out / "accuracy.md";
  write_file_atomically(md_path, markdown(options, result), "out");
  result.files.push_back(md_path);
}

}  // namespace linkage::bench
