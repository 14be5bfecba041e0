#include "bench/stress.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <sstream>

#include "bench/accuracy_report.hpp"
#include "bench/closed_form/case1.hpp"
#include "bench/closed_form/case2.hpp"
#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/formulation.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "bench/closed_form/simulation.hpp"
#include "bench/scenarios.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "core/progress.hpp"
#include "render/plot.hpp"

namespace linkage::bench {
namespace fs = std::filesystem;
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string sig(double v, int digits = 3) { return std::isfinite(v) ? format_significant(v, digits) : "-"; }

// --- tracks: one simulation sampled over time -----------------------------------------

/// Kinetic energy relative to the centre of mass. Uniform gravity moves only the centre
/// of mass, so this is conserved on its own, and its error is not swamped by the free
/// fall's growing kinetic and potential energy (y1 falls 4.9e8 m in 10^4 s).
double internal_energy(const Params& p, const BodyState& b) {
  const double vx = (b.x1_dot + b.x2_dot) / 2, vy = (b.y1_dot + b.y2_dot) / 2;
  return invariants(p, b).kinetic_energy - p.m * (vx * vx + vy * vy);
}

struct Sample {
  double t = 0;
  double energy_error = 0;           // |E - E0| / energy_scale (as `simulate` reports it)
  double internal_energy_error = 0;  // |E_int - E_int0| / E_int0
  double constraint_error = 0;       // |C|, m
};

struct Track {
  std::string name;  // legend text
  SimulationOptions options;
  std::vector<Sample> samples;
  SimulationStats stats;
  std::string failure;  // why the run stopped early, if it did
};

std::vector<double> log_times(double first, double last, int count) {
  std::vector<double> t;
  for (int i = 0; i < count; ++i) t.push_back(first * std::pow(last / first, static_cast<double>(i) / (count - 1)));
  t.back() = last;
  return t;
}

Track run_track(const Scenario& s, const SimulationOptions& options, const std::vector<double>& times,
                std::string name) {
  Track track{std::move(name), options, {}, {}, {}};
  const BodyState b0 = body_state(s.params, s.initial);
  const double e0 = invariants(s.params, b0).energy, i0 = internal_energy(s.params, b0);
  Simulation sim(s.params, s.initial, options);
  for (const double t : times) {
    throw_if_interrupted();
    BodyState b;
    try {
      b = sim.state_at(t);
    } catch (const Error& e) {
      if (e.code() != ExitCode::diverged) throw;
      track.failure = e.what();
      break;
    }
    track.samples.push_back({t, std::fabs(invariants(s.params, b).energy - e0) / energy_scale(s.params, b),
                             std::fabs(internal_energy(s.params, b) - i0) / i0,
                             constraint_error(s.params, b).position.norm()});
  }
  track.stats = sim.stats();
  return track;
}

SimulationOptions options_for(int case_id, IntegratorKind kind, double duration, double dt, double tol) {
  SimulationOptions o;
  o.case_id = case_id;
  o.integrator = kind;
  o.duration = duration;
  o.dt = dt;
  o.rtol = o.atol = tol;
  return o;
}

// --- stable step --------------------------------------------------------------------

struct StableStep {
  int case_id = 3;
  IntegratorKind integrator{};
  double largest_stable = kNaN;  // s
  double smallest_unstable = kNaN;
  std::string unstable_because;
};

/// A run is stable when it reaches the end with every sample finite and the internal
/// energy within 10 % of its start.
bool stable(const Scenario& s, int case_id, IntegratorKind kind, double dt, std::string& why) {
  std::vector<double> times;
  for (double t = 0.1; t < s.duration; t += 0.1) times.push_back(t);
  times.push_back(s.duration);
  const Track track = run_track(s, options_for(case_id, kind, s.duration, dt, 1e-8), times, "");
  if (!track.failure.empty()) {
    why = track.failure.substr(0, track.failure.find(';'));
    return false;
  }
  for (const Sample& x : track.samples)
    if (!(x.internal_energy_error <= 0.1)) {
      why = "internal energy off by more than 10 % at t = " + sig(x.t) + " s";
      return false;
    }
  return true;
}

StableStep find_stable_step(const Scenario& s, int case_id, IntegratorKind kind, int bisections) {
  StableStep out{case_id, kind, kNaN, kNaN, {}};
  std::string why;
  double lo = 1e-3, hi = 1e-3;
  if (stable(s, case_id, kind, lo, why)) {
    for (hi = 2e-3; hi <= 1.0 && stable(s, case_id, kind, hi, why); hi *= 2) lo = hi;
    if (hi > 1.0) return {case_id, kind, lo, kNaN, "stable up to 1 s"};
  } else {
    for (lo = 5e-4; lo >= 1e-6 && !stable(s, case_id, kind, lo, why); lo /= 2) hi = lo;
    if (lo < 1e-6) return {case_id, kind, kNaN, hi, why};
  }
  for (int i = 0; i < bisections; ++i) {
    const double mid = std::sqrt(lo * hi);
    std::string mid_why;
    if (stable(s, case_id, kind, mid, mid_why))
      lo = mid;
    else
      hi = mid, why = mid_why;
  }
  (void)stable(s, case_id, kind, hi, out.unstable_because);
  out.largest_stable = lo;
  out.smallest_unstable = hi;
  return out;
}

// --- extremes -----------------------------------------------------------------------

struct Variant {
  std::string what;  // e.g. "m = 1e6 kg"
  Params params;
  State state;
};

std::vector<Variant> variants(bool quick) {
  const Scenario& base = find_scenario("example", "stress");
  std::vector<Variant> out;
  const std::vector<double> masses =
      quick ? std::vector<double>{1e-6, 1e6} : std::vector<double>{1e-6, 1e-3, 1, 1e3, 1e6};
  for (const double m : masses) {
    Variant v{"m = " + sig(m) + " kg", base.params, base.initial};
    v.params.m = m;
    out.push_back(v);
  }
  const std::vector<double> ds =
      quick ? std::vector<double>{0.5, 1e-6} : std::vector<double>{0.5, 1e-1, 1e-2, 1e-4, 1e-6};
  for (const double d : ds) {
    Variant v{"D = " + sig(d) + " L", base.params, base.initial};
    v.params.b = v.params.L / 2 - d * v.params.L;
    out.push_back(v);
  }
  const std::vector<double> ws = quick ? std::vector<double>{1e-4} : std::vector<double>{1e-2, 1e-3, 1e-4};
  for (const double w : ws) {
    Variant v{"w = " + sig(w) + " L", base.params, base.initial};
    v.params.w = w * v.params.L;
    out.push_back(v);
  }
  const std::vector<double> spins = quick ? std::vector<double>{1e4} : std::vector<double>{1, 1e2, 1e3, 1e4};
  for (const double spin : spins) {
    Variant v{"theta1' = " + sig(spin) + ", theta2' = " + sig(-1.75 * spin) + " rad/s", base.params, base.initial};
    v.state.theta1_dot = spin;
    v.state.theta2_dot = -1.75 * spin;
    out.push_back(v);
  }
  return out;
}

struct ExtremeRow {
  std::string what;
  int case_id = 3;
  double condition = 0;         // 2-norm condition number of A
  double condition_scaled = 0;  // of A with each row divided by its largest entry
  double block_error = 0;       // our block solve against a long double solve of the same A, B
  double lu_error = 0;          // Eigen partialPivLu (double) against the same
  double truth_error = 0;       // accelerations against the long double closed form
  std::string tool;             // what `linkage solve` does
};

/// Largest error relative to the largest reference value within each kind of unknown
/// (linear accelerations, angular accelerations, forces): the kinds have different units.
template <class Case, class V, class R>
double grouped_error(const V& q, const R& ref) {
  double worst = 0;
  for (int kind = 0; kind < 3; ++kind) {
    long double size = 0, err = 0;
    for (int i = 0; i < Case::size; ++i) {
      const Unknown u = Case::unknowns[static_cast<std::size_t>(i)];
      const int k = (u == Unknown::F_x || u == Unknown::F_y)                   ? 2
                    : (u == Unknown::theta1_ddot || u == Unknown::theta2_ddot) ? 1
                                                                               : 0;
      if (k != kind) continue;
      size = std::max(size, std::fabs(static_cast<long double>(ref[i])));
      err = std::max(err, std::fabs(static_cast<long double>(q[i]) - static_cast<long double>(ref[i])));
    }
    if (size > 0)
      worst = std::max(worst, static_cast<double>(err / size));
    else if (err > 0)
      worst = std::numeric_limits<double>::infinity();
  }
  return worst;
}

template <class Case>
ExtremeRow extreme_row(const Variant& v) {
  ExtremeRow row;
  row.what = v.what;
  row.case_id = Case::id;
  const State& s = v.state;
  const LinearSystem<Case> sys = assemble<Case>(make_env(v.params, s.theta1, s.theta2, s.theta1_dot, s.theta2_dot));
  const Eigen::JacobiSVD<Mat<Case::size>> svd(sys.A);
  row.condition = svd.singularValues()[0] / svd.singularValues()[Case::size - 1];
  Mat<Case::size> scaled = sys.A;
  for (int r = 0; r < Case::size; ++r) scaled.row(r) /= scaled.row(r).cwiseAbs().maxCoeff();
  const Eigen::JacobiSVD<Mat<Case::size>> svd_scaled(scaled);
  row.condition_scaled = svd_scaled.singularValues()[0] / svd_scaled.singularValues()[Case::size - 1];

  using LMat = Eigen::Matrix<long double, Case::size, Case::size>;
  using LVec = Eigen::Matrix<long double, Case::size, 1>;
  const LMat A = sys.A.template cast<long double>();
  const LVec reference = A.fullPivLu().solve(sys.B.template cast<long double>());
  Vec<Case::size> q;
  row.block_error = solve_blocks<Case>(sys.A, sys.B, q) ? grouped_error<Case>(q, reference) : kNaN;
  const Eigen::Matrix<double, Case::size, Case::size> dense = sys.A;
  const Vec<Case::size> lu = dense.partialPivLu().solve(sys.B);
  row.lu_error = grouped_error<Case>(lu, reference);

  // End to end: the accelerations against the closed form evaluated in long double.
  long double truth[4];
  Case3Fast<long double>(v.params).accelerations(s.theta1, s.theta2, s.theta1_dot, s.theta2_dot, truth);
  const Unknown names[4] = {Unknown::x1_ddot, Unknown::y1_ddot, Unknown::theta1_ddot, Unknown::theta2_ddot};
  double worst = 0;
  for (int group = 0; group < 2; ++group) {
    long double size = 0, err = 0;
    for (int j = 2 * group; j < 2 * group + 2; ++j) {
      const auto it = std::find(Case::unknowns.begin(), Case::unknowns.end(), names[j]);
      const long double got = static_cast<long double>(q[static_cast<int>(it - Case::unknowns.begin())]);
      size = std::max(size, std::fabs(truth[j]));
      err = std::max(err, std::fabs(got - truth[j]));
    }
    if (size > 0) worst = std::max(worst, static_cast<double>(err / size));
  }
  row.truth_error = worst;
  try {
    const CaseSolution solution = solve_case(Case::id, v.params, s);
    row.tool = "solves (residual " + sig(solution.residual, 2) + ")";
  } catch (const Error& e) {
    row.tool = "refuses: " + std::string(e.what()).substr(0, 60) + "...";
  }
  return row;
}

// --- output -------------------------------------------------------------------------

plot::Plot time_plot(const std::string& title, const std::string& y_label) {
  plot::Plot p;
  p.title = title;
  p.x = {"time t (s)", plot::Scale::log, std::nullopt, std::nullopt};
  p.y = {y_label, plot::Scale::log, std::nullopt, std::nullopt};
  p.legend = plot::LegendPlace::outside_right;
  return p;
}

template <class Value>
plot::Series track_series(const Track& track, Value value) {
  plot::Series s;
  s.name = track.name;
  for (const Sample& x : track.samples) s.points.push_back({x.t, value(x)});
  return s;
}

void write_plot(const plot::Plot& p, const fs::path& stem, StressSummary& summary) {
  for (const char* ext : {".png", ".svg"}) {
    fs::path target = stem;
    target += ext;
    (void)plot::write(p, target, plot::Canvas{1100, 650, 14}, "out");
    summary.files.push_back(target);
  }
}

std::string tracks_csv(const std::vector<Track>& tracks) {
  std::ostringstream out;
  out << "run,case,integrator,stabilization,t,energy_error,internal_energy_error,constraint_error\n";
  for (const Track& tr : tracks)
    for (const Sample& x : tr.samples)
      out << '"' << tr.name << "\"," << tr.options.case_id << ',' << info(tr.options.integrator).name << ','
          << name(tr.options.stabilization) << ',' << csv_number(x.t) << ',' << csv_number(x.energy_error) << ','
          << csv_number(x.internal_energy_error) << ',' << csv_number(x.constraint_error) << '\n';
  return out.str();
}

std::string tracks_table(const std::vector<Track>& tracks) {
  std::ostringstream out;
  out << "| run | reached | steps | RHS evaluations | wall time | final energy error | final internal energy error "
         "| final constraint error |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Track& tr : tracks) {
    const Sample last = tr.samples.empty() ? Sample{} : tr.samples.back();
    out << "| " << tr.name << " | " << (tr.failure.empty() ? "end" : "t = " + sig(last.t) + " s (diverged)") << " | "
        << tr.stats.steps_accepted << " | " << tr.stats.rhs_evaluations << " | " << sig(tr.stats.wall_seconds, 2)
        << " s | " << sig(last.energy_error, 2) << " | " << sig(last.internal_energy_error, 2) << " | "
        << (tr.options.case_id == 1 ? sig(last.constraint_error, 2) : "-") << " |\n";
  }
  return out.str();
}

}  // namespace

