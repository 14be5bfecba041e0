#include "integrate/mechanism_simulation.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "integrate/adaptive_rk.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/kinematic_path.hpp"
#include "integrate/load_guard.hpp"
#include "integrate/step_budget.hpp"
#include "integrate/symplectic_euler.hpp"
#include "integrate/vern7.hpp"

namespace linkage {

namespace {

using Vector = Eigen::VectorXd;
constexpr int kDynamic = Eigen::Dynamic;
// A loop whose constraint error passes this, in metres (or radians), has come apart: the
// numbers no longer describe the mechanism.
constexpr double kOpenLoop = 1e-3;
// A driven run whose step fails with the kept rows' Jacobian this close to losing rank
// (smallest over largest singular value) has been driven past its range: J's smallest
// singular value falls as the square root of the distance to a limit position, so a step
// underflowing to round-off there leaves it near sqrt of a step's relative size.
constexpr double kDrivenPastItsRange = 1e-4;
// The largest |C| (m, rad) at which a projected state counts as closed.
constexpr double kClosed = 1e-10;

/// f(t, y) for the integrators; remembers where the case's matrix was singular, and the
/// first load out of its range where y' stopped being finite (a stage a step may reject).
struct Rhs {
  const eval::MechanismDynamics* dynamics;
  LoadGuard* loads;
  double singular_at = std::numeric_limits<double>::quiet_NaN();
  std::string bad_load;
  void operator()(double t, const Vector& y, Vector& dydt) {
    if (!dynamics->derivative(t, y, dydt) && std::isnan(singular_at)) singular_at = t;
    if (bad_load.empty() && !loads->empty() && !dydt.allFinite()) bad_load = loads->check(t, y);
  }
};

std::string case_text(const SimulationOptions& o) {
  return std::string(info(o.integrator).name) + ", Case " + std::to_string(o.case_id);
}

/// Ends a run that cannot go on: one line naming the time, the step (when one failed), the
/// case and integrator, what happened and what to try.
[[noreturn]] void fail(const SimulationOptions& o, const std::string& what, const std::string& hint, double t,
                       double h = std::nan("")) {
  throw Error::diverged("the simulation failed at t = " + format_significant(t, 6) + " s" +
                        (std::isnan(h) ? std::string() : " with step " + format_significant(h, 3) + " s") + " (" +
                        case_text(o) + "): " + what + "; " + hint);
}

}  // namespace

struct MechanismSimulation::Impl {
  Impl(const sym::System& system, const GiNaC::exmap& initial, const SimulationOptions& o,
       std::optional<CaseSystem> derived)
      : options(o),
        system_ptr(&system),
        mechanism(&system.mechanism()),
        dynamics(system, static_cast<CaseId>(o.case_id), std::move(derived)),
        loads(system, dynamics),
        rhs{&dynamics, &loads, std::nan(""), {}} {
    // Kinematic analysis integrates nothing: the stabilization has nothing to stabilize.
    stats.kinematic = dynamics.kinematic();
    if (o.stabilization == Stabilization::baumgarte && !stats.kinematic)
      dynamics.set_baumgarte(o.baumgarte_alpha, o.baumgarte_beta);
    stats.evaluator = choose_evaluator(dynamics, o);
    project = o.stabilization == Stabilization::projection && dynamics.constraint_rows() > 0 && !stats.kinematic;
    y = dynamics.initial_state(initial);
    if (stats.kinematic) kinematic = std::make_unique<KinematicPath>(system, dynamics, y);
    Vector dydt;
    if (!dynamics.derivative(0, y, dydt))
      throw Error::input(system.mechanism().source + ": the matrix of Case " + std::to_string(o.case_id) +
                         " is singular at the initial state (a dead point or change point): the equations do "
                         "not fix the accelerations there; start from another state");
    eval::MechanismSample s;
    dynamics.sample(0, y, s);
    energy0 = s.kinetic + s.potential;
    // The energy scale: T + |V - V_gravity| + sum_i m_i |g| (|y_i| + h_i), h_i the body's
    // half-length (rectangle, rod: length/2; disc: radius; point: 0), so that a body's
    // weight counts over the height it could fall; on two-blocks the homework's
    // T + m g (|y1| + |y2| + L).
    const auto number = [&](const GiNaC::ex& e) {
      return sym::to_double(e.subs(system.constants()).subs(system.constants()).subs(system.parameter_values()));
    };
    double g = 0;
    if (system.mechanism().gravity) g = number(system.quantity(*system.mechanism().gravity, false));
    double total_mass = 0, gravity_potential = 0, fall = 0;
    for (std::size_t i = 0; i < system.bodies().size(); ++i) {
      const double m = number(system.bodies()[i].mass), y_i = s.pose[3 * i + 1];
      const Body& body = system.mechanism().bodies[i];
      double half = 0;
      switch (body.shape) {
        case Shape::rectangle:
        case Shape::rod:
          if (body.length) half = number(system.quantity(*body.length, false)) / 2;
          break;
        case Shape::disc:
        case Shape::ring:
          if (body.radius) half = number(system.quantity(*body.radius, false));
          break;
        case Shape::point:
          break;
      }
      total_mass += m;
      gravity_potential += m * g * y_i;
      fall += m * std::fabs(g) * (std::fabs(y_i) + std::fabs(half));
    }
    stats.energy_scale = s.kinetic + std::fabs(s.potential - gravity_potential) + fall;
    stats.drift_allowed = system.tree().loop_joints.empty();
    for (const Body& b : system.mechanism().bodies)
      for (const auto& [size, what] : {std::pair{&b.length, "length"}, std::pair{&b.radius, "radius"}})
        if (*size && std::fabs(number(system.quantity(**size, false))) > stats.size) {
          stats.size = std::fabs(number(system.quantity(**size, false)));
          stats.size_name = "body " + b.name + "'s " + what + " " + (*size)->text;
        }
    if (!(stats.energy_scale > 0)) stats.energy_scale = 1;  // nothing moves and nothing pulls: report in J
    origin = {energy0, stats.energy_scale, s.momentum_x, s.momentum_y, s.angular_momentum, s.com, total_mass * g, g};
    if (kinematic) {
      kinematic->set_energy_scale(stats.energy_scale);
      return;
    }
    if (project) dynamics.project(0, y);
    start_stepper();
  }

