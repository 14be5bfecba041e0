#include "bench/peer_odeint_pendulum.hpp"

#include <array>
#include <cmath>
#include <functional>

// As in peer_odeint.cpp: odeint's std::array scratch trips GCC's maybe-uninitialized.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/integrate/integrate_n_steps.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "bench/timing.hpp"
#include "core/error.hpp"

namespace linkage::bench {

namespace odeint = boost::numeric::odeint;
using State4 = std::array<double, 4>;

PendulumRun odeint_double_pendulum(const DoublePendulumUser& f, const std::string& stepper, double setting,
                                   double theta1, double theta2, double t_end) {
  long count = 0;
  auto system = [&](const State4& x, State4& dxdt, double t) {
    ++count;
    f(x, dxdt, t);
  };
  State4 x{theta1, theta2, 0, 0};
  const double start = thread_cpu_seconds();
  if (stepper == "rk4") {
    const auto n = static_cast<std::size_t>(std::llround(t_end / setting));
    odeint::integrate_n_steps(odeint::runge_kutta4<State4>(), std::ref(system), x, 0.0, setting, n);
  } else if (stepper == "rkf78") {
    odeint::integrate_adaptive(odeint::make_controlled(setting, setting, odeint::runge_kutta_fehlberg78<State4>()),
                               std::ref(system), x, 0.0, t_end, 1e-3);
  } else if (stepper == "dopri5") {
    odeint::integrate_adaptive(odeint::make_controlled(setting, setting, odeint::runge_kutta_dopri5<State4>()),
                               std::ref(system), x, 0.0, t_end, 1e-3);
  } else {
    throw Error::failure("odeint_double_pendulum: unknown stepper " + stepper);
  }
  PendulumRun out;
  out.seconds = thread_cpu_seconds() - start;
  out.theta1 = x[0];
  out.theta2 = x[1];
  out.evaluations = count;
  return out;
}

}  // namespace linkage::bench
