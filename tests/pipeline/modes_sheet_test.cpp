// Every mode in one still (`render --modes-sheet`, issue 26): each panel draws the
// mechanism at the equilibrium displaced by +A and -A along the mode's shape (loops closed),
// all panels through one camera, captioned with the frequencies modal_analysis computes.
#include "pipeline/modes_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "model/mechanism_toml.hpp"
#include "render/theme.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

namespace fs = std::filesystem;

struct Modes {
  explicit Modes(Mechanism mechanism)
      : system(std::move(mechanism)), linear(linearize(system)), modes(modal_analysis(linear)) {}
  sym::System system;
  Linearization linear;
  ModalAnalysis modes;
};

MechanismClip sheet_clip() {
  MechanismClip clip;
  clip.theme = load_theme("light", {}, "theme");
  clip.settings.title = "a sheet";
  return clip;
}

/// q0 + sign A tree_shape / max |tree_shape|, as --mode scales a mode.
Eigen::VectorXd displaced(const Modes& m, const Mode& mode, double amplitude, double sign) {
  return m.linear.equilibrium + sign * amplitude / mode.tree_shape.cwiseAbs().maxCoeff() * mode.tree_shape;
}

void expect_outlines(const std::vector<MechanismDrawList::Outline>& drawn, const MechanismGeometry& geometry,
                     const std::vector<double>& pose) {
  ASSERT_EQ(drawn.size(), geometry.bodies.size());
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    const std::vector<Vec2> expected = body_outline(geometry.bodies[b], pose, b);
    ASSERT_EQ(drawn[b].points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_LT((drawn[b].points[i] - expected[i]).norm(), 1e-12);
  }
}

TEST(ModesSheet, TheDoublePendulumsPanelsDrawTheEquilibriumPlusAndMinusTheShape) {
  const Modes m(load_mechanism("double-pendulum"));
  ASSERT_EQ(m.modes.modes.size(), 2U);
  const MechanismClip clip = sheet_clip();
  const double amplitude = 0.2;
  const ModesSheet sheet(m.system, m.linear, m.modes, amplitude, clip);
  ASSERT_EQ(sheet.panels().size(), 2U);
  EXPECT_EQ(sheet.columns(), 2);
  EXPECT_EQ(sheet.rows(), 1);
  const MechanismGeometry geometry = mechanism_geometry(m.system);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const ModesSheetPanel& panel = sheet.panels()[k];
    const Mode& mode = m.modes.modes[k];
    const Eigen::VectorXd plus = displaced(m, mode, amplitude, 1), minus = displaced(m, mode, amplitude, -1);
    ASSERT_EQ(panel.plus.size(), 2);
    for (Eigen::Index i = 0; i < 2; ++i) {
      EXPECT_NEAR(panel.plus[i], plus[i], 1e-12);
      EXPECT_NEAR(panel.minus[i], minus[i], 1e-12);
    }
    // The rods' absolute angles are the tree coordinates: pose 3 b + 2 of each body.
    const std::vector<double>& at_plus = panel.motion.samples.back().pose;
    const std::vector<double>& at_minus = panel.motion.samples.front().pose;
    for (std::size_t b = 0; b < 2; ++b) {
      EXPECT_NEAR(at_plus[3 * b + 2], plus[static_cast<Eigen::Index>(b)], 1e-12);
      EXPECT_NEAR(at_minus[3 * b + 2], minus[static_cast<Eigen::Index>(b)], 1e-12);
      EXPECT_NEAR(panel.equilibrium_pose[3 * b + 2], m.linear.equilibrium[static_cast<Eigen::Index>(b)], 1e-12);
    }
    // The first rod hangs from the ground pin at the origin, its centre half a length out
    // along its angle: the pose is the mechanism's, not just the angles.
    const double half = 0.5 * geometry.bodies[0].length;
    EXPECT_NEAR(at_plus[0], half * std::cos(plus[0]), 1e-12);
    EXPECT_NEAR(at_plus[1], half * std::sin(plus[0]), 1e-12);
    // Drawn: the bodies at +A, the equilibrium faint, -A as the outlined ghost.
    expect_outlines(panel.list.outlines, geometry, at_plus);
    ASSERT_EQ(panel.list.ghosts.size(), 2U);
    EXPECT_FALSE(panel.list.ghosts[0].compare);
    expect_outlines(panel.list.ghosts[0].outlines, geometry, panel.equilibrium_pose);
    EXPECT_TRUE(panel.list.ghosts[1].compare);
    expect_outlines(panel.list.ghosts[1].outlines, geometry, at_minus);
    // Trails from -A to +A, of points that move.
    std::size_t trails = 0;
    for (const MechanismDrawList::Line& line : panel.list.lines) {
      if (line.kind != MechanismDrawList::Line::Kind::trail) continue;
      ++trails;
      EXPECT_GT((line.points.front() - line.points.back()).norm(), 1e-3);
    }
    EXPECT_GE(trails, 2U);
    // The caption: the frequency modal_analysis computes, and the shape as `modes` gives it.
    const double hz = mode.omega / (2 * std::numbers::pi);
    EXPECT_EQ(panel.heading, "mode " + std::to_string(k + 1) + " \u00b7 " + format_significant(hz, 3) + " Hz (" +
                                 format_significant(mode.omega, 3) + " rad/s)");
    EXPECT_EQ(panel.shape, m.linear.coordinates[0] + " : " + m.linear.coordinates[1] + " = " +
                               format_significant(mode.shape[0], 3) + " : " + format_significant(mode.shape[1], 3));
    // Every pose in the one camera's view.
    const View view = sheet.camera().visible();
    for (const auto* pose : {&at_plus, &at_minus})
      for (std::size_t b = 0; b < 2; ++b)
        for (const Vec2& p : body_outline(geometry.bodies[b], *pose, b)) {
          EXPECT_GT(p.x(), view.xmin);
          EXPECT_LT(p.x(), view.xmax);
          EXPECT_GT(p.y(), view.ymin);
          EXPECT_LT(p.y(), view.ymax);
        }
  }
  // In phase, then anti-phase: the double pendulum's two modes.
  EXPECT_GT(m.modes.modes[0].tree_shape[0] * m.modes.modes[0].tree_shape[1], 0);
  EXPECT_LT(m.modes.modes[1].tree_shape[0] * m.modes.modes[1].tree_shape[1], 0);
}