  void start_stepper();
  void advance(double t);
  /// Every kCheckInterval steps: lets Ctrl-C stop the run and reports progress. True on those steps.
  bool after_step(double t) {
    if (++steps % kCheckInterval != 0) return false;
    throw_if_interrupted();
    if (report) report(t);
    return true;
  }
  void check_loop(double t) {
    if (dynamics.constraint_rows() == 0 || (stats.drift_allowed && !project)) return;
    const double violation = project ? dynamics.project(t, y) : dynamics.constraint_violation(t, y);
    if (violation > kOpenLoop) stop_if_past_range(t);
    if (violation > kOpenLoop)
      fail(options,
           "joint " + dynamics.worst_joint(t, y) + " came " + format_significant(violation, 2) +
               " m apart (the loop opened)",
           project ? "try a smaller step or tighter rtol/atol" : "try stabilization by projection", t);
  }
  /// A driven run that failed by t with fixed steps, which jump over the limit the
  /// adaptive ones meet, or reached a sample `at_t` at t: when the loops cannot close at t
  /// with the drivers on their motion, stops with the limit's one line at the last time
  /// they close, found by marching from the last sample's state in steps of dt (each
  /// closed from the one before, so Newton starts near) and bisecting the step they fail in.
  void stop_if_past_range(double t, const Vector* at_t = nullptr) {
    if (mechanism->drivers.empty() || dynamics.constraint_rows() == 0 || info(options.integrator).adaptive ||
        !anchor.allFinite())
      return;
    Vector trial;
    const auto closes = [&](const Vector& from, double when) {
      trial = from;
      return dynamics.project(when, trial) <= kClosed;
    };
    if (at_t != nullptr && closes(*at_t, t)) return;
    // A step may have carried the sample past the limit already: back from it until the
    // loops close (the anchor's q is near the limit, so Newton starts near there too).
    double a = anchor_t;
    for (double back = options.dt; !closes(anchor, a); back *= 2) {
      if (a <= 0) return;
      a = std::max(0.0, anchor_t - back);
    }
    Vector closed = trial;
    double b = a;
    for (;;) {
      if (a >= t) return;  // they close all the way to t: no limit
      b = std::min(t, a + options.dt);
      if (!closes(closed, b)) break;
      a = b;
      closed = trial;
    }
    while (b - a > 1e-12 * std::max(1.0, b)) {
      const double m = (a + b) / 2;
      if (closes(closed, m)) {
        a = m;
        closed = trial;
      } else {
        b = m;
      }
    }
    stop_at_limit(a, closed);
  }
  [[noreturn]] void stop_at_limit(double t, const Vector& at) {
    throw Error::input(driven_stop_message(
        *system_ptr, t, past_the_limit(*system_ptr, dynamics, t, at) + "; " + case_text(options) + ")"));
  }
  [[noreturn]] void fail_step(ode::StepStatus status, double t, double h) {
    if (!rhs.bad_load.empty()) throw Error::input(rhs.bad_load);
    stop_if_past_range(t + (std::isnan(h) ? 0.0 : h));
    // Driven past the mechanism's range: the kept rows' Jacobian has nearly lost rank where
    // the step failed (a limit position or toggle), which no tolerance or step cures.
    if (!mechanism->drivers.empty() && dynamics.constraint_rows() > 0 && y.allFinite()) {
      if (dynamics.jacobian_spread(t, y) < kDrivenPastItsRange) stop_at_limit(t, y);
    }
    if (!std::isnan(rhs.singular_at))
      fail(options,
           "the matrix of Case " + std::to_string(options.case_id) +
               " turned singular at t = " + format_significant(rhs.singular_at, 6) +
               " s: the mechanism reached a dead point or change point where its equations do not fix the "
               "accelerations",
           "try another initial state, more inertia on the driving body, or a duration under " +
               format_significant(rhs.singular_at, 3) + " s",
           t, h);
    std::string what(ode::describe(status));
    if (info(options.integrator).adaptive && status != ode::StepStatus::newton_failed)
      what += "; the equations may be stiff or beyond double precision here";
    fail(options, what, failed_step_hint(options, dynamics.constraint_rows() > 0, status, t, h), t, h);
  }

