#include "bench/overhead.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/closed_form/case3_fast.hpp"
#include "core/error.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/symplectic_euler.hpp"
#include "integrate/vern7.hpp"

namespace linkage::bench {
namespace {

template <class Integrator>
std::int64_t fixed(double n_steps, double duration, double& sink) {
  const auto n = static_cast<std::int64_t>(n_steps);
  const double h = duration / static_cast<double>(n);
  OscillatorsRhs f;
  Integrator integrator;
  Vec<8> y = oscillators_start();
  for (std::int64_t k = 0; k < n; ++k)
    if (integrator.step(f, static_cast<double>(k) * h, h, y) != ode::StepStatus::ok) break;
  sink += y.sum();
  return integrator.counters().rhs_evaluations;
}

template <class Integrator>
std::int64_t adaptive(double tol, std::int64_t evaluations, double& sink) {
  typename Integrator::Settings settings;
  settings.tolerances = {tol, tol};
  OscillatorsRhs f;
  Integrator integrator(settings);
  integrator.start(f, 0.0, oscillators_start());
  while (integrator.counters().rhs_evaluations < evaluations)
    if (integrator.step(f) != ode::StepStatus::ok) break;
  sink += integrator.y().sum();
  return integrator.counters().rhs_evaluations;
}

}  // namespace

Vec<8> oscillators_start() {
  Vec<8> y;
  y << 0.4, -0.3, 0.2, 0.1, 0.0, 0.5, -1.0, 1.5;
  return y;
}

bool has_dynamic_run(const std::string& method) {
  return method == "dopri5" || method == "dop853" || method == "vern7";
}

std::int64_t run_on_oscillators(const std::string& method, double knob, double duration, std::int64_t evaluations,
                                double& sink, bool dynamic) {
  if (dynamic && method == "dopri5") return adaptive<ode::Dopri5<double, Eigen::Dynamic>>(knob, evaluations, sink);
  if (dynamic && method == "dop853") return adaptive<ode::Dop853<double, Eigen::Dynamic>>(knob, evaluations, sink);
  if (dynamic && method == "vern7") return adaptive<ode::Vern7<double, Eigen::Dynamic>>(knob, evaluations, sink);
  if (dynamic) throw Error::failure("run_on_oscillators: no dynamic-size run of '" + method + "'");
  if (method == "euler") return fixed<ode::ExplicitEuler<double, 8>>(knob, duration, sink);
  if (method == "symplectic-euler") return fixed<ode::SymplecticEuler<double, 8>>(knob, duration, sink);
  if (method == "rk4") return fixed<ode::Rk4<double, 8>>(knob, duration, sink);
  if (method == "gauss-legendre") return fixed<ode::GaussLegendre2<double, 8>>(knob, duration, sink);
  if (method == "dopri5") return adaptive<ode::Dopri5<double, 8>>(knob, evaluations, sink);
  if (method == "dop853") return adaptive<ode::Dop853<double, 8>>(knob, evaluations, sink);
  if (method == "vern7") return adaptive<ode::Vern7<double, 8>>(knob, evaluations, sink);
  throw Error::failure("run_on_oscillators: no integrator '" + method + "'");
}

PerCall time_on_oscillators(const std::string& method, double knob, double duration, std::int64_t evaluations,
                            double min_time, std::int64_t& made, bool dynamic) {
  double sink = 0;
  made = 0;
  const Timing t =
      time_repeated([&] { made = run_on_oscillators(method, knob, duration, evaluations, sink, dynamic); }, min_time);
  if (sink == 0.123456789) throw Error::failure("unreachable");  // keeps the runs alive
  const double per = 1e9 / static_cast<double>(std::max<std::int64_t>(made, 1));
  return {t.median_seconds * per, t.cpu_median_seconds * per};
}

namespace {

/// Case 3's closed form on a dynamic-size state, never inlined: the call simulate's
/// integrators make to a mechanism's right-hand side.
struct OutOfLineClosedForm {
  Case3Fast<double> f;
  __attribute__((noinline)) void operator()(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
    dydt.resize(y.size());
    f.rhs(y, dydt);
  }
};

struct InlineClosedForm {
  Case3Fast<double> f;
  void operator()(double /*t*/, const Vec<8>& y, Vec<8>& dydt) const { f.rhs(y, dydt); }
};

template <class Integrator, class F, class V>
std::int64_t closed_form_run(const F& f, const V& y0, double tol, double duration, double& sink) {
  typename Integrator::Settings settings;
  settings.tolerances = {tol, tol};
  settings.t_stop = duration;
  Integrator integrator(settings);
  integrator.start(f, 0.0, y0);
  while (integrator.t() < duration)
    if (integrator.step(f) != ode::StepStatus::ok) break;
  sink += integrator.y().sum();
  return integrator.counters().rhs_evaluations;
}

template <template <class, int> class Integrator>
std::int64_t closed_form_run(const Scenario& s, double tol, bool dynamic, double& sink) {
  const Case3Fast<double> f(s.params);
  const Vec<8> y0 = s.initial.vector();
  if (dynamic)
    return closed_form_run<Integrator<double, Eigen::Dynamic>>(OutOfLineClosedForm{f}, Eigen::VectorXd(y0), tol,
                                                               s.duration, sink);
  return closed_form_run<Integrator<double, 8>>(InlineClosedForm{f}, y0, tol, s.duration, sink);
}

}  // namespace

PerCall time_on_closed_form(const std::string& method, const Scenario& scenario, double tol, double min_time,
                            bool dynamic, std::int64_t& made) {
  double sink = 0;
  made = 0;
  auto run = [&] {
    if (method == "dopri5") return closed_form_run<ode::Dopri5>(scenario, tol, dynamic, sink);
    if (method == "dop853") return closed_form_run<ode::Dop853>(scenario, tol, dynamic, sink);
    if (method == "vern7") return closed_form_run<ode::Vern7>(scenario, tol, dynamic, sink);
    throw Error::failure("time_on_closed_form: no adaptive integrator '" + method + "'");
  };
  const Timing t = time_repeated([&] { made = run(); }, min_time);
  if (sink == 0.123456789) throw Error::failure("unreachable");  // keeps the runs alive
  const double per = 1e9 / static_cast<double>(std::max<std::int64_t>(made, 1));
  return {t.median_seconds * per, t.cpu_median_seconds * per};
}

PerCall oscillators_rhs_ns(double min_batch) {
  std::vector<Vec<8>> ys;
  const OscillatorsRhs f;
  Vec<8> y = oscillators_start(), dy;
  for (int i = 0; i < 64; ++i) {  // explicit Euler at h = 0.01 s: states along the motion
    f(0.0, y, dy);
    y += 0.01 * dy;
    ys.push_back(y);
  }
  double sink = 0;
  const PerCall ns = nanoseconds_per_call(
      [&](std::size_t i) {
        f(0.0, ys[i % ys.size()], dy);
        sink += dy[7];
      },
      min_batch);
  if (sink == 0.123456789) throw Error::failure("unreachable");
  return ns;
}

}  // namespace linkage::bench
