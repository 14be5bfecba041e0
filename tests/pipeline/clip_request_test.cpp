// A request made into the checked clip, as `linkage render` and a lesson's render step
// both do: the overlays, the trails, the equations (and a draft leaving out those that do
// not fit), the mechanism's title as the default, a compared run's system and start.
#include "pipeline/clip_request.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

/// Stands in for report's case_equations: which case was asked for, and enough lines.
EquationsText equations_of(const sym::System& /*system*/, int case_id) {
  EquationsText text{"Case " + std::to_string(case_id), {}};
  for (int i = 0; i < 6; ++i) text.lines.push_back("    (" + std::to_string(i) + ")  a long enough row of symbols");
  return text;
}

ClipPlan plan_into(const test::TempDir& dir, const std::string& out) {
  ClipPlan plan;
  plan.out = dir / out;
  plan.equations = equations_of;
  return plan;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

/// The homework, as every command runs it: two-blocks.toml from its initial state.
struct TwoBlocks {
  sym::System system{load_mechanism("two-blocks")};
  GiNaC::exmap initial = sym::checked_initial_state(system).state;
};

TEST(ClipRequest, HomeworkOverlaysAndEquations) {
  test::TempDir dir;
  const TwoBlocks homework;
  RenderRequest request;
  request.settings.at = 2;
  request.settings.elements.show(Element::equations);
  request.ensemble = 4;
  request.spread = 0.1;
  request.compare = "theta1=0.1000001,integrator=rk4";
  SimulationOptions simulation;
  simulation.case_id = 2;
  const CheckedMechanismClip made =
      mechanism_clip(request, homework.system, homework.initial, simulation, plan_into(dir, "fan.png"));
  const MechanismClip& clip = made.clip;
  EXPECT_EQ(clip.ensemble, 4);
  EXPECT_DOUBLE_EQ(clip.spread, 0.1);
  ASSERT_TRUE(clip.compare.has_value());
  EXPECT_EQ(clip.compare->label, "theta1=0.1000001, integrator=rk4");
  EXPECT_EQ(clip.compare->simulation.integrator, IntegratorKind::rk4);
  EXPECT_EQ(clip.settings.equations.heading, "Case 2");
  EXPECT_TRUE(clip.is_still());
  // theta1 (the alias of 1.theta) is the one initial value that differs, in the run's own system.
  ASSERT_NE(made.compared, nullptr);
  std::vector<double> differing;
  for (const auto& [symbol, value] : clip.compare->initial) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(symbol).get_name();
    for (const auto& [own, own_value] : homework.initial)
      if (GiNaC::ex_to<GiNaC::symbol>(own).get_name() == name && !(own_value - value).evalf().is_zero())
        differing.push_back(GiNaC::ex_to<GiNaC::numeric>(value.evalf()).to_double());
  }
  EXPECT_EQ(differing, std::vector<double>{0.1000001});
}

TEST(ClipRequest, ADraftLeavesOutEquationsThatDoNotFit) {
  test::TempDir dir;
  const TwoBlocks homework;
  RenderRequest request;
  request.settings.width = 320;
  request.settings.height = 180;
  request.settings.elements.show(Element::equations);
  ClipPlan plan = plan_into(dir, "a.png");
  EXPECT_NE(error_of([&] { (void)mechanism_clip(request, homework.system, homework.initial, {}, plan); }), "");
  plan.draft = true;
  const CheckedMechanismClip draft = mechanism_clip(request, homework.system, homework.initial, {}, plan);
  EXPECT_FALSE(draft.clip.settings.elements.has(Element::equations));
}

