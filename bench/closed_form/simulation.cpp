#include "bench/closed_form/simulation.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/closed_form/projection.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "integrate/adaptive_rk.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/step_budget.hpp"
#include "integrate/symplectic_euler.hpp"
#include "integrate/vern7.hpp"

namespace linkage {

// --- the runs -----------------------------------------------------------------------

namespace {

/// Ends a run that cannot go on: one line naming the time, the step, the case and
/// integrator, what happened and what to try.
[[noreturn]] void fail(const SimulationOptions& o, std::string_view what, const std::string& hint, double t, double h) {
  throw Error::diverged("the simulation failed at t = " + format_significant(t, 6) + " s with step " +
                        format_significant(h, 3) + " s (" + std::string(info(o.integrator).name) + ", Case " +
                        std::to_string(o.case_id) + "): " + std::string(what) + "; " + hint);
}

[[noreturn]] void fail(const SimulationOptions& o, ode::StepStatus status, double t, double h) {
  std::string what(ode::describe(status));
  if (info(o.integrator).adaptive && status != ode::StepStatus::newton_failed)
    what += "; the equations may be stiff or beyond double precision here";
  fail(o, what, failed_step_hint(o, o.case_id == 1, status, t, h), t, h);
}

/// A run of one case with one integrator; the stepping lives in the two subclasses.
class Run {
 public:
  Run(const Params& p, const State& initial, const SimulationOptions& o)
      : params(p), options(o), start(body_state(p, initial)) {
    const Invariants inv = invariants(p, start);
    energy0 = inv.energy;
    stats.energy_scale = energy_scale(p, start);
  }
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;
  virtual ~Run() = default;

  /// The state at t >= the last sample's time.
  virtual BodyState advance(double t) = 0;
  virtual Dynamics dynamics(const BodyState& s) const = 0;
  [[nodiscard]] virtual ode::Counters counters() const = 0;

  Params params;
  SimulationOptions options;
  BodyState start;
  double energy0 = 0;
  double last_t = 0;
  SimulationStats stats;
  std::function<void(double)> report;  // progress, with the integrator's time
};

/// Everything that depends on the case: its right-hand side, the map between the
/// integrated vector and BodyState, accelerations and pin force for output.
template <class Case>
struct CaseModel;

template <class Case>
struct GeneralizedModel {
  using Rhs = GeneralizedRhs<Case>;
  using Vector = Vec<8>;
  static constexpr bool can_drift = false;
  static Rhs make_rhs(const Params& p, const SimulationOptions& /*o*/) { return Rhs(p); }
  static Vector to_vector(const BodyState& s) { return s.generalized().vector(); }
  static BodyState to_body(const Params& p, const Vector& y) { return body_state(p, State::from_vector(y)); }
  static Dynamics dynamics(const Params& p, const Rhs& rhs, const BodyState& s) {
    const Vec<Case::size> q = rhs.unknowns(to_vector(s));
    Dynamics d;
    d.x1_ddot = q[0];
    d.y1_ddot = q[1];
    d.theta1_ddot = q[2];
    d.theta2_ddot = q[3];
    if constexpr (Case::size == 6) {
      d.F_x = q[4];
      d.F_y = q[5];
    } else {  // Case 3 eliminated the pin force with (1.2), (2.2)
      d.F_x = p.m * d.x1_ddot;
      d.F_y = p.m * (d.y1_ddot + p.g);
    }
    d.x2_ddot = -d.F_x / p.m;        // (4.1)
    d.y2_ddot = -p.g - d.F_y / p.m;  // (5.1)
    return d;
  }
};

template <>
struct CaseModel<Case3> : GeneralizedModel<Case3> {};
template <>
struct CaseModel<Case2> : GeneralizedModel<Case2> {};

template <>
struct CaseModel<Case1> {
  using Rhs = MaximalRhs;
  using Vector = Vec<12>;
  static constexpr bool can_drift = true;
  static Rhs make_rhs(const Params& p, const SimulationOptions& o) {
    const bool on = o.stabilization == Stabilization::baumgarte;
    return Rhs(p, on ? o.baumgarte_alpha : 0.0, on ? o.baumgarte_beta : 0.0);
  }
  static Vector to_vector(const BodyState& s) { return s.vector(); }
  static BodyState to_body(const Params& /*p*/, const Vector& y) { return BodyState::from_vector(y); }
  static Dynamics dynamics(const Params& /*p*/, const Rhs& rhs, const BodyState& s) {
    const Vec<8> q = rhs.unknowns(s.vector());
    return {q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]};
  }
};

/// The parts of a run shared by fixed-step and adaptive stepping.
template <class Case>
class CaseRun : public Run {
 protected:
  using Model = CaseModel<Case>;
  using Vector = typename Model::Vector;

  CaseRun(const Params& p, const State& initial, const SimulationOptions& o)
      : Run(p, initial, o),
        rhs_(Model::make_rhs(p, o)),
        project_(Model::can_drift && o.stabilization == Stabilization::projection) {}

