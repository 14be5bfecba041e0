#include "bench/accuracy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <thread>

#include "bench/accuracy_report.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/general_rhs.hpp"
#include "bench/rhs.hpp"
#include "bench/targets.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "core/progress.hpp"

namespace linkage::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// How far a sweep goes (full run / --quick).
struct SweepLimits {
  std::vector<double> tolerances;  // adaptive methods, loosest first
  int max_step_counts;             // fixed-step methods: at most this many doublings
  double min_time;                 // s of repeats per point
  double max_run;                  // s: no tighter setting after a run this long
};

SweepLimits sweep_limits(bool quick) {
  SweepLimits s;
  if (quick) {
    s.tolerances = {1e-3, 1e-5, 1e-7, 1e-9};
    s.max_step_counts = 4;
    s.min_time = 0.0;
    s.max_run = 0.5;
  } else {
    // Down to 1e-16: each method goes as tight as it can (its sweep stops at its round-off
    // floor or the time cap), so a ratio is against a peer's best, not an arbitrary end.
    for (int k = 0; k <= 26; ++k) s.tolerances.push_back(std::pow(10.0, -3.0 - 0.5 * k));
    s.max_step_counts = 18;
    s.min_time = 0.02;
    s.max_run = 1.0;
  }
  return s;
}

/// The first step count: a power of two giving steps of at most 0.1 s.
double first_step_count(double duration) {
  double n = 16;
  while (duration / n > 0.1) n *= 2;
  return n;
}

AccuracyPoint measure(const Method& m, const Scenario& s, const Reference& ref, double knob, double min_time) {
  AccuracyPoint p;
  p.method = m.id;
  p.library = m.library;
  p.label = m.label;
  p.case_id = m.case_id;
  p.rhs = m.rhs;
  p.adaptive = m.adaptive;
  p.knob = knob;
  p.timing = time_repeated([&] { p.outcome = m.run(s, knob); }, min_time);
  const BodyState& b = p.outcome.final;
  if (!p.outcome.failure.empty()) {
    p.error = p.energy_error = p.constraint_error = kNaN;
    return p;
  }
  p.error = final_error(ref, b);
  const double e0 = invariants(s.params, body_state(s.params, s.initial)).energy;
  p.energy_error = std::fabs(invariants(s.params, b).energy - e0) / energy_scale(s.params, b);
  p.constraint_error = m.case_id == 1 ? constraint_error(s.params, b).position.norm() : kNaN;
  if (!std::isfinite(p.error)) p.outcome.failure = "the final state is not finite";
  return p;
}

/// Runs one method over its settings, loosest first, stopping early where tighter
/// settings cannot tell more (a run over the time cap, a round-off floor).
void sweep(const Method& m, const Scenario& s, const Reference& ref, const SweepLimits& limits,
           std::vector<AccuracyPoint>& out, Progress& progress, long& done) {
  double best = std::numeric_limits<double>::infinity();
  if (m.adaptive) {
    int stalled = 0;
    for (const double tol : limits.tolerances) {
      throw_if_interrupted();
      out.push_back(measure(m, s, ref, tol, limits.min_time));
      progress.update(++done);
      const AccuracyPoint& p = out.back();
      if (!p.outcome.failure.empty() || p.timing.median_seconds > limits.max_run) break;
      if (p.error < 0.9 * best) {
        best = p.error;
        stalled = 0;
      } else if (++stalled >= 3) {
        break;  // three tighter settings no better: the round-off floor
      }
    }
    return;
  }
  int stalled = 0;
  double n = first_step_count(s.duration);
  for (int k = 0; k < limits.max_step_counts; ++k, n *= 2) {
    throw_if_interrupted();
    out.push_back(measure(m, s, ref, n, limits.min_time));
    progress.update(++done);
    const AccuracyPoint& p = out.back();
    if (p.error < 0.9 * best) {
      best = p.error;
      stalled = 0;
    } else if (std::isfinite(p.error) && ++stalled >= 2) {
      break;  // at the round-off floor
    }
    if (p.timing.median_seconds * 2 > limits.max_run || best < 1e-13) break;
  }
}