TEST(ClipRequest, CompareNamesFilesOnlyWhereThePlanAllows) {
  test::TempDir dir;
  const TwoBlocks homework;
  RenderRequest request;
  request.compare = "four-bar";
  ClipPlan plan = plan_into(dir, "a.png");
  EXPECT_NE(error_of([&] {
              (void)mechanism_clip(request, homework.system, homework.initial, {}, plan);
            }).find("a compared mechanism's bodies must be named as the clip's"),
            std::string::npos);
  plan.compare_files = false;
  plan.compare_origin = "compare";
  const std::string as_settings =
      error_of([&] { (void)mechanism_clip(request, homework.system, homework.initial, {}, plan); });
  EXPECT_NE(as_settings.find("'four-bar'"), std::string::npos) << as_settings;
  EXPECT_EQ(as_settings.find("bodies"), std::string::npos) << as_settings;
  EXPECT_EQ(compare_kind("run.csv"), CompareKind::trajectory);
  EXPECT_EQ(compare_kind("other.toml"), CompareKind::mechanism);
  EXPECT_EQ(compare_kind("L=0.4"), CompareKind::settings);
}

TEST(ClipRequest, AMechanismsTitleTrailsAndComparedRun) {
  test::TempDir dir;
  const sym::System system(load_mechanism("double-pendulum"));
  const GiNaC::exmap initial = sym::checked_initial_state(system).state;
  RenderRequest request;
  request.trails = {"2.A"};
  request.compare = "2.theta=-1.25,integrator=rk4";
  const CheckedMechanismClip made =
      mechanism_clip(request, system, initial, SimulationOptions{}, plan_into(dir, "a.png"));
  EXPECT_EQ(made.clip.settings.title, system.mechanism().title);
  EXPECT_EQ(made.clip.trails, std::vector<std::string>{"2.A"});
  ASSERT_TRUE(made.clip.compare.has_value());
  EXPECT_EQ(made.clip.compare->label, "2.theta=-1.25, integrator=rk4");
  ASSERT_NE(made.compared, nullptr) << "a changed coordinate gets its own system";
  EXPECT_EQ(made.clip.compare->system, made.compared.get());
  // It starts where the main run does but for 2.theta (its own symbols: matched by name).
  const auto by_name = [](const GiNaC::exmap& state) {
    std::map<std::string, double> out;
    for (const auto& [symbol, value] : state)
      out[GiNaC::ex_to<GiNaC::symbol>(symbol).get_name()] = GiNaC::ex_to<GiNaC::numeric>(value.evalf()).to_double();
    return out;
  };
  const std::map<std::string, double> main = by_name(initial), compared = by_name(made.clip.compare->initial);
  ASSERT_EQ(main.size(), compared.size());
  std::vector<double> differing;
  for (const auto& [name, value] : compared)
    if (main.at(name) != value) differing.push_back(value);
  EXPECT_EQ(differing, std::vector<double>{-1.25});

  request.titled = true;
  request.settings.title = "Own";
  request.compare = "case=1";
  const CheckedMechanismClip same =
      mechanism_clip(request, system, initial, SimulationOptions{}, plan_into(dir, "a.png"));
  EXPECT_EQ(same.clip.settings.title, "Own");
  ASSERT_TRUE(same.clip.compare.has_value());
  EXPECT_EQ(same.clip.compare->simulation.case_id, 1);
  EXPECT_EQ(same.compared, nullptr) << "only the case differs: the clip's own system";
  EXPECT_EQ(same.clip.compare->initial.size(), initial.size());

  request.trails = {"2.Q"};
  EXPECT_NE(error_of([&] {
              (void)mechanism_clip(request, system, initial, SimulationOptions{}, plan_into(dir, "a.png"));
            }).find("'Q' is not a point of 2"),
            std::string::npos);
}

TEST(ClipRequest, AnotherMechanismsBodiesMustBeTheClips) {
  test::TempDir dir;
  const sym::System system(load_mechanism("double-pendulum"));
  RenderRequest request;
  request.compare = "four-bar";
  EXPECT_NE(error_of([&] {
              (void)mechanism_clip(request, system, sym::checked_initial_state(system).state, SimulationOptions{},
                                   plan_into(dir, "a.png"));
            }).find("a compared mechanism's bodies must be named as the clip's"),
            std::string::npos);
}

}  // namespace
}  // namespace linkage
