#include "bench/mechanisms_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/double_pendulum_user.hpp"
#include "bench/timing.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "core/progress.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"
#include "render/plot.hpp"
#include "symbolic/loop_closure.hpp"
#if LINKAGE_PEER_ODEINT
#include "bench/peer_odeint_pendulum.hpp"
#endif
#if LINKAGE_PEER_MUJOCO
#include <mujoco/mujoco.h>

#include "bench/peer_mujoco.hpp"
#endif

namespace linkage::bench {

namespace fs = std::filesystem;

namespace {

constexpr double kEnd = 10.0;  // s, the work-precision study's end time
constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

std::string sig(double v, int digits = 3) { return format_significant(v, digits); }

/// Nanoseconds of this thread's CPU time per f'(y) of one case at y, its last coordinate (an angle for most)
/// nudged by round-off each call so no call can be folded into the last.
double ns_per_rhs(const eval::MechanismDynamics& d, Eigen::VectorXd y, double min_batch, int batches) {
  Eigen::VectorXd dydt(y.size());
  const Eigen::Index at = d.coordinates() - 1;
  const double base = y[at];
  double sink = 0;
  const PerCall per = nanoseconds_per_call(
      [&](std::size_t i) {
        y[at] = base + 1e-15 * static_cast<double>(i & 7U);
        (void)d.derivative(0, y, dydt);
        sink += dydt[dydt.size() - 1];  // one entry, as for the closed form: the harness costs both alike
      },
      min_batch, batches);
  if (!std::isfinite(sink) || !dydt.allFinite())
    throw Error::failure("bench mechanisms: a right-hand side was not finite");
  return per.cpu_ns;
}

struct Loaded {
  std::unique_ptr<sym::System> system;
  GiNaC::exmap state;
};

Loaded load(const Mechanism& mechanism) {
  Loaded out;
  out.system = std::make_unique<sym::System>(mechanism);
  out.state = sym::checked_initial_state(*out.system).state;
  return out;
}

/// The homework's closed form (closed_form/case3_fast.hpp and friends) at its file's values.
void closed_form_rows(const sym::System& system, const GiNaC::exmap& state, double min_batch, int batches,
                      std::vector<RhsRow>& rows) {
  Params p;
  for (const Parameter& q : system.mechanism().parameters) {
    if (q.name == "L") p.L = q.value;
    if (q.name == "w") p.w = q.value;
    if (q.name == "b") p.b = q.value;
    if (q.name == "m") p.m = q.value;
    if (q.name == "g") p.g = q.value;
  }
  const eval::MechanismDynamics generalized(system, CaseId::reduced);
  const Eigen::VectorXd y = generalized.initial_state(state);
  Vec<8> y8;
  for (int i = 0; i < 8; ++i) y8[i] = y[i];
  auto time = [&](auto& f, auto yv) {
    auto out = yv;
    double sink = 0;
    // theta2 (the last coordinate of Cases 2 and 3, the sixth of Case 1), as for the general path
    const int at = yv.size() == 8 ? 3 : 5;
    const double base = yv[at];
    const PerCall per = nanoseconds_per_call(
        [&](std::size_t i) {
          yv[at] = base + 1e-15 * static_cast<double>(i & 7U);
          forget(yv);  // the other entries unknown again: nothing of f hoisted out of the loop
          f(0.0, yv, out);
          forget(out);  // every entry of y' stored, as the general path's
          sink += out[out.size() - 1];
        },
        min_batch, batches);
    if (!std::isfinite(sink) || !out.allFinite())
      throw Error::failure("bench mechanisms: a closed-form right-hand side was not finite");
    return per.cpu_ns;
  };
  const GeneralizedRhs<Case3> case3(p);
  const GeneralizedRhs<Case2> case2(p);
  const MaximalRhs case1(p, 0, 0);
  const eval::MechanismDynamics maximal(system, CaseId::maximal);
  const Eigen::VectorXd ym = maximal.initial_state(state);
  Vec<12> y12;
  for (int i = 0; i < 12; ++i) y12[i] = ym[i];
  rows.push_back({"two-blocks", 1, "closed-form", 2, time(case1, y12)});
  rows.push_back({"two-blocks", 2, "closed-form", 2, time(case2, y8)});
  rows.push_back({"two-blocks", 3, "closed-form", 2, time(case3, y8)});
}

const RhsRow* find(const std::vector<RhsRow>& rows, const std::string& mechanism, int case_id,
                   const std::string& path) {
  for (const RhsRow& r : rows)
    if (r.mechanism == mechanism && r.case_id == case_id && r.path == path) return &r;
  return nullptr;
}

// --- the double pendulum, work against precision -------------------------------------

struct Pendulum {
  double l1 = 0, m1 = 0, l2 = 0, m2 = 0, g = 0, theta1 = 0, theta2 = 0;
};

Pendulum pendulum_values(const Mechanism& m) {
  Pendulum p;
  for (const Parameter& q : m.parameters) {
    if (q.name == "l1") p.l1 = q.value;
    if (q.name == "m1") p.m1 = q.value;
    if (q.name == "l2") p.l2 = q.value;
    if (q.name == "m2") p.m2 = q.value;
    if (q.name == "g") p.g = q.value;
  }
  for (const InitialValue& v : m.initial) {
    if (v.key == "1.theta") p.theta1 = v.value;
    if (v.key == "2.theta") p.theta2 = v.value;
  }
  return p;
}

/// How many runs of each setting of the work-precision study (ours and Odeint's) the
/// median is taken of.
int work_repeats(const MechanismsBenchOptions& o) { return o.quick ? 1 : 3; }

/// Our run to t = 10 s: the angles at the end and the CPU time of state_at() alone, the
/// median of `repeats`.
struct OurRun {
  double theta1 = 0, theta2 = 0, seconds = 0;
};

OurRun run_ours(const sym::System& system, const GiNaC::exmap& state, SimulationOptions o, int repeats) {
  o.duration = kEnd;
  std::vector<double> times;
  OurRun out;
  for (int r = 0; r < repeats; ++r) {
    MechanismSimulation simulation(system, state, o);
    const double start = thread_cpu_seconds();
    const Eigen::VectorXd& y = simulation.state_at(kEnd);
    times.push_back(thread_cpu_seconds() - start);
    out.theta1 = y[0];
    out.theta2 = y[1];
  }
  out.seconds = median(times);
  return out;
}

/// The run time at which a method reaches `error`, interpolated log-log between its two
/// settings that bracket it (a grid of settings would otherwise decide the ratio); the
/// best of the methods whose name starts with `prefix`, with the method's name. NaN when
/// none reaches it.
std::pair<double, std::string> time_at_error(const std::vector<WorkPoint>& work, const std::string& prefix,
                                             double error) {
  std::vector<std::string> methods;
  for (const WorkPoint& w : work)
    if (w.method.rfind(prefix, 0) == 0 && std::find(methods.begin(), methods.end(), w.method) == methods.end())
      methods.push_back(w.method);
  std::pair<double, std::string> best{kNotMeasured, ""};
  for (const std::string& method : methods) {
    std::vector<WorkPoint> curve;
    for (const WorkPoint& w : work)
      if (w.method == method && w.error > 0) curve.push_back(w);
    std::sort(curve.begin(), curve.end(), [](const WorkPoint& a, const WorkPoint& b) { return a.error > b.error; });
    double t = kNotMeasured;
    for (std::size_t i = 0; i + 1 < curve.size() && std::isnan(t); ++i) {
      const WorkPoint &a = curve[i], &b = curve[i + 1];
      if (a.error >= error && b.error <= error) {
        const double f = std::log(a.error / error) / std::log(a.error / b.error);
        t = std::exp(std::log(a.seconds) + f * std::log(b.seconds / a.seconds));
      }
    }
    if (std::isfinite(t) && (std::isnan(best.first) || t < best.first)) best = {t, method};
  }
  return best;
}

// --- the report ---------------------------------------------------------------------

/// Run time against error, one curve per method (ours solid, peers dashed).
void write_work_plot(const std::vector<WorkPoint>& work, const std::string& title, const std::string& error_label,
                     const fs::path& target) {
  plot::Plot wp;
  wp.title = title;
  wp.x = {"run time (s)", plot::Scale::log, std::nullopt, std::nullopt};
  wp.y = {error_label, plot::Scale::log, std::nullopt, std::nullopt};
  wp.legend = plot::LegendPlace::outside_right;
  std::vector<std::string> methods;
  for (const WorkPoint& w : work)
    if (std::find(methods.begin(), methods.end(), w.method) == methods.end()) methods.push_back(w.method);
  for (std::size_t i = 0; i < methods.size(); ++i) {
    plot::Series s;
    s.name = methods[i];
    s.style = plot::Style::line_and_markers;
    const bool peer = methods[i].rfind("odeint", 0) == 0 || methods[i].rfind("mujoco", 0) == 0;
    s.dash = peer ? plot::Dash::dashed : plot::Dash::solid;
    s.color = i % plot::palette_size;
    for (const WorkPoint& w : work)
      if (w.method == methods[i]) s.points.push_back({w.seconds, std::max(w.error, 1e-16)});
    wp.series.push_back(s);
  }
  (void)plot::write(wp, target, plot::Canvas{1250, 720, 14}, "out");
}

void write_plots(const MechanismsBenchResult& r, const fs::path& out, std::vector<fs::path>& files) {
  write_work_plot(r.work, "Double pendulum to t = 10 s: work against precision", "error at t = 10 s: max |Δθ| (rad)",
                  out / "work-precision.png");
  files.push_back(out / "work-precision.png");
  const plot::Canvas canvas{1250, 720, 14};

  plot::Plot chain;
  chain.title = "Pendulum chain: one evaluation of the dynamics";
  chain.x = {"links n", plot::Scale::log, std::nullopt, std::nullopt};
  chain.y = {"time per evaluation (ns)", plot::Scale::log, std::nullopt, std::nullopt};
  for (const std::string path : {"evaluator", "compiled", "mujoco"}) {
    plot::Series s;
    s.name = path == "mujoco" ? "MuJoCo 2.2 mj_forward" : "ours: Case 3, O(n) recursion, " + path;
    s.style = plot::Style::line_and_markers;
    for (const RhsRow& row : r.rows)
      if (row.mechanism.rfind("chain-", 0) == 0 && row.path == path)
        s.points.push_back({static_cast<double>(row.bodies), row.ns_per_rhs});
    if (!s.points.empty()) chain.series.push_back(s);
  }
  (void)plot::write(chain, out / "chain-scaling.png", canvas, "out");
  files.push_back(out / "chain-scaling.png");
}

void write_report(const MechanismsBenchOptions& o, MechanismsBenchResult& r) {
  std::ostringstream csv, md;
  csv << "mechanism,case,path,bodies,ns_per_rhs\n";
  for (const RhsRow& row : r.rows)
    csv << row.mechanism << "," << row.case_id << "," << row.path << "," << row.bodies << ","
        << format_roundtrip(row.ns_per_rhs) << "\n";
  std::ostringstream work;
  work << "method,setting,seconds,error\n";
  for (const WorkPoint& w : r.work)
    work << w.method << "," << format_roundtrip(w.setting) << "," << format_roundtrip(w.seconds) << ","
         << format_roundtrip(w.error) << "\n";

  md << "# Mechanisms: the cost of any mechanism's motion\n\n"
     << "Reproduce: `linkage bench mechanisms" << (o.quick ? " --quick" : "") << " --out " << o.out.string()
     << "`. Every figure comes from this one run on this machine; compare ratios, not "
        "absolute times (shared machines are noisy). Times are this thread's CPU time "
        "(CLOCK_THREAD_CPUTIME_ID: the wall clock also counts other processes' turns on the cores), "
        "the median of batches.\n\n";
  if (!r.lines.empty()) {
    md << "## Notes\n\n";
    for (const std::string& line : r.lines) md << "- " << line << "\n";
    md << "\n";
  }
  md << "## Targets\n\n| target | measured | goal | verdict |\n|---|---|---|---|\n";
  for (const TargetLine& t : r.targets)
    md << "| " << t.target << " | " << t.measured << " | " << t.goal << " | "
       << (t.note.empty() ? (t.met ? "met" : "**missed**") : t.note) << " |\n";
  md << "\n## Nanoseconds per right-hand side\n\n"
        "`evaluator`: the mechanism's equations compiled from the symbolic system into programs run by the "
        "interpreter (Case 3 of a tree: the O(n) recursion over the spanning tree, with a Schur complement for "
        "loops; Cases 1 and 2: the compiled rows solved by LU). `compiled`: the same programs as native code, as "
        "simulate runs them (the shipped mechanisms' built into the program; the chains' compiled at run time "
        "into the user's cache, the recursion's programs alone). `closed-form`: the homework's equations written "
        "out by hand. `mujoco`: mj_forward on "
        "the same chain.\n\n| mechanism | case | path | bodies | ns |\n|---|---|---|---|---|\n";
  for (const RhsRow& row : r.rows)
    md << "| " << row.mechanism << " | " << row.case_id << " | " << row.path << " | " << row.bodies << " | "
       << sig(row.ns_per_rhs) << " |\n";
  md << "\n![chain scaling](chain-scaling.png)\n\n## Double pendulum, work against precision\n\n"
     << "Error: the largest |Δθ| of the two rods at t = 10 s against our DOP853 at rtol = atol = 1e-14 in Case 3; "
        "the same run in Case 2 (the compiled rows, LU) differs from it by "
     << sig(r.reference_check, 2)
     << " rad, so errors down to about 1e-13 are real. Odeint runs the right-hand side a user writes "
        "by hand (bench/double_pendulum_user.hpp); MuJoCo its own model of the same rods (bench/peer_mujoco.cpp). "
        "MuJoCo's Euler is semi-implicit in the velocity. Run time: this thread's CPU time, the median of "
     << work_repeats(o)
     << " runs for ours and Odeint's, one run for MuJoCo's.\n\n"
        "| method | setting | run time (s) | error (rad) |\n|---|---|---|---|\n";
  for (const WorkPoint& w : r.work)
    md << "| " << w.method << " | " << sig(w.setting, 2) << " | " << sig(w.seconds) << " | " << sig(w.error, 2)
       << " |\n";
  md << "\n![work-precision](work-precision.png)\n";

  ensure_directory(o.out, "out");
  write_file_atomically(o.out / "mechanisms.csv", csv.str(), "out");
  write_file_atomically(o.out / "work-precision.csv", work.str(), "out");
  write_file_atomically(o.out / "mechanisms.md", md.str(), "out");
  r.files = {o.out / "mechanisms.csv", o.out / "work-precision.csv", o.out / "mechanisms.md"};
  write_plots(r, o.out, r.files);
}

void judge(const MechanismsBenchOptions& o, MechanismsBenchResult& r) {
  // `why`: what stops a measurement; `because`: why a measured target is missed.
  auto line = [&](const std::string& target, double measured, double goal, bool below, const std::string& unit,
                  const std::string& why, const std::string& because = "") {
    TargetLine t;
    t.target = target;
    t.measured = std::isfinite(measured) ? sig(measured) + unit : "-";
    t.goal = (below ? "<= " : ">= ") + sig(goal) + unit;
    t.met = std::isfinite(measured) && (below ? measured <= goal : measured >= goal);
    if (!std::isfinite(measured)) t.note = why;
    if (std::isfinite(measured) && !t.met && !because.empty())
      t.note = "**missed** by " + sig(below ? measured / goal : goal / measured) + "x: " + because;
    r.targets.push_back(t);
  };
  auto ns_of = [&](const std::string& mechanism, int case_id, const std::string& path) {
    const RhsRow* row = find(r.rows, mechanism, case_id, path);
    return row != nullptr ? row->ns_per_rhs : kNotMeasured;
  };
  const std::string no_compiled = "not measured: no compiled row (see the notes)";
  // What the general LU (the structured solve's reference) gave on the same case in this run.
  auto structured = [&](const std::string& key) {
    const auto it = r.structured.find(key);
    return it == r.structured.end() ? std::string()
                                    : "; with the general LU instead of the structured solve "
                                      "(MechanismDynamics::solve_by_structure(false)) " +
                                          sig(it->second) + " ns";
  };
  const double compiled3 = ns_of("two-blocks", 3, "compiled"), closed3 = ns_of("two-blocks", 3, "closed-form");
  line("homework Case 3: compiled / closed form", compiled3 / closed3, kMaxCompiledOverClosed, true, "x", no_compiled,
       "the closed form is the two blocks' four equations solved by hand and inlined by the compiler (" + sig(closed3) +
           " ns, two sincos and about 35 operations); the compiled path computes A and B from the expanded "
           "rows (each term's parameter factor computed once per run), eliminates the force rows' constant pivots and "
           "solves the symmetric "
           "2 x 2 remainder by LDL^T in one program (evaluate/static_solve.hpp), then checks its pivots (" +
           sig(compiled3) + " ns; evaluator " + sig(ns_of("two-blocks", 3, "evaluator")) + " ns)" +
           structured("two-blocks Case 3"));
  line("four-bar Case 1 right-hand side (compiled)", ns_of("four-bar", 1, "compiled"), kMaxFourBarCase1Ns, true, " ns",
       no_compiled,
       "the general LU of its 14 x 14 A (evaluator " + sig(ns_of("four-bar", 1, "evaluator")) + " ns)" +
           structured("four-bar Case 1"));
  line("four-bar Case 3 right-hand side (compiled)", ns_of("four-bar", 3, "compiled"), kMaxFourBarCase3Ns, true, " ns",
       no_compiled,
       "the recursion over the spanning tree and the Schur complement of the loop's rows by the general LU "
       "(evaluator " +
           sig(ns_of("four-bar", 3, "evaluator")) + " ns)" + structured("four-bar Case 3"));
  const std::string quick = "not measured: --quick stops at 8 links";
  const double ours32 = ns_of("chain-32", 3, "compiled"), mujoco32 = ns_of("chain-32", 3, "mujoco");
  std::string why32 = o.quick ? quick : std::isnan(ours32) ? no_compiled : "not measured: MuJoCo not built";
  line("chain of 32: mj_forward / ours (compiled)", mujoco32 / ours32, kMinSpeedupOverMujocoChain32, false, "x", why32,
       "both are O(n) per evaluation; ours " + sig(ours32) + " ns (evaluator " +
           sig(ns_of("chain-32", 3, "evaluator")) +
           " ns) runs the recursion in plain scalars (evaluate/tree_dynamics.cpp)");
  const double c8 = ns_of("chain-8", 3, "compiled"), c16 = ns_of("chain-16", 3, "compiled"),
               c64 = ns_of("chain-64", 3, "compiled");
  line("chain: time at 64 links / at 8 (compiled)", c64 / c8, kMaxChainGrowth, true, "x", o.quick ? quick : no_compiled,
       "8 links (8 rows) are solved in one compiled program by the static solve, faster than the recursion that 16 "
       "links and more run; the recursion grows as n: 64 / 16 links = " +
           sig(c64 / c16) + "x (goal for 4x the links: <= 4.5x)");
  const auto [ours, ours_method] = time_at_error(r.work, "ours", kPendulumTargetError);
  const auto [rk4, rk4_method] = time_at_error(r.work, "mujoco rk4", kPendulumTargetError);
  std::string why = "not measured: MuJoCo not built";
#if LINKAGE_PEER_MUJOCO
  if (std::isnan(rk4)) why = "MuJoCo's RK4 reached no error of 1e-8 at the steps tried";
#endif
  const double pendulum = ns_of("double-pendulum", 3, "compiled"), mj2 = ns_of("chain-2", 3, "mujoco");
  line("double pendulum, error 1e-8 at t = 10 s (interpolated): MuJoCo RK4 / ours (" + ours_method + ", compiled)",
       rk4 / ours, kMinSpeedupOverMujocoRk4, false, "x", why,
       "one evaluation of ours costs " + sig(pendulum) + " ns against " + sig(mj2) +
           " ns for mj_forward on two links, but at 1e-8 MuJoCo's RK4 needs only a step of a few "
           "milliseconds (four evaluations each), while DOP853 rejects about a quarter of its steps on "
           "this motion, whose fast phases make its error estimate swing");
  const auto [odeint, odeint_method] = time_at_error(r.work, "odeint", kPendulumTargetError);
  std::string why_odeint = "not measured: Boost.Odeint not built";
#if LINKAGE_PEER_ODEINT
  why_odeint = "no Odeint method reached an error of 1e-8 at the settings tried";
#endif
  line("the same: best Odeint (" + odeint_method + ", hand-written right-hand side) / ours", odeint / ours,
       kMinSpeedupOverOdeint, false, "x", why_odeint,
       "the hand-written right-hand side (bench/double_pendulum_user.hpp) is a few lines of closed form for this "
       "one mechanism, cheaper per evaluation than the general path's (" +
           sig(pendulum) + " ns compiled)");
}

}  // namespace

std::string pendulum_chain_toml(int links) {
  std::ostringstream t;
  t << "title = \"A chain of " << links << " rods from a ground pin\"\ngravity = \"g\"\n\n[parameters]\n"
    << "l = 0.3\nm = 0.1\ng = 9.81\n\n[ground]\npoints = { O = [0, 0] }\n";
  for (int k = 1; k <= links; ++k)
    t << "\n[[body]]\nname = \"" << k << "\"\nshape = \"rod\"\nmass = \"m\"\nlength = \"l\"\n"
      << "points = { S = [\"-l/2\", 0], E = [\"l/2\", 0] }\n";
  for (int k = 1; k <= links; ++k)
    t << "\n[[joint]]\nname = \"J" << k << "\"\ntype = \"pin\"\nbodies = [\""
      << (k == 1 ? std::string("ground") : std::to_string(k - 1)) << "\", \"" << k << "\"]\npoints = [\""
      << (k == 1 ? "O" : "E") << "\", \"S\"]\n";
  t << "\n[initial]\n";
  for (int k = 1; k <= links; ++k)
    t << "\"" << k << "\" = { theta = " << format_roundtrip(-1.2 + 0.05 * k)
      << ", theta_dot = " << format_roundtrip(0.1 * (k % 3)) << " }\n";
  return t.str();
}

MechanismsBenchResult run_mechanisms_bench(const MechanismsBenchOptions& o) {
  MechanismsBenchResult r;
  const double min_batch = o.quick ? 0.002 : 0.05;
  const int batches = o.quick ? 3 : 7;
  const std::vector<std::string> names = shipped_mechanism_names();
  const std::vector<int> chains = o.quick ? std::vector<int>{2, 4, 8} : std::vector<int>{2, 4, 8, 16, 32, 64};
  Progress progress("bench mechanisms", static_cast<long>(names.size() + chains.size() + 1), "studies", o.quiet);
  long done = 0;
  std::vector<std::string> missing_builtin;  // shipped cases without built-in native code

  for (const std::string& name : names) {
    const Loaded m = load(load_mechanism(name));
    const int bodies = static_cast<int>(m.system->bodies().size());
    for (CaseId id : kAllCases) {
      const eval::MechanismDynamics d(*m.system, id);
      const Eigen::VectorXd y = d.initial_state(m.state);
      r.rows.push_back({name, case_number(id), "evaluator", bodies, ns_per_rhs(d, y, min_batch, batches)});
      eval::MechanismDynamics compiled(*m.system, id);
      if (!compiled.attach_builtin()) {
        missing_builtin.push_back(name + " Case " + std::to_string(case_number(id)));
        continue;
      }
      r.rows.push_back({name, case_number(id), "compiled", bodies, ns_per_rhs(compiled, y, min_batch, batches)});
      const std::string key = name + " Case " + std::to_string(case_number(id));
      if (key == "two-blocks Case 3" || key == "four-bar Case 1" || key == "four-bar Case 3") {
        compiled.solve_by_structure(false);
        r.structured[key] = ns_per_rhs(compiled, y, min_batch, batches);
      }
    }
    if (name == "two-blocks") closed_form_rows(*m.system, m.state, min_batch, batches, r.rows);
    progress.update(++done);
  }
  if (!missing_builtin.empty())
    r.lines.push_back("no compiled rows for " + std::to_string(missing_builtin.size()) +
                      " shipped cases (first: " + missing_builtin.front() +
                      "): no built-in native code in this program; the evaluator's rows stand");
  std::string chains_not_compiled;  // why the chains have no compiled rows ("" when they have)
  if (!eval::native_compiler_found()) chains_not_compiled = "no C++ compiler (c++) on PATH";
  for (int n : chains) {
    const Loaded m = load(read_mechanism(pendulum_chain_toml(n), "chain-" + std::to_string(n) + ".toml"));
    const eval::MechanismDynamics d(*m.system, CaseId::reduced);
    const std::string name = "chain-" + std::to_string(n);
    const Eigen::VectorXd y = d.initial_state(m.state);
    r.rows.push_back({name, 3, "evaluator", n, ns_per_rhs(d, y, min_batch, batches)});
    if (chains_not_compiled.empty()) {
      eval::MechanismDynamics compiled(*m.system, CaseId::reduced);
      const eval::NativeAttachment a = compiled.attach_native_derivative();
      if (a.attached)
        r.rows.push_back({name, 3, "compiled", n, ns_per_rhs(compiled, y, min_batch, batches)});
      else
        chains_not_compiled = a.reason;
    }
#if LINKAGE_PEER_MUJOCO
    r.rows.push_back({name, 3, "mujoco", n, mujoco_forward_ns(n, min_batch * batches)});
#endif
    progress.update(++done);
  }
  if (!chains_not_compiled.empty())
    r.lines.push_back("chains: no compiled rows (" + chains_not_compiled + "); the evaluator's rows stand");

  // The double pendulum to t = 10 s.
  const Mechanism pendulum = load_mechanism("double-pendulum");
  const Loaded m = load(pendulum);
  const Pendulum p = pendulum_values(pendulum);
  SimulationOptions reference;
  reference.integrator = IntegratorKind::dop853;
  reference.rtol = reference.atol = 1e-14;
  reference.evaluator = Evaluator::compiled;  // built in: no compiler needed
  const OurRun exact = run_ours(*m.system, m.state, reference, 1);
  SimulationOptions check = reference;
  check.case_id = 2;
  const OurRun second = run_ours(*m.system, m.state, check, 1);
  r.reference_check = std::max(std::fabs(second.theta1 - exact.theta1), std::fabs(second.theta2 - exact.theta2));
  auto error = [&](double t1, double t2) {
    return std::max(std::fabs(t1 - exact.theta1), std::fabs(t2 - exact.theta2));
  };
  const int repeats = work_repeats(o);
  const std::vector<double> tolerances =
      o.quick ? std::vector<double>{1e-6, 1e-9}
              : std::vector<double>{1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13};
  const std::vector<double> steps =
      o.quick ? std::vector<double>{1e-2, 1e-3} : std::vector<double>{2e-2, 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4};
  for (const IntegratorKind kind : {IntegratorKind::dop853, IntegratorKind::vern7, IntegratorKind::dopri5})
    for (double tol : tolerances) {
      SimulationOptions s = reference;
      s.integrator = kind;
      s.rtol = s.atol = tol;
      const OurRun run = run_ours(*m.system, m.state, s, repeats);
      r.work.push_back({"ours " + std::string(info(kind).name), tol, run.seconds, error(run.theta1, run.theta2)});
    }
  for (double dt : steps) {
    SimulationOptions s = reference;
    s.integrator = IntegratorKind::rk4;
    s.dt = dt;
    const OurRun run = run_ours(*m.system, m.state, s, repeats);
    r.work.push_back({"ours rk4", dt, run.seconds, error(run.theta1, run.theta2)});
  }
#if LINKAGE_PEER_ODEINT
  const DoublePendulumUser user{p.l1, p.m1, p.l2, p.m2, p.g};
  // As ours: the median of `repeats` runs (a single run had moved Odeint / ours by 0.88x
  // to 1.4x between runs of the same code).
  auto odeint_run = [&](const std::string& stepper, double setting) {
    std::vector<double> times;
    PendulumRun run;
    for (int k = 0; k < repeats; ++k) {
      run = odeint_double_pendulum(user, stepper, setting, p.theta1, p.theta2, kEnd);
      times.push_back(run.seconds);
    }
    run.seconds = median(times);
    return run;
  };
  for (const std::string stepper : {"rkf78", "dopri5"})
    for (double tol : tolerances) {
      const PendulumRun run = odeint_run(stepper, tol);
      r.work.push_back({"odeint " + stepper, tol, run.seconds, error(run.theta1, run.theta2)});
    }
  for (double dt : steps) {
    const PendulumRun run = odeint_run("rk4", dt);
    r.work.push_back({"odeint rk4", dt, run.seconds, error(run.theta1, run.theta2)});
  }
#endif
#if LINKAGE_PEER_MUJOCO
  DoublePendulumSpec spec;
  spec.L1 = p.l1;
  spec.L2 = p.l2;
  spec.m1 = p.m1;
  spec.m2 = p.m2;
  spec.g = p.g;
  spec.theta1 = p.theta1;
  spec.theta2 = p.theta2;
  const std::vector<double> mujoco_steps =
      o.quick ? std::vector<double>{1e-2, 1e-3} : std::vector<double>{1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5};
  for (double dt : mujoco_steps) {
    const MujocoRun run = mujoco_double_pendulum(spec, mjINT_RK4, dt, kEnd);
    r.work.push_back({"mujoco rk4", dt, run.seconds, error(run.theta1, run.theta2)});
  }
  for (double dt : o.quick ? std::vector<double>{1e-3} : std::vector<double>{1e-3, 1e-4, 1e-5}) {
    const MujocoRun run = mujoco_double_pendulum(spec, mjINT_EULER, dt, kEnd);
    r.work.push_back({"mujoco euler", dt, run.seconds, error(run.theta1, run.theta2)});
  }
#else
  (void)p;
#endif
  progress.update(++done);
  progress.finish();

  judge(o, r);
  write_report(o, r);
  for (const TargetLine& t : r.targets)
    r.lines.push_back(t.target + ": " + t.measured + (t.goal == "-" ? std::string(" ") : " (goal " + t.goal + ") ") +
                      (t.note.empty()                       ? (t.met ? "met" : "MISSED")
                       : t.note.rfind("**missed**", 0) == 0 ? "MISSED" + t.note.substr(10)
                                                            : t.note));
  return r;
}

namespace {

/// Every body's x, y, theta at the end of a run of `o` (its duration), through the
/// sample, so every case is compared on the same quantities; and the time of state_at().
struct PoseRun {
  std::vector<double> pose;
  double seconds = 0;
};

PoseRun run_poses(const sym::System& system, const GiNaC::exmap& state, const SimulationOptions& o) {
  MechanismSimulation simulation(system, state, o);
  const auto start = std::chrono::steady_clock::now();
  const Eigen::VectorXd y = simulation.state_at(o.duration);
  PoseRun out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  eval::MechanismSample sample;
  simulation.sample(o.duration, y, sample);
  out.pose = sample.pose;
  return out;
}

/// Sets `o` to the compiled path when it can run its case (built in, else compiled into the
/// user's cache as simulate does), else to the evaluator; what runs, as simulate's summary says it.
std::string choose_path(const sym::System& system, const GiNaC::exmap& state, SimulationOptions& o) {
  o.evaluator = Evaluator::compiled;
  try {
    return MechanismSimulation(system, state, o).stats().evaluator;
  } catch (const Error& e) {
    if (e.setting() != "evaluator") throw;
    o.evaluator = Evaluator::interpreted;
    // detail(): "'compiled' cannot run: REASON; valid: ..."
    std::string reason = e.detail();
    reason = reason.substr(0, reason.rfind("; valid:"));
    reason = reason.substr(reason.find(": ") == std::string::npos ? 0 : reason.find(": ") + 2);
    return "interpreted (" + reason + ")";
  }
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

}  // namespace

MechanismAccuracyResult run_mechanism_accuracy(const MechanismAccuracyOptions& o) {
  MechanismAccuracyResult r;
  const Mechanism mechanism = load_mechanism(o.mechanism);
  const Loaded m = load(mechanism);
  const double duration = o.quick ? std::min(o.duration, 1.0) : o.duration;
  const bool loops = !m.system->tree().loop_joints.empty();
  SimulationOptions reference;
  reference.integrator = IntegratorKind::dop853;
  reference.rtol = reference.atol = 1e-14;
  reference.duration = duration;
  reference.stabilization = loops ? Stabilization::projection : Stabilization::none;
  std::vector<std::string> paths;  // per case: what computes its equations
  std::vector<Evaluator> evaluators;
  for (int c : o.cases) {
    SimulationOptions s = reference;
    s.case_id = c;
    paths.push_back("Case " + std::to_string(c) + ": " + choose_path(*m.system, m.state, s));
    evaluators.push_back(s.evaluator);
  }
  {
    SimulationOptions s = reference;
    r.path = "reference (Case 3): " + choose_path(*m.system, m.state, s);
    reference.evaluator = s.evaluator;
    for (const std::string& p : paths) r.path += "; " + p;
  }
  const PoseRun exact = run_poses(*m.system, m.state, reference);
  SimulationOptions second = reference;
  second.case_id = 2;
  r.second_equations = largest_difference(run_poses(*m.system, m.state, second).pose, exact.pose);
  SimulationOptions gauss = reference;
  gauss.integrator = IntegratorKind::gauss2;
  gauss.dt = o.quick ? 1e-3 : 2e-4;
  r.second_method = largest_difference(run_poses(*m.system, m.state, gauss).pose, exact.pose);

  const std::vector<double> tolerances =
      o.quick ? std::vector<double>{1e-6, 1e-10} : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13};
  const std::vector<double> steps =
      o.quick ? std::vector<double>{1e-2, 1e-3} : std::vector<double>{1e-2, 3e-3, 1e-3, 3e-4, 1e-4};
  Progress progress("bench accuracy", static_cast<long>(o.cases.size()), "cases", o.quiet);
  long done = 0;
  for (std::size_t k = 0; k < o.cases.size(); ++k) {
    const int c = o.cases[k];
    for (const IntegratorInfo& info : integrators()) {
      for (double setting : info.adaptive ? tolerances : steps) {
        SimulationOptions s = reference;
        s.case_id = c;
        s.evaluator = evaluators[k];
        s.integrator = info.kind;
        s.stabilization = c == 1 || loops ? Stabilization::projection : Stabilization::none;
        if (info.adaptive)
          s.rtol = s.atol = setting;
        else
          s.dt = setting;
        double error = kNotMeasured, seconds = kNotMeasured;
        try {
          const PoseRun run = run_poses(*m.system, m.state, s);
          error = largest_difference(run.pose, exact.pose);
          seconds = run.seconds;
        } catch (const Error&) {
          // a run that fails (an explicit method too coarse for the motion) has no point
        }
        r.work.push_back({"Case " + std::to_string(c) + " " + std::string(info.name), setting, seconds, error});
      }
    }
    progress.update(++done);
  }
  progress.finish();

