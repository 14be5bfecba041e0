#pragma once
// The shaking force and moment: what the moving bodies exert on the ground, from the same
// joint forces, driver multipliers and loads the Newton-Euler rows hold (System), so that
// there is one definition of each force and this is only their sum on the ground's side.
#include <ginac/ginac.h>

#include "symbolic/system.hpp"

namespace linkage::sym {

/// The resultant force on the ground and its moment about the world origin (with the
/// couples: a slider's moment, the drivers' reaction torques, the ground pins' spring-
/// damper torques), in maximal coordinates, rates, the joints' force unknowns and the
/// drivers' unknowns:
///   a joint with bodies[0] the ground: +F (the force bodies[1] exerts on bodies[0]) at the
///     point Newton-Euler applies it to bodies[0], and +M; with bodies[1] the ground: -F, -M;
///   a driver: minus its loads on the moving bodies (lambda dC/dq, a pair between the
///     joint's bodies: it holds for any rigid motion of both, so it sums to nothing);
///   a spring with an end on the ground: minus its force on the moving end, at the ground's
///     point; a pin spring-damper at a ground pin: minus its torque on the moving body.
struct GroundReaction {
  Vec2 force;
  GiNaC::ex moment = 0;
};
[[nodiscard]] GroundReaction ground_reaction(const System& system);

}  // namespace linkage::sym
