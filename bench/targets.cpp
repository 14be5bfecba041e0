#include "bench/targets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/number_format.hpp"

namespace linkage::bench {
namespace {

std::string ns(double v) { return format_significant(v, 3) + " ns"; }
std::string ratio(double v) { return format_significant(v, 3) + "x"; }
std::string seconds(double v) { return format_significant(v * 1e3, 3) + " ms"; }

struct Best {
  double time = std::numeric_limits<double>::infinity();
  std::string name;
};

/// The fastest curve among those `pick` accepts to reach `error`.
template <class Pick>
Best best_time(const std::vector<Curve>& all, double error, Pick pick, Clock clock = Clock::wall) {
  Best best;
  for (const Curve& c : all) {
    if (!pick(c)) continue;
    const std::optional<double> t = time_to_error(c, error, clock);
    if (t && *t < best.time) best = {*t, c.name()};
  }
  return best;
}

bool is_ours_fastest(const Curve& c) { return c.ours() && c.case_id == 3 && c.rhs == RhsKind::fastest; }
bool is_ours_general(const Curve& c) { return c.ours() && c.case_id == 3 && c.rhs == RhsKind::general; }

double pick(const PerCall& c, Clock clock) { return clock == Clock::wall ? c.wall_ns : c.cpu_ns; }
const char* clock_name(Clock clock) { return clock == Clock::wall ? "steady clock" : "thread CPU time"; }
Clock other(Clock clock) { return clock == Clock::wall ? Clock::cpu : Clock::wall; }

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// How close the curves `pick` accepts came, and why they stopped: "odeint-rkf78
/// (user RHS) best 5.2e-10 at 1e-16, the tightest setting tried".
template <class Pick>
std::string closest(const std::vector<Curve>& all, Pick pick) {
  std::string out;
  for (const Curve& c : all) {
    if (!pick(c) || c.points.empty()) continue;
    const AccuracyPoint* best = nullptr;
    for (const AccuracyPoint* p : c.points)
      if (std::isfinite(p->error) && (best == nullptr || p->error < best->error)) best = p;
    if (best == nullptr) continue;
    const AccuracyPoint* last = c.points.back();
    const std::string why = !last->outcome.failure.empty()      ? "then failed: " + last->outcome.failure
                            : last != best                      ? "tighter settings no better (round-off)"
                            : last->timing.median_seconds > 0.5 ? "the time cap"
                                                                : "the tightest setting tried";
    out += (out.empty() ? "" : "; ") + c.name() + " best " + format_significant(best->error, 2) + " at " +
           format_significant(best->knob, 2) + ", " + why;
  }
  return out;
}

/// Our best time against the best peer's (both by `clock`), to reach `error`. With a
/// peer library missing from the build the best peer may be missing too: no figure
/// when none ran, and the figure names what it leaves out otherwise.
template <class PeerPick, class OursPick = bool (*)(const Curve&)>
TargetRow speed_row(const std::vector<Curve>& all, const std::string& what, double error, PeerPick peer_pick,
                    double goal, Clock clock, const std::vector<std::string>& peers_not_built,
                    OursPick ours_pick = is_ours_fastest) {
  TargetRow row;
  row.target = what;
  row.goal = ">= " + format_significant(goal, 2) + "x";
  const std::string missing = peers_not_built.empty() ? "" : "peer not built: " + joined(peers_not_built);
  if (std::none_of(all.begin(), all.end(), peer_pick)) {
    row.measured = "n/a";
    row.note = "not measured: " + (missing.empty() ? std::string("no peer in this run") : missing);
    return row;
  }
  const Best ours = best_time(all, error, ours_pick, clock);
  const Best peer = best_time(all, error, peer_pick, clock);
  if (!std::isfinite(peer.time) || !std::isfinite(ours.time)) {
    row.measured = "n/a";
    row.note = std::none_of(all.begin(), all.end(), ours_pick)
                   ? "not measured: not in this run (--cases, --integrators)"
               : !std::isfinite(ours.time) ? "none of our integrators reached the error"
                                           : "no peer reached the error: " + closest(all, peer_pick);
  } else {
    const double r = peer.time / ours.time;
    row.measured = ratio(r);
    row.met = r >= goal;
    row.note = ours.name + " " + seconds(ours.time) + " vs " + peer.name + " " + seconds(peer.time);
    const Best ours_other = best_time(all, error, ours_pick, other(clock));
    const Best peer_other = best_time(all, error, peer_pick, other(clock));
    if (std::isfinite(peer_other.time) && std::isfinite(ours_other.time))
      row.note += "; by " + std::string(clock_name(other(clock))) + " " + ratio(peer_other.time / ours_other.time);
  }
  if (!missing.empty()) row.note += row.met ? "; best of the peers built (" + missing + ")" : "; " + missing;
  return row;
}

}  // namespace

std::string Curve::name() const {
  std::string suffix;
  if (ours()) {
    suffix = "Case " + std::to_string(case_id);
    if (case_id == 3 && rhs == RhsKind::definition) suffix += ", definition RHS";
    if (case_id == 3 && rhs == RhsKind::general) suffix += ", general path";
  } else if (case_id == 1 && rhs == RhsKind::user) {
    suffix = "Case 1 DAE, user residual";
  } else {
    if (case_id != 3) suffix = "Case " + std::to_string(case_id) + ", ";
    suffix += rhs == RhsKind::user ? "user RHS" : "our RHS";
  }
  return label + " (" + suffix + ")";
}

std::vector<Curve> curves(const ScenarioResult& result) {
  std::vector<Curve> out;
  for (const AccuracyPoint& p : result.points) {
    auto it = std::find_if(out.begin(), out.end(), [&](const Curve& c) {
      return c.method == p.method && c.case_id == p.case_id && c.rhs == p.rhs;
    });
    if (it == out.end()) {
      out.push_back({p.method, p.library, p.label, p.case_id, p.rhs, {}});
      it = out.end() - 1;
    }
    it->points.push_back(&p);
  }
  return out;
}

std::optional<double> time_to_error(const Curve& curve, double error, Clock clock) {
  auto time_of = [clock](const AccuracyPoint* p) {
    return clock == Clock::wall ? p->timing.median_seconds : p->timing.cpu_median_seconds;
  };
  const AccuracyPoint* previous = nullptr;
  for (const AccuracyPoint* p : curve.points) {
    const bool ok = std::isfinite(p->error);
    if (ok && p->error <= error) {
      const double t = time_of(p);
      if (previous == nullptr || p->error <= 0 || previous->error == p->error || time_of(previous) <= 0 || t <= 0)
        return t;
      // log-log interpolation between the setting above the error and this one
      const double le0 = std::log(previous->error), le1 = std::log(p->error);
      const double lt0 = std::log(time_of(previous)), lt1 = std::log(t);
      return std::exp(lt0 + (std::log(error) - le0) * (lt1 - lt0) / (le1 - le0));
    }
    previous = ok ? p : nullptr;
  }
  return std::nullopt;
}

const AccuracyPoint* overhead_point(const Curve& curve, double error) {
  const AccuracyPoint* last = nullptr;
  for (const AccuracyPoint* p : curve.points) {
    if (!p->outcome.failure.empty() || !std::isfinite(p->error)) continue;
    if (p->error <= error) return p;
    last = p;
  }
  return last;
}

std::vector<TargetRow> evaluate_targets(const ScenarioResult& fast, const RhsTimings& rhs, Clock clock,
                                        const std::vector<std::string>& peers_not_built) {
  const std::string by = std::string(" (") + clock_name(clock) + ")";
  const std::string by_other = std::string("; by ") + clock_name(other(clock)) + " ";
  std::vector<TargetRow> rows;
  const double fast_ns = pick(rhs.case3_fast, clock);
  rows.push_back({"Case 3 right-hand side, closed form incl. 2 sincos" + by, ns(fast_ns), "<= 40 ns", fast_ns <= 40.0,
                  "user's hand-typed 4x4 + Eigen partialPivLu: " + ns(pick(rhs.case3_user, clock)) + " (" +
                      ratio(pick(rhs.case3_user, clock) / fast_ns) + "); definition + block solve: " +
                      ns(pick(rhs.case3_definition, clock)) + by_other + ns(pick(rhs.case3_fast, other(clock)))});
  rows.push_back({"Case 3 4x4 solve alone, block solve" + by, ns(pick(rhs.solve_blocks, clock)), "(info)", std::nullopt,
                  "Eigen partialPivLu on the same matrices: " + ns(pick(rhs.solve_lu, clock))});

  const std::vector<Curve> all = curves(fast);
  auto peer_user = [](const Curve& c) { return !c.ours() && c.rhs == RhsKind::user; };
  auto peer_ours = [](const Curve& c) { return !c.ours() && c.rhs != RhsKind::user; };
  for (const double error : {1e-8, 1e-10}) {
    const std::string e = format_significant(error, 1);
    rows.push_back(speed_row(all, "time to error " + e + ": best peer with user RHS / our best" + by, error, peer_user,
                             error == 1e-8 ? 4.0 : 3.0, clock, peers_not_built));
    rows.push_back(speed_row(all, "time to error " + e + ", RHS shared: best peer with our RHS / our best" + by, error,
                             peer_ours, 1.0, clock, peers_not_built));
  }

  // The homework as simulate runs it: two-blocks.toml on the general path.
  const std::string path = rhs.general_evaluator.empty() ? "" : ", " + rhs.general_evaluator;
  for (const double error : {1e-8, 1e-10}) {
    rows.push_back(speed_row(all,
                             "general path" + path + ", time to error " + format_significant(error, 1) +
                                 ": best peer with user RHS / ours" + by,
                             error, peer_user, error == 1e-8 ? 4.0 : 3.0, clock, peers_not_built, is_ours_general));
  }

  const std::string oscillators = ns(pick(rhs.oscillators, clock));
  for (const OverheadTiming& o : fast.overhead) {
    TargetRow row;
    row.target = "integrator overhead per RHS evaluation, " + o.label + by;
    row.goal = "< 15 ns";
    const double v = pick(o.per_evaluation, clock);
    row.measured = ns(v);
    row.met = v < 15.0;
    const std::string setting =
        o.adaptive ? "rtol = atol = " + format_significant(o.knob, 2) : format_significant(o.knob, 6) + " steps";
    row.note = "run time / evaluations on 4 uncoupled oscillators (8 values; that RHS alone " + oscillators +
               ", included), " + std::to_string(o.evaluations) + " evaluations at " + setting +
               " as on Case 3 (error " + format_significant(o.homework_error, 2) + ")" + by_other +
               ns(pick(o.per_evaluation, other(clock)));
    rows.push_back(row);
    if (o.dynamic_per_evaluation) {
      TargetRow dynamic;
      dynamic.target = "integrator overhead per RHS evaluation, " + o.label + ", dynamic-size state" + by;
      dynamic.goal = "< 15 ns";
      const double d = pick(*o.dynamic_per_evaluation, clock);
      dynamic.measured = ns(d);
      dynamic.met = d < 15.0;
      dynamic.note = "the same run on Eigen::VectorXd, as a mechanism file's state (simulate)" + by_other +
                     ns(pick(*o.dynamic_per_evaluation, other(clock)));
      if (o.closed_form_fixed && o.closed_form_dynamic) {
        // What the dynamic-size state costs a right-hand side that does real work: on the
        // oscillators the fixed-size run fuses their few additions into the stages.
        const double fixed = pick(*o.closed_form_fixed, clock), dyn = pick(*o.closed_form_dynamic, clock);
        dynamic.note +=
            "; on Case 3's closed form (real work per evaluation) the dynamic-size state with the "
            "right-hand side called out of line takes " +
            ns(dyn) + " an evaluation against " + ns(fixed) + " fixed-size and inline (" + ratio(dyn / fixed) + ")";
      }
      rows.push_back(dynamic);
    }
  }
  return rows;
}

}  // namespace linkage::bench
