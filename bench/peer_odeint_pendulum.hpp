#pragma once
// Boost.Odeint on the double pendulum with the right-hand side a user writes by hand
// (double_pendulum_user.hpp): built when Boost is found (LINKAGE_PEER_ODEINT).
#include <string>

#include "bench/double_pendulum_user.hpp"

namespace linkage::bench {

struct PendulumRun {
  double theta1 = 0, theta2 = 0;  // rad, at the end
  double seconds = 0;             // the integration alone, this thread's CPU time
  long evaluations = 0;
};

/// "rk4" (fixed step `setting` s), "rkf78" or "dopri5" (controlled, tolerance `setting`),
/// from (th1, th2) at rest to `t_end`.
[[nodiscard]] PendulumRun odeint_double_pendulum(const DoublePendulumUser& f, const std::string& stepper,
                                                 double setting, double theta1, double theta2, double t_end);

}  // namespace linkage::bench