// States for the right-hand-side timings: 64 points along the scenario's motion, so the
// angles and spins are those the integrators see.
std::vector<BodyState> timing_states(const Scenario& s) {
  const std::vector<Method> ours = linkage_methods(3);
  const auto dop853 = std::find_if(ours.begin(), ours.end(), [](const Method& m) { return m.id == "dop853"; });
  std::vector<BodyState> out;
  for (int i = 1; i <= 64; ++i) {
    Scenario part = s;
    part.duration = s.duration * i / 64.0;
    out.push_back(dop853->run(part, 1e-8).final);
  }
  return out;
}

template <class V, class F>
PerCall rhs_ns(const F& f, const std::vector<V>& ys, double min_batch) {
  V dy = ys.front();
  const Eigen::Index last = dy.size() - 1;
  double sink = 0;
  const PerCall ns = nanoseconds_per_call(
      [&](std::size_t i) {
        f(0.0, ys[i % ys.size()], dy);
        sink += dy[last];
      },
      min_batch);
  if (sink == 0.123456789) throw Error::failure("unreachable");  // keeps the calls alive
  return ns;
}

RhsTimings measure_rhs(const Scenario& s, bool quick) {
  const double batch = quick ? 1e-3 : 20e-3;
  const Params& p = s.params;
  std::vector<Vec<8>> y8;
  std::vector<Vec<12>> y12;
  for (const BodyState& b : timing_states(s)) {
    y8.push_back(b.generalized().vector());
    y12.push_back(b.vector());
  }
  RhsTimings t;
  t.case3_fast = rhs_ns(FastCase3Rhs<double>(p), y8, batch);
  t.case3_definition = rhs_ns(DefinitionCase3Rhs{p}, y8, batch);
  const UserConstants user(p);
  t.case3_user =
      rhs_ns([&](double, const Vec<8>& y, Vec<8>& dy) { user_case3_rhs(user, y.data(), dy.data()); }, y8, batch);
  t.case2 = rhs_ns(GeneralizedRhs<Case2>(p), y8, batch);
  t.case1 = rhs_ns(MaximalRhs(p, 0.0, 0.0), y12, batch);

  // The 4x4 solve alone, on systems assembled beforehand.
  std::vector<LinearSystem<Case3>> systems;
  for (const Vec<8>& y : y8) systems.push_back(assemble<Case3>(make_env(p, y[2], y[3], y[6], y[7])));
  Vec<4> q;
  double sink = 0;
  t.solve_blocks = nanoseconds_per_call(
      [&](std::size_t i) {
        const LinearSystem<Case3>& sys = systems[i % systems.size()];
        sink += solve_blocks<Case3>(sys.A, sys.B, q) ? q[3] : 0.0;
      },
      batch);
  t.solve_lu = nanoseconds_per_call(
      [&](std::size_t i) {
        const LinearSystem<Case3>& sys = systems[i % systems.size()];
        const Eigen::Matrix4d A = sys.A;
        const Eigen::Vector4d x = A.partialPivLu().solve(sys.B);
        sink += x[3];
      },
      batch);
  if (sink == 0.123456789) throw Error::failure("unreachable");
  t.oscillators = oscillators_rhs_ns(batch);
  const GeneralCase3Rhs general(p);
  std::vector<Eigen::VectorXd> states;  // the mechanism's own, as simulate integrates them
  for (const Vec<8>& y : y8) states.push_back(general.state(y));
  t.case3_general = rhs_ns(general, states, batch);
  t.general_evaluator = general.evaluator();
  return t;
}

// Our integrators on the oscillators, each copying its Case 3 run at the overhead's error.
std::vector<OverheadTiming> measure_overhead(const ScenarioResult& sr, double min_time) {
  std::vector<OverheadTiming> out;
  for (const Curve& c : curves(sr)) {
    if (!c.ours() || c.case_id != 3 || c.rhs != RhsKind::fastest) continue;
    const AccuracyPoint* p = overhead_point(c);
    if (p == nullptr) continue;
    OverheadTiming o;
    o.method = c.method;
    o.label = c.label;
    o.adaptive = p->adaptive;
    o.knob = p->knob;
    o.homework_error = p->error;
    o.per_evaluation = time_on_oscillators(c.method, p->knob, sr.scenario.duration, p->outcome.rhs_evaluations,
                                           min_time, o.evaluations);
    if (has_dynamic_run(c.method)) {
      std::int64_t made = 0;
      o.dynamic_per_evaluation = time_on_oscillators(c.method, p->knob, sr.scenario.duration,
                                                     p->outcome.rhs_evaluations, min_time, made, true);
      o.closed_form_fixed = time_on_closed_form(c.method, sr.scenario, p->knob, min_time, false, made);
      o.closed_form_dynamic = time_on_closed_form(c.method, sr.scenario, p->knob, min_time, true, made);
    }
    out.push_back(o);
  }
  return out;
}