  SimulationOptions options;
  const sym::System* system_ptr;
  const Mechanism* mechanism;
  eval::MechanismDynamics dynamics;
  LoadGuard loads;
  Rhs rhs;
  bool project = false;
  Vector y, sample_y;
  double energy0 = 0, last_t = 0;
  ColumnOrigin origin;  // the error columns' t = 0
  MechanismStats stats;
  std::function<void(double)> report;
  unsigned steps = 0;
  StepBudget budget;  // adaptive runs only
  // One of these steps, by the integrator chosen.
  std::unique_ptr<ode::ExplicitEuler<double, kDynamic>> euler;
  std::unique_ptr<ode::SymplecticEuler<double, kDynamic>> symplectic;
  std::unique_ptr<ode::Rk4<double, kDynamic>> rk4;
  std::unique_ptr<ode::GaussLegendre2<double, kDynamic>> gauss;
  std::unique_ptr<ode::Dopri5<double, kDynamic>> dopri5;
  std::unique_ptr<ode::Dop853<double, kDynamic>> dop853;
  std::unique_ptr<ode::Vern7<double, kDynamic>> vern7;
  std::int64_t k = 0;                        // fixed steps taken
  Vector anchor;                             // fixed steps: the state at the last sample's grid time,
  double anchor_t = 0;                       // and that time
  std::unique_ptr<KinematicPath> kinematic;  // instead of a step when the drivers take every degree of freedom
};

namespace {

// Right-hand sides a run is expected to take: duration / dt steps of the method's stages
// (dt the first step of an adaptive method, so an estimate from below).
double expected_evaluations(const SimulationOptions& o) {
  double stages = 1;
  switch (o.integrator) {
    case IntegratorKind::euler:
    case IntegratorKind::symplectic_euler:
      stages = 1;
      break;
    case IntegratorKind::rk4:
    case IntegratorKind::gauss2:
      stages = 4;
      break;
    case IntegratorKind::dopri5:
      stages = 6;
      break;
    case IntegratorKind::dop853:
      stages = 12;
      break;
    case IntegratorKind::vern7:
      stages = 10;
      break;
  }
  return o.duration / o.dt * stages;
}

}  // namespace

std::string choose_evaluator(eval::MechanismDynamics& dynamics, const SimulationOptions& o) {
  if (o.evaluator == Evaluator::interpreted) return "interpreted (as asked)";
  if (dynamics.attach_builtin(o.kinematics)) return "compiled (built in)";
  const auto compiled = [](const eval::NativeAttachment& a) {
    return std::string("compiled (") + (a.compiled ? "compiled into " : "cache ") + a.library.string() + ")";
  };
  if (o.evaluator == Evaluator::compiled) {
    const eval::NativeAttachment a = dynamics.attach_native();
    if (!a.attached)
      throw Error::invalid("evaluator", "'compiled' cannot run: " + a.reason + "; valid: auto, interpreted");
    return compiled(a);
  }
  // auto: a cached entry costs milliseconds; compiling pays only on very long runs.
  if (const eval::NativeAttachment a = dynamics.attach_native(o.kinematics, false); a.attached) return compiled(a);
  if (!eval::native_compiler_found()) return "interpreted (no C++ compiler on PATH)";
  if (expected_evaluations(o) < kCompileWorthEvaluations) return "interpreted (run too short to gain from compiling)";
  const eval::NativeAttachment a = dynamics.attach_native(o.kinematics);
  return a.attached ? compiled(a) : "interpreted (" + a.reason + ")";
}

void MechanismSimulation::Impl::start_stepper() {
  switch (options.integrator) {
    case IntegratorKind::euler:
      euler = std::make_unique<ode::ExplicitEuler<double, kDynamic>>();
      break;
    case IntegratorKind::symplectic_euler:
      symplectic = std::make_unique<ode::SymplecticEuler<double, kDynamic>>();
      break;
    case IntegratorKind::rk4:
      rk4 = std::make_unique<ode::Rk4<double, kDynamic>>();
      break;
    case IntegratorKind::gauss2:
      gauss = std::make_unique<ode::GaussLegendre2<double, kDynamic>>();
      break;
    case IntegratorKind::dopri5:
    case IntegratorKind::dop853:
    case IntegratorKind::vern7: {
      auto settings = [&](auto& stepper) {
        typename std::remove_reference_t<decltype(*stepper)>::Settings s;
        s.tolerances = {options.rtol, options.atol};
        s.first_step = options.dt;
        return s;
      };
      if (options.integrator == IntegratorKind::dopri5) {
        dopri5 = std::make_unique<ode::Dopri5<double, kDynamic>>(settings(dopri5));
        dopri5->start(rhs, 0.0, y);
      } else if (options.integrator == IntegratorKind::dop853) {
        dop853 = std::make_unique<ode::Dop853<double, kDynamic>>(settings(dop853));
        dop853->start(rhs, 0.0, y);
      } else {
        vern7 = std::make_unique<ode::Vern7<double, kDynamic>>(settings(vern7));
        vern7->start(rhs, 0.0, y);
      }
      break;
    }
  }
}

void MechanismSimulation::Impl::advance(double t) {
  if (kinematic) {
    kinematic->advance(t, y);
    loads.require(t, y);
    sample_y = y;
    return;
  }
  if (dopri5 || dop853 || vern7) {
    auto run = [&](auto& stepper) {
      while (stepper.t() < t) {
        const double from = stepper.t();
        const ode::StepStatus status = stepper.step(rhs);
        if (status != ode::StepStatus::ok) fail_step(status, stepper.t(), stepper.next_step());  // the failed attempt
        y = stepper.y();
        if (std::string bad = loads.check(stepper.t(), y); !bad.empty()) {
          // Where in the step the value left its range: bisection on the dense output.
          double a = from, b = stepper.t();
          Vector between;
          while (b - a > 1e-12 * std::max(1.0, b)) {
            const double m = (a + b) / 2;
            stepper.dense(rhs, m, between);
            if (std::string at_m = loads.check(m, between); at_m.empty()) {
              a = m;
            } else {
              b = m;
              bad = std::move(at_m);
            }
          }
          throw Error::input(bad);
        }
        check_loop(stepper.t());
        if (project) stepper.replace_state(rhs, y);
        if (!after_step(stepper.t())) continue;
        if (const auto overrun = budget.check(stepper.t(), stepper.counters().steps_accepted, options)) {
          fail(options, overrun->what + " (last step " + format_significant(stepper.last_step(), 3) + " s)",
               overrun->hint, stepper.t());
        }
      }
      stepper.dense(rhs, t, sample_y);
      if (project && t != stepper.t()) dynamics.project(t, sample_y);
      loads.require(t, sample_y);
    };
    if (dopri5)
      run(*dopri5);
    else if (dop853)
      run(*dop853);
    else
      run(*vern7);
    return;
  }
  // Fixed steps on the grid t_k = k dt; a sample between grid points is a short step
  // from the grid point before it, on a copy.
  const double dt = options.dt;
  auto take = [&](double from, double h, Vector& state) {
    ode::StepStatus status = ode::StepStatus::ok;
    if (euler) status = euler->step(rhs, from, h, state);
    if (symplectic) status = symplectic->step(rhs, from, h, state);
    if (rk4) status = rk4->step(rhs, from, h, state);
    if (gauss) status = gauss->step(rhs, from, h, state);
    if (status != ode::StepStatus::ok || !std::isnan(rhs.singular_at)) fail_step(status, from, h);
  };
  const double tolerance = 1e-9 * dt + 8 * std::numeric_limits<double>::epsilon() * t;
  auto n = static_cast<std::int64_t>(std::llround(t / dt));
  const bool on_grid = std::fabs(t - static_cast<double>(n) * dt) <= tolerance;
  if (!on_grid) n = static_cast<std::int64_t>(std::floor(t / dt));
  anchor = y;
  anchor_t = static_cast<double>(k) * dt;
  while (k < n) {
    take(static_cast<double>(k) * dt, dt, y);
    ++k;
    loads.require(static_cast<double>(k) * dt, y);
    check_loop(static_cast<double>(k) * dt);
    after_step(static_cast<double>(k) * dt);
  }
  sample_y = y;
  if (!on_grid) {
    const double t_grid = static_cast<double>(k) * dt;
    // A fresh stepper of the same method: what one keeps between steps (Gauss-Legendre's
    // Newton start) never sees the samples.
    auto partial = [&](const auto& stepper) {
      if (!stepper) return;
      std::remove_cvref_t<decltype(*stepper)> fresh;
      const ode::StepStatus status = fresh.step(rhs, t_grid, t - t_grid, sample_y);
      if (status != ode::StepStatus::ok || !std::isnan(rhs.singular_at)) fail_step(status, t_grid, t - t_grid);
    };
    partial(euler);
    partial(symplectic);
    partial(rk4);
    partial(gauss);
    if (project) dynamics.project(t, sample_y);
    loads.require(t, sample_y);
  }
  // A fixed step may carry a driven mechanism past its limit with its loops still near
  // closed (a drift under kOpenLoop): no sample is written from there.
  if (!mechanism->drivers.empty() && dynamics.constraint_rows() > 0) stop_if_past_range(t, &sample_y);
}

MechanismSimulation::MechanismSimulation(const sym::System& system, const GiNaC::exmap& initial,
                                         const SimulationOptions& options, std::optional<CaseSystem> derived) {
  options.validate();
  impl_ = std::make_unique<Impl>(system, initial, options, std::move(derived));
}

MechanismSimulation::~MechanismSimulation() = default;
MechanismSimulation::MechanismSimulation(MechanismSimulation&&) noexcept = default;
MechanismSimulation& MechanismSimulation::operator=(MechanismSimulation&&) noexcept = default;

const Eigen::VectorXd& MechanismSimulation::state_at(double t) {
  Impl& run = *impl_;
  if (!(t >= run.last_t && t <= run.options.duration))
    throw Error::failure("state_at(" + format_roundtrip(t) + "): times must be non-decreasing and within [0, " +
                         format_roundtrip(run.options.duration) + "] s");
  const auto start = std::chrono::steady_clock::now();
  struct Count {
    Impl& run;
    std::chrono::steady_clock::time_point start;
    ~Count() {
      ode::Counters c;
      if (run.euler) c = run.euler->counters();
      if (run.symplectic) c = run.symplectic->counters();
      if (run.rk4) c = run.rk4->counters();
      if (run.gauss) c = run.gauss->counters();
      if (run.dopri5) c = run.dopri5->counters();
      if (run.dop853) c = run.dop853->counters();
      if (run.vern7) c = run.vern7->counters();
      if (run.kinematic) c = {run.kinematic->accepted(), run.kinematic->rejected(), run.kinematic->solves()};
      run.stats.steps_accepted = c.steps_accepted;
      run.stats.steps_rejected = c.steps_rejected;
      run.stats.rhs_evaluations = c.rhs_evaluations;
      run.stats.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } count{run, start};
  run.advance(t);
  run.last_t = t;
  return run.sample_y;
}

void MechanismSimulation::sample(double t, const Eigen::VectorXd& y, eval::MechanismSample& out, bool kinematics) {
  Impl& run = *impl_;
  run.dynamics.sample(t, y, out, kinematics);
  const double work = eval::work_of(y);
  const double balance = std::fabs(out.kinetic + out.potential - run.energy0 - work) / run.stats.energy_scale;
  run.stats.max_energy_error = std::max(run.stats.max_energy_error, balance);
  for (std::size_t j = 0; j < out.constraint.size(); ++j)
    if (out.constraint[j] > run.stats.max_constraint_error) {
      run.stats.max_constraint_error = out.constraint[j];
      run.stats.drifted_joint = run.mechanism->joints[j].name;
    }
}

void MechanismSimulation::on_progress(std::function<void(double)> report) { impl_->report = std::move(report); }
const eval::MechanismDynamics& MechanismSimulation::dynamics() const { return impl_->dynamics; }
const MechanismStats& MechanismSimulation::stats() const { return impl_->stats; }
double MechanismSimulation::energy0() const { return impl_->energy0; }
const ColumnOrigin& MechanismSimulation::origin() const { return impl_->origin; }
const SimulationOptions& MechanismSimulation::options() const { return impl_->options; }

std::string mechanism_result_warning(const SimulationOptions& o, const MechanismStats& st) {
  const double scale = st.size > 0 ? st.size : 1.0;  // m, when no body has a size
  std::string energy, drift;
  if (st.max_energy_error > kMeaninglessEnergyError)
    energy = "the energy balance is off by " + format_significant(st.max_energy_error, 2) +
             " times the energy scale (" + format_significant(st.energy_scale, 3) + " J)";
  if (st.drift_allowed && st.max_constraint_error > kMeaninglessDrift * scale)
    drift = "joint " + st.drifted_joint + " came " + format_significant(st.max_constraint_error, 2) + " m apart" +
            (st.size > 0 ? " (" + format_significant(st.max_constraint_error / st.size, 2) + " of " + st.size_name + ")"
                         : std::string());
  return meaningless_run_warning(o, energy, drift);
}

}  // namespace linkage
