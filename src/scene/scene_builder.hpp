#pragma once
// Builds the draw list of one frame from the sampled motion:
//   blocks   rectangles L x w centred at C1 and C2, turned by theta1 and theta2
//   pin      P = C1 + D e1 (block 1's pin point)
//   forces   F on block 1 at P, -F on block 2 at its pin point C2 - D e2
//   gravity  (0, -m g) at each centre of mass
//   velocity C1', C2' (minus G' in the frame falling with G)
//   trail    P over the last `trail_seconds`, fading with age
// The free-body view (`explode`) moves the blocks apart along the line of their centres,
// each with its own pin point and loads.
// In a frame that follows G (`relative_to_com`) the velocities are those an observer
// falling with G sees; the blocks and the trail are where they are in the world.
#include <array>
#include <cstddef>

#include "model/params.hpp"
#include "scene/arrow_scale.hpp"
#include "scene/draw_list.hpp"
#include "scene/elements.hpp"
#include "scene/motion.hpp"

namespace linkage {

/// The --arrow-scale names of the arrow kinds, indexed by ArrowKind.
inline constexpr std::array<std::string_view, kArrowKinds> kArrowKindNames{"pin", "gravity", "velocity"};

struct SceneOptions {
  ElementSet elements = ElementSet::defaults();
  std::array<ArrowScale, kArrowKinds> arrow_scales{};  // indexed by ArrowKind
  bool common_force_scale = false;                     // pin force and gravity share one scale
  bool relative_to_com = false;
  double trail_seconds = 2.0;
  double shortest_arrow = 0;    // m: a shorter arrow (not zero) is drawn stretched_length long, marked stretched
  double stretched_length = 0;  // m: how long a stretched arrow is drawn; 0: shortest_arrow
  double explode = 0;           // m: > 0 draws the free-body view, the blocks this far apart (no trail, no G)
};

/// The longest arrow drawn (metres): 3/4 of D, within L/4 .. L/2.
[[nodiscard]] double default_longest_arrow(const Params& p);

/// The scene options for a motion: arrow scales from the largest magnitude of each kind
/// over the motion, each arrow at most `longest_arrow` metres (default_longest_arrow);
/// with `request.common` one scale for both forces (from the larger); a kind the request
/// fixes at its value.
[[nodiscard]] SceneOptions scene_options_for(const Params& p, const Motion& motion, ElementSet elements,
                                             bool relative_to_com, const ArrowScaleRequest& request = {},
                                             double longest_arrow = 0);

/// Whether any arrow of the motion is drawn stretched (shorter than
/// options.shortest_arrow at its scale, not zero).
[[nodiscard]] bool any_stretched(const Params& p, const SceneOptions& options, const Motion& motion);

/// Adds another run's blocks (with parameters `p`) in state `s` to `out.ghosts`.
void add_ghost(const Params& p, const BodyState& s, double ramp, bool compare, DrawList& out);

/// Clears `out` and fills it with what sample `index` of `motion` shows.
void build_scene(const Params& p, const SceneOptions& options, const Motion& motion, std::size_t index, DrawList& out);

}  // namespace linkage