std::vector<Method> all_methods() {
  std::vector<Method> out;
  for (int c : {3, 2, 1})
    for (Method& m : linkage_methods(c)) out.push_back(std::move(m));
  for (Method& m : peer_methods()) out.push_back(std::move(m));
  return out;
}

}  // namespace

void validate(const AccuracyOptions& o) {
  for (const std::string& s : o.scenarios) (void)find_scenario(s, "--scenario");
  if (o.scenarios.empty()) throw Error::input("--scenario: no scenario given; valid: " + scenario_names() + ", all");
  if (o.cases.empty()) throw Error::input("--cases: no case given; valid: 1, 2, 3");
  for (int c : o.cases)
    if (c < 1 || c > 3) throw Error::input("--cases: " + std::to_string(c) + " is not a case; valid: 1, 2, 3");
  const std::vector<std::string> ids = method_ids();
  for (const std::string& id : o.integrators)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
      for (const PeerLibrary& peer : peer_libraries())
        if (std::find(peer.ids.begin(), peer.ids.end(), id) != peer.ids.end())
          throw Error::input("--integrators: '" + id + "' is not in this build: " + peer.not_built_note());
      std::string valid;
      for (const std::string& v : ids) {
        if (!valid.empty()) valid += ", ";
        valid += v;
      }
      throw Error::input("--integrators: '" + id + "' is not an integrator; valid: " + valid);
    }
  if (o.duration && !(*o.duration > 0 && *o.duration <= 1e4))
    throw Error::input("--duration: " + format_roundtrip(*o.duration) + " s is out of range; valid: (0, 10000] s");
}

std::vector<std::string> method_ids() {
  std::vector<std::string> ids;
  for (const Method& m : all_methods())
    if (std::find(ids.begin(), ids.end(), m.id) == ids.end()) ids.push_back(m.id);
  return ids;
}

std::vector<Method> selected_methods(const AccuracyOptions& o) {
  std::vector<Method> out;
  for (Method& m : all_methods()) {
    const bool case_ok = std::find(o.cases.begin(), o.cases.end(), m.case_id) != o.cases.end();
    const bool id_ok =
        o.integrators.empty() || std::find(o.integrators.begin(), o.integrators.end(), m.id) != o.integrators.end();
    if (case_ok && id_ok) out.push_back(std::move(m));
  }
  return out;
}

AccuracyResult run_accuracy(const AccuracyOptions& options) {
  validate(options);
  const std::vector<Method> methods = selected_methods(options);
  if (methods.empty()) throw Error::input("--integrators: none of the chosen integrators runs the chosen --cases");
  prepare_output_folder(options.out, "out");
  const SweepLimits limits = sweep_limits(options.quick);

  AccuracyResult result;
  result.peers_not_built = peers_not_built();
  result.cores = std::max(1u, std::thread::hardware_concurrency());
  std::ifstream("/proc/loadavg") >> result.load_average;
  Scenario first = find_scenario(options.scenarios.front(), "--scenario");
  if (options.duration) first.duration = *options.duration;
  result.rhs = measure_rhs(first, options.quick);
  for (const std::string& name : options.scenarios) {
    ScenarioResult sr;
    sr.scenario = find_scenario(name, "--scenario");
    if (options.duration) sr.scenario.duration = *options.duration;
    sr.reference = compute_reference(sr.scenario, options.quick);
    long total = 0;
    for (const Method& m : methods)
      total += m.adaptive ? static_cast<long>(limits.tolerances.size()) : limits.max_step_counts;
    Progress progress("accuracy " + name, total, "runs", options.quiet);
    long done = 0;
    // The general path is derived and compiled once per Params, here rather than in a timed run.
    if (std::any_of(methods.begin(), methods.end(), [](const Method& m) { return m.rhs == RhsKind::general; }))
      (void)GeneralCase3Rhs(sr.scenario.params);
    for (const Method& m : methods) sweep(m, sr.scenario, sr.reference, limits, sr.points, progress, done);
    progress.finish();
    sr.overhead = measure_overhead(sr, limits.min_time);
    result.scenarios.push_back(std::move(sr));
  }
  write_accuracy_report(options, result);
  return result;
}

}  // namespace linkage::bench
