// Drawing a frame allocates nothing on the C++ heap once the first frame has set up the
// caches (cairo's own internals aside): the draw list keeps its capacity, names are
// short strings, the HUD formats into fixed buffers. Counted by replacing operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "render/clip_renderer.hpp"
#include "render_test_support.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// GCC pairs the inlined replacement delete with the library's new and warns; the pair
// here is matched (malloc/free), so the warning is a false positive in this file only.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

[[gnu::noinline]] void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace linkage {
namespace {

TEST(Allocation, FramesAfterTheFirstAllocateNothing) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 40, 1.0 / 30, true);
  RenderSettings settings;
  settings.width = 640;
  settings.height = 360;
  settings.elements = ElementSet::all();
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  std::vector<Frame> buffers(3, Frame(settings.width, settings.height));
  // Warm up: every buffer once, and the longest trail (the last frame) once.
  for (std::size_t k = 0; k < 3; ++k) renderer.draw(k, buffers[k]);
  renderer.draw(39, buffers[0]);
  const long before = g_allocations.load();
  for (std::size_t k = 3; k < 39; ++k) renderer.draw(k, buffers[k % 3]);
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace linkage
