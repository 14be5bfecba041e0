// Drawing a clip's frame allocates on the C++ heap (cairo's own internals aside) a bounded
// amount that does not grow with the frame's index or the clip's length: each frame's draw
// list, labels and legend rows are built afresh (97 allocations a frame for the homework,
// 125 for the four-bar, at 640x360), but nothing accumulates, and the caches kept across
// frames (a fixed camera's backdrop, the title's pixels) are filled by the first frames.
// Counted by replacing operator new, over frames 10-19 and 100-109 of a 4 s clip and over
// frames 10-19 of an 8 s one, for the homework (a following camera) and the four-bar (a
// fixed one).
#include <gtest/gtest.h>

#include <string>

#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "support/allocation_counter.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

struct Counts {
  long early = 0;  // over frames 10-19
  long late = 0;   // over frames 100-109 (0 when the clip is shorter)
};

Counts allocations_drawing(const std::string& mechanism, double duration) {
  const sym::System system(load_mechanism(mechanism));
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  MechanismClip clip;
  clip.settings.width = 640;
  clip.settings.height = 360;
  clip.settings.duration = duration;
  clip.settings.elements = ElementSet::all();
  clip.settings.elements.hide(Element::equations);
  clip.simulation.duration = clip.settings.duration;
  clip.trails = system.mechanism().picture.trails;
  clip.theme = load_theme("light", {}, "--theme");
  ClipResult result;
  MechanismClipFrames frames(system, initial, clip, result);
  EXPECT_EQ(frames.count(), static_cast<int>(duration * 30)) << mechanism;
  Frame frame(640, 360);
  const auto count = [&](std::size_t from) {
    for (std::size_t k = 0; k < from; ++k) frames.draw(k, frame);  // the frames before, as a clip draws them
    const long before = test::allocations();
    for (std::size_t k = from; k < from + 10; ++k) frames.draw(k, frame);
    return test::allocations() - before;
  };
  Counts counts;
  counts.early = count(10);
  if (frames.count() >= 110) counts.late = count(100);
  return counts;
}

void expect_bounded(const std::string& mechanism) {
  const Counts short_clip = allocations_drawing(mechanism, 4.0);
  const Counts long_clip = allocations_drawing(mechanism, 8.0);
  SCOPED_TRACE(mechanism);
  EXPECT_GT(short_clip.early, 0);  // the counter counts this drawing
  // Ten frames of the same clip later on, and the same frames of a clip twice as long:
  // within a tenth (the labels' numbers change with the frame, their strings' lengths too).
  EXPECT_NEAR(static_cast<double>(short_clip.late), static_cast<double>(short_clip.early),
              0.1 * static_cast<double>(short_clip.early));
  EXPECT_NEAR(static_cast<double>(long_clip.early), static_cast<double>(short_clip.early),
              0.1 * static_cast<double>(short_clip.early));
  EXPECT_LT(short_clip.early, 10 * 200) << "about a hundred allocations a frame, not more";
}

TEST(Allocation, FramesAllocateABoundedAmountThatDoesNotGrowWithTheFrameOrTheClip) {
  expect_bounded("two-blocks");
  expect_bounded("four-bar");
}

}  // namespace
}  // namespace linkage