StressSummary run_stress(const StressOptions& options) {
  prepare_output_folder(options.out, "out");
  StressSummary summary;
  const bool quick = options.quick;
  const Scenario& example = find_scenario("example", "stress");
  Scenario fast = find_scenario("fast", "stress");
  const auto& kinds = integrators();
  Progress progress("stress", 2 * static_cast<long>(kinds.size()) + 12 + 1 + 5, "studies", options.quiet);
  long done = 0;

  // 1. long runs
  const double long_duration = quick ? 50.0 : 1e4;
  const std::vector<double> long_times = log_times(0.1, long_duration, quick ? 30 : 150);
  std::vector<Track> long_runs;
  for (const int case_id : {3, 1})
    for (const IntegratorInfo& k : kinds) {
      const SimulationOptions o = options_for(case_id, k.kind, long_duration, 0.01, 1e-10);
      long_runs.push_back(run_track(
          example, o, long_times,
          std::string(k.name) + (k.adaptive ? " (tol 1e-10)" : " (dt 0.01 s)") + ", Case " + std::to_string(case_id)));
      progress.update(++done);
    }

  // 2. largest stable step
  if (quick) fast.duration = 2.0;
  std::vector<StableStep> steps;
  for (const int case_id : {3, 2, 1})
    for (const IntegratorInfo& k : kinds) {
      if (k.adaptive) continue;
      steps.push_back(find_stable_step(fast, case_id, k.kind, quick ? 3 : 10));
      progress.update(++done);
    }

  // 3. extremes
  std::vector<ExtremeRow> extremes;
  for (const Variant& v : variants(quick)) {
    extremes.push_back(extreme_row<Case1>(v));
    extremes.push_back(extreme_row<Case2>(v));
    extremes.push_back(extreme_row<Case3>(v));
  }
  progress.update(++done);

  // 4. Case 1 drift
  fast = find_scenario("fast", "stress");
  const double drift_duration = quick ? 20.0 : 1000.0;
  const std::vector<double> drift_times = log_times(0.01, drift_duration, quick ? 30 : 200);
  std::vector<Track> drift;
  struct Stab {
    Stabilization kind;
    double gain;
  };
  for (const Stab st :
       {Stab{Stabilization::none, 0}, Stab{Stabilization::baumgarte, 1}, Stab{Stabilization::baumgarte, 10},
        Stab{Stabilization::baumgarte, 100}, Stab{Stabilization::projection, 0}}) {
    SimulationOptions o = options_for(1, IntegratorKind::dop853, drift_duration, 1e-3, 1e-8);
    o.stabilization = st.kind;
    o.baumgarte_alpha = o.baumgarte_beta = st.gain;
    std::string label(name(st.kind));
    if (st.kind == Stabilization::baumgarte) label += " alpha = beta = " + sig(st.gain) + "/s";
    drift.push_back(run_track(fast, o, drift_times, label));
    progress.update(++done);
  }
  progress.finish();

  // --- files
  write_file_atomically(options.out / "stress_long_runs.csv", tracks_csv(long_runs), "out");
  write_file_atomically(options.out / "stress_drift.csv", tracks_csv(drift), "out");
  summary.files.push_back(options.out / "stress_long_runs.csv");
  summary.files.push_back(options.out / "stress_drift.csv");
  {
    std::ostringstream csv;
    csv << "case,integrator,largest_stable_dt_s,smallest_unstable_dt_s,unstable_because\n";
    for (const StableStep& s : steps)
      csv << s.case_id << ',' << info(s.integrator).name << ',' << csv_number(s.largest_stable) << ','
          << csv_number(s.smallest_unstable) << ",\"" << s.unstable_because << "\"\n";
    write_file_atomically(options.out / "stress_stable_step.csv", csv.str(), "out");
    summary.files.push_back(options.out / "stress_stable_step.csv");
  }
  {
    std::ostringstream csv;
    csv << "variant,case,condition_number,condition_number_row_scaled,block_solve_error,partial_piv_lu_error,"
           "acceleration_error_vs_long_double,tool\n";
    for (const ExtremeRow& r : extremes)
      csv << '"' << r.what << "\"," << r.case_id << ',' << csv_number(r.condition) << ','
          << csv_number(r.condition_scaled) << ',' << csv_number(r.block_error) << ',' << csv_number(r.lu_error) << ','
          << csv_number(r.truth_error) << ",\"" << r.tool << "\"\n";
    write_file_atomically(options.out / "stress_extremes.csv", csv.str(), "out");
    summary.files.push_back(options.out / "stress_extremes.csv");
  }

  plot::Plot energy =
      time_plot("Long runs, Case 3: internal energy error", "relative error of the energy about the centre of mass");
  plot::Plot energy1 = time_plot("Long runs, Case 1: energy error", "|E − E_{0}| / energy scale");
  plot::Plot constraint = time_plot("Long runs, Case 1: constraint error", "|C| (m)");
  for (const Track& tr : long_runs) {
    if (tr.options.case_id == 3)
      energy.series.push_back(track_series(tr, [](const Sample& x) { return x.internal_energy_error; }));
    else {
      energy1.series.push_back(track_series(tr, [](const Sample& x) { return x.energy_error; }));
      constraint.series.push_back(track_series(tr, [](const Sample& x) { return x.constraint_error; }));
    }
  }
  write_plot(energy, options.out / "stress_long_runs_energy", summary);
  write_plot(energy1, options.out / "stress_long_runs_case1_energy", summary);
  write_plot(constraint, options.out / "stress_long_runs_constraint", summary);
  plot::Plot drift_plot = time_plot("Case 1 constraint drift, scenario fast, DOP853 at 1e-8", "|C| (m)");
  for (const Track& tr : drift)
    drift_plot.series.push_back(track_series(tr, [](const Sample& x) { return x.constraint_error; }));
  write_plot(drift_plot, options.out / "stress_drift", summary);

  std::ostringstream md;
  md << "# Numerical stability\n\nReproduce with `linkage bench stress --out " << options.out.string()
     << (quick ? " --quick" : "") << "`. Every run goes through the tool's own engine (`Simulation`).\n\n"
     << "## Long runs: the spec's example over " << sig(long_duration) << " s\n\n"
     << "Fixed-step methods at dt = 0.01 s, adaptive ones at rtol = atol = 1e-10. The centre of mass falls "
     << sig(0.5 * example.params.g * long_duration * long_duration, 2)
     << " m, so the total energy's error is measured against a scale dominated by the fall; the internal energy "
        "(kinetic energy about the centre of mass, conserved on its own under uniform gravity) shows what each "
        "integrator does to the motion itself.\n\n"
     << "![internal energy](stress_long_runs_energy.svg)\n\n![constraint](stress_long_runs_constraint.svg)\n\n"
     << tracks_table(long_runs) << "\n"
     << "## Largest stable step (scenario fast over " << sig(quick ? 2.0 : 10.0) << " s)\n\n"
     << "Stable: the run reaches the end with the internal energy within 10 % of its start. Bisection on dt.\n\n"
     << "| case | integrator | largest stable dt | smallest unstable dt | why unstable |\n| --- | --- | --- | --- | "
        "--- |\n";
  for (const StableStep& s : steps)
    md << "| " << s.case_id << " | " << info(s.integrator).name << " | " << sig(s.largest_stable) << " s | "
       << sig(s.smallest_unstable) << " s | " << s.unstable_because << " |\n";
  md << "\n## Extreme parameters (the example's state unless the spin is named)\n\n"
     << "Condition numbers of each case's matrix (2-norm; and after scaling every row to a largest entry of 1), the "
        "error of our block solve and of Eigen's partial-pivot LU against a long double solve of the same matrix, "
        "and the accelerations' error against the closed form evaluated in long double (relative, per kind of "
        "unknown).\n\n"
     << "| variant | case | cond | cond, rows scaled | block solve | partialPivLu | accelerations | linkage solve |\n"
     << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const ExtremeRow& r : extremes)
    md << "| " << r.what << " | " << r.case_id << " | " << sig(r.condition, 2) << " | " << sig(r.condition_scaled, 2)
       << " | " << sig(r.block_error, 2) << " | " << sig(r.lu_error, 2) << " | " << sig(r.truth_error, 2) << " | "
       << r.tool << " |\n";
  md << "\n## Case 1 constraint drift (scenario fast over " << sig(drift_duration) << " s, DOP853 at 1e-8)\n\n"
     << "![drift](stress_drift.svg)\n\n"
     << tracks_table(drift) << "\n";
  write_file_atomically(options.out / "stress.md", md.str(), "out");
  summary.files.push_back(options.out / "stress.md");

  for (const StableStep& s : steps)
    summary.lines.push_back("largest stable dt, Case " + std::to_string(s.case_id) + ", " +
                            std::string(info(s.integrator).name) + ": " + sig(s.largest_stable) + " s");
  for (const Track& tr : drift)
    summary.lines.push_back("Case 1 constraint error after " + sig(drift_duration) + " s, " + tr.name + ": " +
                            (tr.samples.empty() ? "-" : sig(tr.samples.back().constraint_error, 2)) + " m");
  return summary;
}

}  // namespace linkage::bench