  Dynamics dynamics(const BodyState& s) const override { return Model::dynamics(params, rhs_, s); }

  /// Projects a Case 1 vector onto the constraint when asked to; fails the run if the
  /// projection does not converge.
  void stabilize(Vector& y, double t, double h) const {
    if constexpr (Model::can_drift) {
      if (project_ && !project_onto_constraint(params, y).converged)
        fail(options, "the projection onto the pin constraint did not converge",
             info(options.integrator).adaptive ? "try a tighter rtol/atol" : "try a smaller step dt", t, h);
    }
  }

  /// After each step: every kCheckInterval steps, lets Ctrl-C stop the run and reports
  /// progress at time t. True on those steps.
  bool after_step(double t) {
    if (++steps_ % kCheckInterval != 0) return false;
    throw_if_interrupted();
    if (report) report(t);
    return true;
  }

  typename Model::Rhs rhs_;
  bool project_;
  unsigned steps_ = 0;
};

/// Fixed steps on the grid t_k = k dt. A sample between grid points is a shorter step
/// from the grid point before it, taken on a copy, so the grid run is never disturbed.
template <class Case, class Stepper>
class FixedStepRun final : public CaseRun<Case> {
  using Base = CaseRun<Case>;
  using typename Base::Model;
  using typename Base::Vector;

 public:
  FixedStepRun(const Params& p, const State& initial, const SimulationOptions& o) : Base(p, initial, o) {
    y_ = Model::to_vector(this->start);
    this->stabilize(y_, 0, o.dt);
  }

  BodyState advance(double t) override {
    const double dt = this->options.dt;
    const double tolerance = 1e-9 * dt + 8 * std::numeric_limits<double>::epsilon() * t;
    auto n = static_cast<std::int64_t>(std::llround(t / dt));
    const bool on_grid = std::fabs(t - static_cast<double>(n) * dt) <= tolerance;
    if (!on_grid) n = static_cast<std::int64_t>(std::floor(t / dt));
    while (k_ < n) {
      take(stepper_, y_, static_cast<double>(k_) * dt, dt);
      ++k_;
      this->after_step(static_cast<double>(k_) * dt);
    }
    if (on_grid) return Model::to_body(this->params, y_);
    Vector sample = y_;
    const double t_grid = static_cast<double>(k_) * dt;
    take(partial_, sample, t_grid, t - t_grid);
    return Model::to_body(this->params, sample);
  }

  [[nodiscard]] ode::Counters counters() const override {
    ode::Counters c = stepper_.counters();
    const ode::Counters& p = partial_.counters();
    c.steps_accepted += p.steps_accepted;
    c.rhs_evaluations += p.rhs_evaluations;
    c.newton_iterations += p.newton_iterations;
    return c;
  }

 private:
  void take(Stepper& stepper, Vector& y, double t, double h) {
    const ode::StepStatus status = stepper.step(this->rhs_, t, h, y);
    if (status != ode::StepStatus::ok) fail(this->options, status, t, h);
    this->stabilize(y, t + h, h);
  }

  // The grid run, and the short steps to samples between grid points: separate, so
  // what one method keeps between steps (Gauss-Legendre's Newton start) never sees
  // the samples.
  Stepper stepper_, partial_;
  Vector y_;
  std::int64_t k_ = 0;
};

/// Adaptive steps chosen by the error controller; samples come from dense output.
template <class Case, class Stepper>
class AdaptiveRun final : public CaseRun<Case> {
  using Base = CaseRun<Case>;
  using typename Base::Model;
  using typename Base::Vector;

 public:
  AdaptiveRun(const Params& p, const State& initial, const SimulationOptions& o)
      : Base(p, initial, o), stepper_(settings(o)) {
    Vector y0 = Model::to_vector(this->start);
    this->stabilize(y0, 0, o.dt);
    stepper_.start(this->rhs_, 0.0, y0);
  }

  BodyState advance(double t) override {
    while (stepper_.t() < t) {
      const ode::StepStatus status = stepper_.step(this->rhs_);
      if (status != ode::StepStatus::ok) fail(this->options, status, stepper_.t(), stepper_.next_step());
      if (this->project_) {
        Vector y = stepper_.y();
        this->stabilize(y, stepper_.t(), stepper_.last_step());
        stepper_.replace_state(this->rhs_, y);
      }
      if (this->after_step(stepper_.t())) check_budget();
    }
    Vector sample;
    stepper_.dense(this->rhs_, t, sample);
    if (t != stepper_.t()) this->stabilize(sample, t, stepper_.last_step());
    return Model::to_body(this->params, sample);
  }

  [[nodiscard]] ode::Counters counters() const override { return stepper_.counters(); }

 private:
  static typename Stepper::Settings settings(const SimulationOptions& o) {
    typename Stepper::Settings s;
    s.tolerances = {o.rtol, o.atol};
    s.first_step = o.dt;
    return s;
  }

