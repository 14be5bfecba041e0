#pragma once
// Motions for scene and render tests built from closed-form states, with pin forces
// from the Case 3 solve: no integrator needed.
#include "formulations/formulation.hpp"
#include "model/kinematics.hpp"
#include "scene/motion.hpp"

namespace linkage::test {

/// The pin force on block 1 at a state (Case 3's eliminated equations).
inline Vec2 pin_force_at(const Params& p, const State& s) {
  const CaseSolution solution = solve_case(3, p, s);
  return {solution_value(solution, Unknown::F_x, p), solution_value(solution, Unknown::F_y, p)};
}

/// A motion of `count` samples `dt` apart: the blocks turn at their initial rates and
/// the system falls at g (not the true motion, which turns slightly non-uniformly, but
/// close and closed-form, so scene tests need no integrator).
inline Motion closed_form_motion(const Params& p, const State& s0, int count, double dt, bool forces) {
  Motion motion;
  motion.has_pin_force = forces;
  for (int j = 0; j < count; ++j) {
    const double t = j * dt;
    State s = s0;
    s.theta1 += s0.theta1_dot * t;
    s.theta2 += s0.theta2_dot * t;
    s.x1 += s0.x1_dot * t;
    s.y1 += s0.y1_dot * t - 0.5 * p.g * t * t;
    s.y1_dot -= p.g * t;
    MotionSample sample;
    sample.t = t;
    sample.state = body_state(p, s);
    if (forces) sample.pin_force = pin_force_at(p, s);
    motion.samples.push_back(sample);
  }
  motion.set_energy_reference(p, body_state(p, s0));
  return motion;
}

/// One sample at the given state, at time t.
inline Motion still_motion(const Params& p, const State& s, bool forces, double t = 0) {
  Motion motion = closed_form_motion(p, s, 1, 0.0, forces);
  motion.samples.front().t = t;
  return motion;
}

}  // namespace linkage::test
