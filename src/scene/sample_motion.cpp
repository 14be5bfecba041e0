// Kept apart from motion.cpp: only this file needs the Simulation, so code that builds
// scenes from given states links without the integrators.
#include "core/interrupt.hpp"
#include "integrate/simulation.hpp"
#include "scene/motion.hpp"

namespace linkage {

Motion sample_motion(Simulation& sim, const std::vector<double>& times, bool pin_force,
                     const std::function<void(long)>& progress) {
  Motion motion;
  motion.has_pin_force = pin_force;
  motion.samples.reserve(times.size());
  motion.set_energy_reference(sim.params(), sim.state_at(0.0));  // times are >= 0, so this call keeps t non-decreasing
  for (std::size_t j = 0; j < times.size(); ++j) {
    throw_if_interrupted();
    MotionSample sample;
    sample.t = times[j];
    sample.state = sim.state_at(times[j]);
    if (pin_force) {
      const Dynamics dynamics = sim.dynamics(sample.state);
      sample.pin_force = {dynamics.F_x, dynamics.F_y};
    }
    motion.samples.push_back(sample);
    if (progress) progress(static_cast<long>(j + 1));
  }
  return motion;
}

}  // namespace linkage
