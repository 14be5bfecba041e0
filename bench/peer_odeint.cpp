// Boost.Odeint peers on Case 3: runge_kutta_fehlberg78 (controlled), runge_kutta_dopri5
// (dense output) and bulirsch_stoer, driven by integrate_adaptive as the library's
// tutorial does, with std::array<double, 8> as the state. Each runs with the
// right-hand side a user would write (user_case3_rhs) and with ours (Case3Fast).
#include <array>
#include <exception>
#include <functional>

// Odeint's steppers copy std::array scratch members before first use; GCC sees that as
// maybe-uninitialized inside the library's templates. Harmless; silenced for this file.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/stepper/bulirsch_stoer.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/method.hpp"
#include "bench/rhs.hpp"

namespace linkage::bench {
namespace {

namespace odeint = boost::numeric::odeint;
using State8 = std::array<double, 8>;

// The system functors: odeint calls system(x, dxdt, t). Each counts its evaluations.
struct UserSystem {
  UserConstants constants;
  std::int64_t* count;
  void operator()(const State8& x, State8& dxdt, double /*t*/) const {
    ++*count;
    user_case3_rhs(constants, x.data(), dxdt.data());
  }
};
struct OurSystem {
  Case3Fast<double> f;
  std::int64_t* count;
  void operator()(const State8& x, State8& dxdt, double /*t*/) const {
    ++*count;
    f.rhs(x, dxdt);
  }
};

enum class Stepper { rkf78, dopri5, bulirsch_stoer };

template <class System>
Outcome run(Stepper which, const Scenario& scenario, double tol, System system) {
  std::int64_t count = 0;
  system.count = &count;
  State8 x;
  const Vec<8> y0 = scenario.initial.vector();
  for (int i = 0; i < 8; ++i) x[static_cast<std::size_t>(i)] = y0[i];
  const double dt = 1e-3;  // the first step a user passes; the controllers adapt it
  Outcome out;
  try {
    std::size_t steps = 0;
    switch (which) {
      case Stepper::rkf78:
        steps = odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<State8>()),
                                           std::ref(system), x, 0.0, scenario.duration, dt);
        break;
      case Stepper::dopri5:
        steps = odeint::integrate_adaptive(odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<State8>()),
                                           std::ref(system), x, 0.0, scenario.duration, dt);
        break;
      case Stepper::bulirsch_stoer:
        steps = odeint::integrate_adaptive(odeint::bulirsch_stoer<State8>(tol, tol), std::ref(system), x, 0.0,
                                           scenario.duration, dt);
        break;
    }
    out.steps = static_cast<std::int64_t>(steps);
  } catch (const std::exception& e) {  // odeint throws when the step size control gives up
    out.failure = e.what();
  }
  Vec<8> y;
  for (int i = 0; i < 8; ++i) y[i] = x[static_cast<std::size_t>(i)];
  out.final = body_state(scenario.params, State::from_vector(y));
  out.rhs_evaluations = count;
  return out;
}

Method odeint_method(Stepper which, RhsKind rhs) {
  Method m;
  m.library = "Boost.Odeint";
  m.case_id = 3;
  m.rhs = rhs;
  m.adaptive = true;
  switch (which) {
    case Stepper::rkf78:
      m.id = "odeint-rkf78", m.label = "Odeint RKF78", m.order = 8;
      break;
    case Stepper::dopri5:
      m.id = "odeint-dopri5", m.label = "Odeint dense Dopri5", m.order = 5;
      break;
    case Stepper::bulirsch_stoer:
      m.id = "odeint-bs", m.label = "Odeint Bulirsch-Stoer", m.order = 0;
      break;
  }
  m.run = [which, rhs](const Scenario& scenario, double tol) {
    if (rhs == RhsKind::user) return run(which, scenario, tol, UserSystem{UserConstants(scenario.params), nullptr});
    return run(which, scenario, tol, OurSystem{Case3Fast<double>(scenario.params), nullptr});
  };
  return m;
}

}  // namespace

std::vector<Method> odeint_methods() {
  std::vector<Method> out;
  for (Stepper s : {Stepper::rkf78, Stepper::dopri5, Stepper::bulirsch_stoer})
    for (RhsKind rhs : {RhsKind::user, RhsKind::fastest}) out.push_back(odeint_method(s, rhs));
  return out;
}

}  // namespace linkage::bench