  const std::string stem = "accuracy-" + mechanism.name;
  std::ostringstream csv, md;
  csv << "method,setting,seconds,error\n";
  for (const WorkPoint& w : r.work)
    csv << w.method << "," << format_roundtrip(w.setting) << "," << format_roundtrip(w.seconds) << ","
        << format_roundtrip(w.error) << "\n";
  md << "# Accuracy: " << mechanism.title << "\n\nReproduce: `linkage bench accuracy --mechanism " << o.mechanism
     << (o.quick ? " --quick" : "") << " --out " << o.out.string() << "`.\n\n"
     << "Error: the largest difference of any body's x, y (m) or theta (rad) at t = " << sig(duration)
     << " s from the reference, DOP853 at rtol = atol = 1e-14 in Case 3"
     << (loops ? " with projection onto the loop constraints" : "")
     << ". The reference is double precision (the compiled evaluator has no extended-precision build); instead it is "
        "checked twice: the same run on Case 2's equations differs by "
     << sig(r.second_equations, 2) << ", Gauss-Legendre (order 4, implicit) at dt = " << sig(gauss.dt) << " s by "
     << sig(r.second_method, 2)
     << ". Errors below the larger of these are not resolved. Case 1 and mechanisms with loops run with projection."
     << "\n\nWhat computes the equations (the compiled path when it can run, as simulate's `--evaluator compiled`): "
     << r.path << ".\n\n"
     << "| method | setting | run time (s) | error |\n|---|---|---|---|\n";
  for (const WorkPoint& w : r.work)
    md << "| " << w.method << " | " << sig(w.setting, 2) << " | "
       << (std::isfinite(w.seconds) ? sig(w.seconds) : std::string("failed")) << " | "
       << (std::isfinite(w.error) ? sig(w.error, 2) : std::string("-")) << " |\n";
  md << "\n![work-precision](" << stem << ".png)\n";
  ensure_directory(o.out, "out");
  write_file_atomically(o.out / (stem + ".csv"), csv.str(), "out");
  write_file_atomically(o.out / (stem + ".md"), md.str(), "out");
  write_work_plot(r.work, mechanism.title + ": work against precision to t = " + sig(duration) + " s",
                  "error: max |Δ| of every body's x, y, θ", o.out / (stem + ".png"));
  r.files = {o.out / (stem + ".csv"), o.out / (stem + ".md"), o.out / (stem + ".png")};
  r.lines.push_back("path: " + r.path);
  r.lines.push_back("reference (DOP853 1e-14, Case 3) against Case 2: " + sig(r.second_equations, 2) +
                    ", against Gauss-Legendre: " + sig(r.second_method, 2));
  for (const int c : o.cases)
    for (const IntegratorInfo& info : integrators()) {
      const std::string method = "Case " + std::to_string(c) + " " + std::string(info.name);
      const auto [t, name] = time_at_error(r.work, method, 1e-8);
      if (std::isfinite(t)) r.lines.push_back(method + ": error 1e-8 in " + sig(t) + " s");
    }
  return r;
}

}  // namespace linkage::bench