  void check_budget() {
    const auto overrun = budget_.check(stepper_.t(), stepper_.counters().steps_accepted, this->options);
    if (overrun) fail(this->options, overrun->what, overrun->hint, stepper_.t(), stepper_.last_step());
  }

  Stepper stepper_;
  StepBudget budget_;
};

template <class Case>
std::unique_ptr<Run> make_run(const Params& p, const State& initial, const SimulationOptions& o) {
  constexpr int n = state_size<Case>;
  switch (o.integrator) {
    case IntegratorKind::euler:
      return std::make_unique<FixedStepRun<Case, ode::ExplicitEuler<double, n>>>(p, initial, o);
    case IntegratorKind::symplectic_euler:
      return std::make_unique<FixedStepRun<Case, ode::SymplecticEuler<double, n>>>(p, initial, o);
    case IntegratorKind::rk4:
      return std::make_unique<FixedStepRun<Case, ode::Rk4<double, n>>>(p, initial, o);
    case IntegratorKind::gauss2:
      return std::make_unique<FixedStepRun<Case, ode::GaussLegendre2<double, n>>>(p, initial, o);
    case IntegratorKind::dopri5:
      return std::make_unique<AdaptiveRun<Case, ode::Dopri5<double, n>>>(p, initial, o);
    case IntegratorKind::dop853:
      return std::make_unique<AdaptiveRun<Case, ode::Dop853<double, n>>>(p, initial, o);
    case IntegratorKind::vern7:
      return std::make_unique<AdaptiveRun<Case, ode::Vern7<double, n>>>(p, initial, o);
  }
  throw Error::failure("unknown integrator kind");
}

/// Runs a callable and adds its duration to `seconds`.
template <class F>
auto timed(double& seconds, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  struct Add {
    double& total;
    std::chrono::steady_clock::time_point start;
    ~Add() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  } add{seconds, start};
  return f();
}

}  // namespace

struct Simulation::Impl {
  std::unique_ptr<Run> run;
};

// --- Simulation ---------------------------------------------------------------------

Simulation::Simulation(const Params& params, const State& initial, const SimulationOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  switch (options.case_id) {
    case 1:
      impl_->run = make_run<Case1>(params, initial, options);
      break;
    case 2:
      impl_->run = make_run<Case2>(params, initial, options);
      break;
    default:
      impl_->run = make_run<Case3>(params, initial, options);
      break;
  }
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

BodyState Simulation::state_at(double t) {
  Run& run = *impl_->run;
  if (!(t >= run.last_t && t <= run.options.duration))
    throw Error::failure("state_at(" + format_roundtrip(t) + "): times must be non-decreasing and within [0, " +
                         format_roundtrip(run.options.duration) + "] s");
  // The work done is counted even when the run fails part way.
  struct CountWork {
    Run& run;
    ~CountWork() {
      const ode::Counters c = run.counters();
      run.stats.steps_accepted = c.steps_accepted;
      run.stats.steps_rejected = c.steps_rejected;
      run.stats.rhs_evaluations = c.rhs_evaluations;
    }
  };
  const BodyState s = [&] {
    const CountWork count{run};
    return timed(run.stats.wall_seconds, [&] { return run.advance(t); });
  }();
  run.last_t = t;
  const double energy_error = std::fabs(invariants(run.params, s).energy - run.energy0) / run.stats.energy_scale;
  const double constraint = constraint_error(run.params, s).position.norm();
  run.stats.max_energy_error = std::max(run.stats.max_energy_error, energy_error);
  run.stats.max_constraint_error = std::max(run.stats.max_constraint_error, constraint);
  return s;
}

Dynamics Simulation::dynamics(const BodyState& state) {
  Run& run = *impl_->run;
  ++run.stats.force_evaluations;
  return timed(run.stats.wall_seconds, [&] { return run.dynamics(state); });
}

void Simulation::on_progress(std::function<void(double)> report) { impl_->run->report = std::move(report); }

const SimulationStats& Simulation::stats() const { return impl_->run->stats; }

const Params& Simulation::params() const { return impl_->run->params; }
const SimulationOptions& Simulation::options() const { return impl_->run->options; }

// --- results that mean nothing ------------------------------------------------------

std::string result_warning(const SimulationOptions& o, const Params& p, const SimulationStats& st) {
  std::string energy, pin;
  if (st.max_energy_error > kMeaninglessEnergyError)
    energy = "the energy error reached " + format_significant(st.max_energy_error, 2) + " times the energy scale (" +
             format_significant(st.energy_scale, 3) + " J)";
  if (st.max_constraint_error > kMeaninglessDrift * p.L)
    pin = "the pin came " + format_significant(st.max_constraint_error, 2) + " m apart (" +
          format_significant(st.max_constraint_error / p.L, 2) + " of the block length L)";
  return meaningless_run_warning(o, energy, pin);
}

}  // namespace linkage