TEST(ModesSheet, AClosedLoopsPosesKeepTheIndependentCoordinateAndCloseTheLoop) {
  const Modes m(load_mechanism("four-bar-spring"));
  ASSERT_EQ(m.modes.modes.size(), 1U);
  const MechanismClip clip = sheet_clip();
  const ModesSheet sheet(m.system, m.linear, m.modes, 0.1, clip);
  ASSERT_EQ(sheet.panels().size(), 1U);
  const ModesSheetPanel& panel = sheet.panels()[0];
  const Mode& mode = m.modes.modes[0];
  const auto& coordinates = m.system.coordinates();
  for (const double sign : {1.0, -1.0}) {
    const Eigen::VectorXd linear = displaced(m, mode, 0.1, sign);
    const Eigen::VectorXd& drawn = sign > 0 ? panel.plus : panel.minus;
    for (const std::size_t i : m.linear.independent)
      EXPECT_NEAR(drawn[static_cast<Eigen::Index>(i)], linear[static_cast<Eigen::Index>(i)], 1e-12);
    // Closed: closing the loops again moves nothing; the dependent coordinates moved off
    // the linear prediction by the constraint's curvature (second order in A).
    GiNaC::exmap state;
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
      state[coordinates[i].symbols.q] = drawn[static_cast<Eigen::Index>(i)];
      state[coordinates[i].symbols.q_dot] = 0;
    }
    EXPECT_LT(sym::close_loops(m.system, state).largest_change, 1e-10);
    EXPECT_GT((drawn - linear).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(ModesSheet, AModeThatDoesNotOscillateIsDrawnStillAndSaysSo) {
  Mechanism inverted = load_mechanism("double-pendulum");
  apply_setting(inverted, "1.theta=-1.5", "test");
  apply_setting(inverted, "2.theta=1.5", "test");
  const Modes m(std::move(inverted));
  ASSERT_EQ(m.modes.modes[0].kind, Mode::Kind::unstable);
  const MechanismClip clip = sheet_clip();
  const ModesSheet sheet(m.system, m.linear, m.modes, 0.1, clip);
  const ModesSheetPanel& panel = sheet.panels()[0];
  EXPECT_EQ(panel.plus.size(), 0);
  EXPECT_TRUE(panel.list.ghosts.empty());
  EXPECT_EQ(panel.motion.samples.size(), 1U);
  EXPECT_NE(panel.heading.find("unstable, growth rate " + format_significant(m.modes.modes[0].growth_rate, 3)),
            std::string::npos)
      << panel.heading;
  EXPECT_NE(panel.shape.find("no oscillation"), std::string::npos) << panel.shape;
  EXPECT_EQ(sheet.panels()[1].kind, Mode::Kind::oscillation);
  EXPECT_EQ(sheet.panels()[1].list.ghosts.size(), 2U);
}

TEST(ModesSheet, WritesAPngSvgOrPdfWholeAndRefusesAVideo) {
  const Modes m(load_mechanism("double-pendulum"));
  MechanismClip clip = sheet_clip();
  clip.settings.width = 320;
  clip.settings.height = 180;
  const ModesSheet sheet(m.system, m.linear, m.modes, 0.1, clip);
  const test::TempDir dir;
  for (const char* name : {"sheet.png", "sheet.svg", "sheet.pdf"}) {
    sheet.write(dir.path() / name, "modes_sheet");
    EXPECT_GT(fs::file_size(dir.path() / name), 1000U) << name;
  }
  EXPECT_EQ(test::read_text(dir.path() / "sheet.png").substr(1, 3), "PNG");
  // A vector sheet keeps every panel a shape: no bitmap fallback (each panel's background,
  // painted with the SOURCE operator, must come before anything under it).
  const std::string svg = test::read_text(dir.path() / "sheet.svg");
  EXPECT_NE(svg.find("<path"), std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  try {
    sheet.write(dir.path() / "sheet.mp4", "modes_sheet");
    FAIL() << "a video was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.setting(), "modes_sheet");
  }
  EXPECT_FALSE(fs::exists(dir.path() / "sheet.mp4"));
  // Only the three files: no temporary left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 3);
}

TEST(ModesSheet, ThreeModesFillOneRowAndABadAmplitudeIsRefused) {
  const Modes m(load_mechanism(std::string(LINKAGE_SOURCE_DIR) + "/tests/data/mechanisms/coupled-pendulums.toml"));
  ASSERT_EQ(m.modes.modes.size(), 3U);
  const MechanismClip clip = sheet_clip();
  const ModesSheet sheet(m.system, m.linear, m.modes, 0.1, clip);
  EXPECT_EQ(sheet.columns(), 3);
  EXPECT_EQ(sheet.rows(), 1);
  for (const double bad : {0.0, -0.1, std::nan("")}) {
    try {
      const ModesSheet refused(m.system, m.linear, m.modes, bad, clip);
      ADD_FAILURE() << "amplitude " << bad << " was taken";
    } catch (const Error& e) {
      EXPECT_EQ(e.setting(), "amplitude");
    }
  }
}

}  // namespace
}  // namespace linkage
