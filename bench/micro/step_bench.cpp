// One step of each of our integrators on Case 3 (closed-form right-hand side, 8 values)
// and DOP853 on Case 1 (12 values). Fixed-step methods restart from the same state each
// iteration; adaptive ones step on and restart every 1000 steps, so the step size is the
// one their controller picks for the scenario `fast` at rtol = atol = 1e-10.
// overhead/*: the same on OscillatorsRhs (bench/overhead.hpp, a few ns), whose counter
// time_per_rhs is the integrator's own cost per evaluation, that cheap RHS included.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <type_traits>

#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/general_rhs.hpp"
#include "bench/overhead.hpp"
#include "bench/rhs.hpp"
#include "bench/scenarios.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/symplectic_euler.hpp"

namespace linkage::bench {
namespace {

const Scenario& fast() { return find_scenario("fast", "micro"); }

// The oscillators called, not inlined, as simulate calls MechanismDynamics::derivative.
struct OutOfLineOscillators {
  template <class V>
  [[gnu::noinline]] void operator()(double t, const V& y, V& dydt) const {
    OscillatorsRhs{}(t, y, dydt);
  }
};

/// Time per evaluation, as a counter.
benchmark::Counter per_evaluation(std::int64_t evaluations) {
  return benchmark::Counter(static_cast<double>(evaluations),
                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class Integrator, class F = FastCase3Rhs<double>>
void BM_FixedStep(benchmark::State& state) {
  constexpr bool cheap = std::is_same_v<F, OscillatorsRhs>;
  F f = [&] {
    if constexpr (cheap)
      return F{};
    else
      return F(fast().params);
  }();
  const Vec<8> y0 = cheap ? oscillators_start() : fast().initial.vector();
  Integrator integrator;
  Vec<8> y;
  for (auto _ : state) {
    y = y0;
    benchmark::DoNotOptimize(integrator.step(f, 0.0, 1e-3, y));
    benchmark::DoNotOptimize(y);
  }
  state.counters["rhs_per_step"] =
      static_cast<double>(integrator.counters().rhs_evaluations) / static_cast<double>(state.iterations());
  if constexpr (cheap) state.counters["time_per_rhs"] = per_evaluation(integrator.counters().rhs_evaluations);
}
BENCHMARK(BM_FixedStep<ode::ExplicitEuler<double, 8>>)->Name("step/euler");
BENCHMARK(BM_FixedStep<ode::SymplecticEuler<double, 8>>)->Name("step/symplectic_euler");
BENCHMARK(BM_FixedStep<ode::Rk4<double, 8>>)->Name("step/rk4");
BENCHMARK(BM_FixedStep<ode::GaussLegendre2<double, 8>>)->Name("step/gauss_legendre");
BENCHMARK(BM_FixedStep<ode::ExplicitEuler<double, 8>, OscillatorsRhs>)->Name("overhead/euler");
BENCHMARK(BM_FixedStep<ode::SymplecticEuler<double, 8>, OscillatorsRhs>)->Name("overhead/symplectic_euler");
BENCHMARK(BM_FixedStep<ode::Rk4<double, 8>, OscillatorsRhs>)->Name("overhead/rk4");
BENCHMARK(BM_FixedStep<ode::GaussLegendre2<double, 8>, OscillatorsRhs>)->Name("overhead/gauss_legendre");

template <class Integrator, class F, class V>
void adaptive_steps(benchmark::State& state, F f, const V& y0) {
  typename Integrator::Settings settings;
  settings.tolerances = {1e-10, 1e-10};
  Integrator integrator(settings);
  integrator.start(f, 0.0, y0);
  int k = 0;
  std::int64_t evaluations = 0;  // in timed steps only (start() evaluates too)
  for (auto _ : state) {
    const std::int64_t before = integrator.counters().rhs_evaluations;
    benchmark::DoNotOptimize(integrator.step(f));
    evaluations += integrator.counters().rhs_evaluations - before;
    if (++k == 1000) {
      state.PauseTiming();
      integrator.start(f, 0.0, y0);
      k = 0;
      state.ResumeTiming();
    }
  }
  // rejected attempts included
  state.counters["rhs_per_step"] = static_cast<double>(evaluations) / static_cast<double>(state.iterations());
  if constexpr (std::is_same_v<F, OscillatorsRhs> || std::is_same_v<F, OutOfLineOscillators> ||
                std::is_same_v<F, GeneralCase3Rhs>)
    state.counters["time_per_rhs"] = per_evaluation(evaluations);
}

void BM_Dopri5Case3(benchmark::State& state) {
  adaptive_steps<ode::Dopri5<double, 8>>(state, FastCase3Rhs<double>(fast().params), fast().initial.vector());
}
BENCHMARK(BM_Dopri5Case3)->Name("step/dopri5");

void BM_Dop853Case3(benchmark::State& state) {
  adaptive_steps<ode::Dop853<double, 8>>(state, FastCase3Rhs<double>(fast().params), fast().initial.vector());
}
BENCHMARK(BM_Dop853Case3)->Name("step/dop853");

void BM_Dop853Case1(benchmark::State& state) {
  adaptive_steps<ode::Dop853<double, 12>>(state, MaximalRhs(fast().params, 0.0, 0.0),
                                          body_state(fast().params, fast().initial).vector());
}
BENCHMARK(BM_Dop853Case1)->Name("step/dop853_case1");

// The homework on the general path, as simulate runs it (dynamic-size state, the
// built-in native code): time_per_rhs is all of a step's cost per evaluation.
void BM_Dop853General(benchmark::State& state) {
  const GeneralCase3Rhs f(fast().params);
  adaptive_steps<ode::Dop853<double, Eigen::Dynamic>>(state, f, f.state(fast().initial.vector()));
}
BENCHMARK(BM_Dop853General)->Name("step/dop853_general");

// The closed form on a dynamic-size state, called out of line as the general path's
// native code is: beside step/dop853 it shows what a dynamic-size state and the call
// cost a step whose right-hand side is real work (nothing measurable, where the
// oscillators' overhead rows, whose right-hand side is a few additions, show 7 ns).
struct DynamicClosedForm {
  Case3Fast<double> f{fast().params};
  __attribute__((noinline)) void operator()(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
    dydt.resize(y.size());
    f.rhs(y, dydt);
  }
};
void BM_Dop853DynamicClosedForm(benchmark::State& state) {
  adaptive_steps<ode::Dop853<double, Eigen::Dynamic>>(state, DynamicClosedForm{},
                                                      Eigen::VectorXd(fast().initial.vector()));
}
BENCHMARK(BM_Dop853DynamicClosedForm)->Name("step/dop853_dynamic_out_of_line");

// An integrator on the oscillators (bench/overhead.hpp): time_per_rhs is its own cost.
template <class Integrator, class F>
void BM_Oscillators(benchmark::State& state) {
  adaptive_steps<Integrator>(state, F{}, oscillators_start());
}
BENCHMARK(BM_Oscillators<ode::Dopri5<double, 8>, OscillatorsRhs>)->Name("overhead/dopri5");
BENCHMARK(BM_Oscillators<ode::Dop853<double, 8>, OscillatorsRhs>)->Name("overhead/dop853");
// The same with dynamic-size states, as a mechanism read from a file runs.
BENCHMARK(BM_Oscillators<ode::Dopri5<double, Eigen::Dynamic>, OscillatorsRhs>)->Name("overhead/dopri5_dynamic");
BENCHMARK(BM_Oscillators<ode::Dop853<double, Eigen::Dynamic>, OscillatorsRhs>)->Name("overhead/dop853_dynamic");
// The fixed-size runs with the oscillators out of line: beside the dynamic-size rows they
// show that what the dynamic-size state costs is the call, not Eigen's dynamic vectors
// (session 19: Dopri5 24.2 ns fixed-size out of line, 23.1 dynamic-size, 16.0 inlined).
BENCHMARK(BM_Oscillators<ode::Dopri5<double, 8>, OutOfLineOscillators>)->Name("overhead/dopri5_out_of_line");
BENCHMARK(BM_Oscillators<ode::Dop853<double, 8>, OutOfLineOscillators>)->Name("overhead/dop853_out_of_line");

// The oscillators alone, each input waiting for the previous output as stages do.
void BM_OscillatorsRhs(benchmark::State& state) {
  const OscillatorsRhs f;
  Vec<8> y = oscillators_start(), dy = Vec<8>::Zero();
  for (auto _ : state) {
    const Vec<8> in = y + 0.0 * dy;
    f(0.0, in, dy);
    benchmark::DoNotOptimize(dy);
  }
}
BENCHMARK(BM_OscillatorsRhs)->Name("overhead/oscillators_rhs");

}  // namespace
}  // namespace linkage::bench
