// Other runs over the main one (--ensemble, --compare): where the ensemble starts, that
// it is the same every time and fans out for the double pendulum, and that a compared
// run with the clip's own settings is the main run exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

double number(const GiNaC::exmap& state, const GiNaC::symbol& s) {
  return GiNaC::ex_to<GiNaC::numeric>(state.at(s)).to_double();
}

// Released high, where the double pendulum is chaotic.
sym::System high_double_pendulum() {
  Mechanism mechanism = load_mechanism("double-pendulum");
  set_value(mechanism, "1.theta", 1.2, "test");
  set_value(mechanism, "2.theta", 1.4, "test");
  return sym::System(std::move(mechanism));
}

std::vector<double> times_to(double end, double step) {
  std::vector<double> times;
  for (int i = 0; i * step <= end + 1e-12; ++i) times.push_back(i * step);
  return times;
}

SimulationOptions options_for(double duration) {
  SimulationOptions o;
  o.duration = duration;
  return o;
}

// The largest distance between the bodies' centres of two poses.
double pose_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double gap = 0;
  for (std::size_t i = 0; i + 1 < a.size(); i += 3) gap = std::max(gap, std::hypot(a[i] - b[i], a[i + 1] - b[i + 1]));
  return gap;
}

TEST(MechanismOverlay, EnsembleStartsWithinTheSpreadEvenlyAndDistinct) {
  const sym::System system = high_double_pendulum();
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  const std::vector<GiNaC::exmap> states = ensemble_states(system, initial, 20, 1e-6);
  ASSERT_EQ(states.size(), 19U);
  const GiNaC::symbol& q1 = system.coordinates()[0].symbols.q;
  const GiNaC::symbol& q2 = system.coordinates()[1].symbols.q;
  std::set<double> offsets;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double offset = number(states[k], q1) - number(initial, q1);
    EXPECT_NEAR(offset, 1e-6 * static_cast<double>(k + 1) / 19, 1e-15);
    EXPECT_GT(offset, 0);
    EXPECT_LE(offset, 1e-6 + 1e-15);
    EXPECT_EQ(number(states[k], q2), number(initial, q2));  // only the first coordinate moves
    offsets.insert(offset);
  }
  EXPECT_EQ(offsets.size(), states.size());
}

TEST(MechanismOverlay, EnsembleIsDeterministicAndFansOut) {
  const sym::System system = high_double_pendulum();
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  MechanismClip clip;
  clip.ensemble = 8;
  clip.spread = 1e-6;
  const std::vector<double> times = times_to(12, 0.5);
  ClipResult first, second, main_result;
  const auto a = overlay_motions(system, initial, clip, options_for(12), times, first);
  const auto b = overlay_motions(system, initial, clip, options_for(12), times, second);
  const MechanismMotion main = sample_mechanism_motion(system, initial, options_for(12), times, 1, main_result);
  ASSERT_EQ(a.size(), 7U);
  double start = 0, end = 0;
  for (std::size_t r = 0; r < a.size(); ++r) {
    ASSERT_EQ(a[r].samples.size(), times.size());
    for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(a[r].samples[k].pose, b[r].samples[k].pose);
    // 1e-6 rad of rod 1 (0.3 m) moves rod 2's centre, at its tip, by at most 0.3 um.
    start = std::max(start, pose_gap(a[r].samples.front().pose, main.samples.front().pose));
    end = std::max(end, pose_gap(a[r].samples.back().pose, main.samples.back().pose));
  }
  EXPECT_GT(start, 0);
  EXPECT_LE(start, 0.3e-6 + 1e-12);
  EXPECT_GT(end, 0.05);  // visibly apart after 12 s: centimetres, not micrometres
  EXPECT_NE(a.front().samples.back().pose, a.back().samples.back().pose);
  EXPECT_EQ(first.stats.samples, static_cast<std::int64_t>(7 * times.size()));
}

TEST(MechanismOverlay, ComparedRunWithTheSameSettingsIsTheMainRunExactly) {
  const sym::System system = high_double_pendulum();
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  MechanismClip clip;
  clip.compare = MechanismRun{nullptr, initial, options_for(3), "the same"};
  const std::vector<double> times = times_to(3, 0.1);
  ClipResult result, main_result;
  const auto motions = overlay_motions(system, initial, clip, options_for(3), times, result);
  const MechanismMotion main = sample_mechanism_motion(system, initial, options_for(3), times, 1, main_result);
  ASSERT_EQ(motions.size(), 1U);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(motions[0].samples[k].pose, main.samples[k].pose);

  // Another integrator: close over a short time (both accurate), not identical.
  SimulationOptions rk4 = options_for(3);
  rk4.integrator = IntegratorKind::rk4;
  clip.compare = MechanismRun{nullptr, initial, rk4, "integrator=rk4"};
  const auto other = overlay_motions(system, initial, clip, options_for(3), times_to(1, 0.1), result);
  const double gap = pose_gap(other[0].samples.back().pose, main.samples[10].pose);
  EXPECT_GT(gap, 0);
  EXPECT_LT(gap, 1e-3);
}

std::string bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(MechanismOverlay, StillsDrawTheEnsembleTheSameEveryTime) {
  const sym::System system = high_double_pendulum();
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  test::TempDir dir;
  MechanismClip clip;
  clip.settings.width = 320;
  clip.settings.height = 180;
  clip.settings.at = 8;
  clip.simulation.duration = 8;
  clip.theme = load_theme("light", {}, "theme");
  clip.out = (dir / "plain.png").string();
  (void)produce_mechanism_clip(system, initial, clip);
  clip.ensemble = 20;
  clip.out = (dir / "a.png").string();
  (void)produce_mechanism_clip(system, initial, clip);
  clip.out = (dir / "b.png").string();
  (void)produce_mechanism_clip(system, initial, clip);
  EXPECT_EQ(bytes(dir / "a.png"), bytes(dir / "b.png"));
  EXPECT_NE(bytes(dir / "a.png"), bytes(dir / "plain.png"));
}

TEST(MechanismOverlay, BadEnsembleIsAnError) {
  const sym::System system(load_mechanism("double-pendulum"));
  MechanismClip clip;
  clip.out = "x.png";
  clip.ensemble = 1;
  EXPECT_THROW(clip.validate(system), Error);
  clip.ensemble = 201;
  EXPECT_THROW(clip.validate(system), Error);
  clip.ensemble = 20;
  clip.spread = 0;
  EXPECT_THROW(clip.validate(system), Error);
  clip.spread = std::nan("");
  EXPECT_THROW(clip.validate(system), Error);
  clip.spread = 1e-6;
  EXPECT_NO_THROW(clip.validate(system));
}

}  // namespace
}  // namespace linkage
