#include "bench/reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "bench/rhs.hpp"
#include "core/error.hpp"
#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "linkage/reference_example.hpp"

namespace linkage::bench {
namespace {

using LVec = Eigen::Matrix<long double, 8, 1>;

/// Integrates with an adaptive long double method to each time in `times` (increasing),
/// by dense output; returns the states there and the accepted steps.
template <class Integrator>
std::vector<LVec> integrate(const Case3Fast<long double>& closed_form, const LVec& y0,
                            const std::vector<long double>& times, long double tol, long& steps) {
  FastCase3Rhs<long double> f(closed_form);
  typename Integrator::Settings settings;
  settings.tolerances = {tol, tol};
  Integrator integrator(settings);
  integrator.start(f, 0.0L, y0);
  std::vector<LVec> out;
  for (const long double t : times) {
    while (integrator.t() < t) {
      const ode::StepStatus status = integrator.step(f);
      if (status != ode::StepStatus::ok)
        throw Error::diverged("reference run failed: " + std::string(ode::describe(status)) +
                              " at t = " + std::to_string(static_cast<double>(integrator.t())));
    }
    LVec y;
    integrator.dense(f, t, y);
    out.push_back(y);
  }
  steps = static_cast<long>(integrator.counters().steps_accepted);
  return out;
}

long double max_abs_difference(const LVec& a, const LVec& b) {
  long double d = 0;
  for (int i = 0; i < 4; ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

std::optional<double> compare_with_spec(const Scenario& scenario, long double tol) {
  if (scenario.name != "example") return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(kReferenceExampleJson);
  auto number = [](const nlohmann::json& v) { return std::strtold(v.get<std::string>().c_str(), nullptr); };
  // Start from the decimal initial values and parameters of the file, not their doubles.
  const auto& s0 = json["initial_state"];
  LVec y0;
  const char* keys[8] = {"x1", "y1", "theta1", "theta2", "x1_dot", "y1_dot", "theta1_dot", "theta2_dot"};
  for (int i = 0; i < 8; ++i) y0[i] = number(s0[keys[i]]);
  std::vector<long double> times;
  std::vector<LVec> want;
  for (const auto& state : json["states"]) {
    times.push_back(number(state["t"]));
    LVec w = LVec::Zero();
    for (int i = 0; i < 4; ++i) w[i] = number(state[keys[i]]);
    want.push_back(w);
  }
  // Parameters in long double too: g = 9.81 rounded to double alone moves y1(10 s) by 4e-14.
  const auto& pj = json["parameters"];
  const Case3Fast<long double> closed_form(number(pj["L"]), number(pj["w"]), number(pj["b"]), number(pj["m"]),
                                           number(pj["g"]));
  long steps = 0;
  const std::vector<LVec> got = integrate<ode::Dop853<long double, 8>>(closed_form, y0, times, tol, steps);
  long double worst = 0;
  for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, max_abs_difference(got[i], want[i]));
  return static_cast<double>(worst);
}

}  // namespace

Reference compute_reference(const Scenario& scenario, bool quick) {
  const auto start = std::chrono::steady_clock::now();
  Reference ref;
  ref.tolerance = quick ? 1e-15 : 1e-18;
  // Long double Dopri5 is the costly half: over long runs it checks at 1e-16, still far
  // below what double runs reach there (their error grows with the duration).
  ref.check_tolerance = quick ? 1e-14 : scenario.duration <= 20.0 ? 1e-17 : 1e-16;
  const LVec y0 = scenario.initial.vector().cast<long double>();
  const std::vector<long double> end{static_cast<long double>(scenario.duration)};
  long check_steps = 0;
  const Case3Fast<long double> closed_form(scenario.params);
  const LVec y = integrate<ode::Dop853<long double, 8>>(closed_form, y0, end, ref.tolerance, ref.steps).front();
  const LVec check =
      integrate<ode::Dopri5<long double, 8>>(closed_form, y0, end, ref.check_tolerance, check_steps).front();
  for (int i = 0; i < 4; ++i) ref.final[static_cast<std::size_t>(i)] = y[i];
  ref.check_difference = static_cast<double>(max_abs_difference(y, check));
  ref.spec_difference = compare_with_spec(scenario, ref.tolerance);
  long double size = 1;
  for (int i = 0; i < 4; ++i) size = std::max(size, std::fabs(y[i]));
  const double bound = std::max(ref.check_difference, ref.spec_difference.value_or(0.0));
  ref.digits = bound > 0 ? -std::log10(bound / static_cast<double>(size)) : 19.0;
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return ref;
}

double final_error(const Reference& reference, const BodyState& s) {
  const double got[4] = {s.x1, s.y1, s.theta1, s.theta2};
  double worst = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double d = static_cast<double>(std::fabs(reference.final[i] - static_cast<long double>(got[i])));
    if (!std::isfinite(d)) return std::numeric_limits<double>::quiet_NaN();
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace linkage::bench
