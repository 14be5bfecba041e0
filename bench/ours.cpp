// Our integrators (src/integrate) as methods of the work-precision study, driven the
// way the tool drives them: fixed-step methods take n equal steps; adaptive ones take
// their own steps past the end and return the dense-output state at it (they never
// shorten a step to hit a time). Case 3 uses its fastest right-hand side, the closed
// form of case3_fast.hpp; Cases 1 and 2 the block solve of their definition (Case 1
// without stabilization, so its drift shows). DOP853 also runs Case 3 on the
// definition's right-hand side, to show what the closed form buys; every integrator also
// runs Case 3 on the general path (two-blocks.toml through MechanismDynamics with native
// code, general_rhs.hpp), the path the homework takes in simulate, on simulate's
// dynamic-size state.
#include <string>

#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/general_rhs.hpp"
#include "bench/method.hpp"
#include "bench/rhs.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/symplectic_euler.hpp"
#include "integrate/vern7.hpp"

namespace linkage::bench {
namespace {

constexpr std::int64_t kMaxAdaptiveSteps = 100'000'000;

// A run's state: Case 1's 12 values, Case 3's 8, or (Eigen::Dynamic) the general path's
// mechanism state, those 8 and W, as simulate integrates it.
template <int N>
BodyState to_body(const Params& p, const Vec<N>& y) {
  if constexpr (N == 12)
    return BodyState::from_vector(y);
  else
    return body_state(p, State::from_vector(y.template head<8>()));
}

template <int N, class F>
Vec<N> initial_vector(const F& f, const Scenario& s) {
  if constexpr (N == 8)
    return s.initial.vector();
  else if constexpr (N == 12)
    return body_state(s.params, s.initial).vector();
  else
    return f.state(s.initial.vector());
}

void fill_counters(const ode::Counters& c, Outcome& out) {
  out.rhs_evaluations = c.rhs_evaluations;
  out.steps = c.steps_accepted;
  out.rejected = c.steps_rejected;
}

template <class Integrator, int N, class F>
Outcome run_fixed(F f, const Scenario& s, double knob) {
  const auto n = static_cast<std::int64_t>(knob);
  const double h = s.duration / static_cast<double>(n);
  Integrator integrator;
  Vec<N> y = initial_vector<N>(f, s);
  Outcome out;
  for (std::int64_t k = 0; k < n; ++k) {
    const ode::StepStatus status = integrator.step(f, static_cast<double>(k) * h, h, y);
    if (status != ode::StepStatus::ok) {
      out.failure = std::string(ode::describe(status)) + " at t = " + std::to_string(static_cast<double>(k) * h);
      break;
    }
  }
  out.final = to_body<N>(s.params, y);
  fill_counters(integrator.counters(), out);
  return out;
}

template <class Integrator, int N, class F>
Outcome run_adaptive(F f, const Scenario& s, double tol) {
  typename Integrator::Settings settings;
  settings.tolerances = {tol, tol};
  Integrator integrator(settings);
  integrator.start(f, 0.0, initial_vector<N>(f, s));
  Outcome out;
  while (integrator.t() < s.duration && out.failure.empty()) {
    const ode::StepStatus status = integrator.step(f);
    if (status != ode::StepStatus::ok)
      out.failure = std::string(ode::describe(status)) + " at t = " + std::to_string(integrator.t());
    else if (integrator.counters().steps_accepted > kMaxAdaptiveSteps)
      out.failure = "more than " + std::to_string(kMaxAdaptiveSteps) + " steps";
  }
  Vec<N> y = integrator.y();
  if (out.failure.empty()) integrator.dense(f, s.duration, y);
  out.final = to_body<N>(s.params, y);
  fill_counters(integrator.counters(), out);
  return out;
}

struct Info {
  const char* id;
  const char* label;
  bool adaptive;
  int order;
};
constexpr Info kEuler{"euler", "Euler", false, 1};
constexpr Info kSymplecticEuler{"symplectic-euler", "symplectic Euler", false, 1};
constexpr Info kRk4{"rk4", "RK4", false, 4};
constexpr Info kDopri5{"dopri5", "Dopri5", true, 5};
constexpr Info kDop853{"dop853", "DOP853", true, 8};
constexpr Info kVern7{"vern7", "Vern7", true, 7};
constexpr Info kGauss2{"gauss-legendre", "Gauss-Legendre 2", false, 4};

// One method of ours on right-hand side F (a callable built per run from the params).
template <int N, class MakeF>
std::vector<Method> methods_on(int case_id, RhsKind rhs, MakeF make_f, bool all) {
  std::vector<Method> out;
  auto add = [&](const Info& info, auto runner) {
    Method m;
    m.id = info.id;
    m.library = "linkage";
    m.label = info.label;
    m.case_id = case_id;
    m.rhs = rhs;
    m.adaptive = info.adaptive;
    m.order = info.order;
    m.run = [make_f, runner](const Scenario& s, double knob) { return runner(make_f(s.params), s, knob); };
    out.push_back(std::move(m));
  };
  using F = decltype(make_f(Params{}));
  if (all) {
    add(kEuler, [](F f, const Scenario& s, double n) { return run_fixed<ode::ExplicitEuler<double, N>, N>(f, s, n); });
    add(kSymplecticEuler,
        [](F f, const Scenario& s, double n) { return run_fixed<ode::SymplecticEuler<double, N>, N>(f, s, n); });
    add(kRk4, [](F f, const Scenario& s, double n) { return run_fixed<ode::Rk4<double, N>, N>(f, s, n); });
    add(kDopri5, [](F f, const Scenario& s, double tol) { return run_adaptive<ode::Dopri5<double, N>, N>(f, s, tol); });
  }
  add(kDop853, [](F f, const Scenario& s, double tol) { return run_adaptive<ode::Dop853<double, N>, N>(f, s, tol); });
  add(kVern7, [](F f, const Scenario& s, double tol) { return run_adaptive<ode::Vern7<double, N>, N>(f, s, tol); });
  if (all)
    add(kGauss2,
        [](F f, const Scenario& s, double n) { return run_fixed<ode::GaussLegendre2<double, N>, N>(f, s, n); });
  return out;
}

}  // namespace

std::vector<Method> linkage_methods(int case_id) {
  switch (case_id) {
    case 1:
      return methods_on<12>(
          1, RhsKind::definition, [](const Params& p) { return MaximalRhs(p, 0.0, 0.0); }, true);
    case 2:
      return methods_on<8>(
          2, RhsKind::definition, [](const Params& p) { return GeneralizedRhs<Case2>(p); }, true);
    default: {
      std::vector<Method> out = methods_on<8>(
          3, RhsKind::fastest, [](const Params& p) { return FastCase3Rhs<double>(p); }, true);
      for (Method& m : methods_on<8>(
               3, RhsKind::definition, [](const Params& p) { return DefinitionCase3Rhs{p}; }, false))
        out.push_back(std::move(m));
      for (Method& m : methods_on<Eigen::Dynamic>(
               3, RhsKind::general, [](const Params& p) { return GeneralCase3Rhs(p); }, true))
        out.push_back(std::move(m));
      return out;
    }
  }
}

}  // namespace linkage::bench
