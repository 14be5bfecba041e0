// `linkage mechanisms`: the shipped mechanisms as a table, one described, and a bad
// mechanism file refused in one line with its position (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::lines_of;

void expect_one_line_error(const test::RunResult& r, const std::vector<std::string>& pieces) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("linkage: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const std::string& piece : pieces) EXPECT_NE(r.err.find(piece), std::string::npos) << piece << "\n" << r.err;
}

TEST(MechanismsCommand, ListsTheShippedMechanismsAsATable) {
  const test::RunResult r = test::run_linkage({"mechanisms"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_GE(lines.size(), 8u) << r.out;
  EXPECT_EQ(lines[0], "name              bodies joints dof  title");
  // name, bodies, joints, degrees of freedom, title; sorted by name, columns aligned.
  const std::vector<std::string> rows{
      "cart-pendulum          2      2   1  Cart-pendulum: a cart moved by a motor, a pendulum free on it",
      "coupled-pendulums      3      3   3  Coupled pendulums: three rods joined by two springs",
      "double-pendulum        2      2   2  Double pendulum: two uniform rods from a ground pin",
      "engine                 3      4   0  Engine: a slider-crank driven at constant crank speed",
      "four-bar               3      4   1  Four-bar linkage: a Grashof crank-rocker",
      "four-bar-driven        3      4   0  Four-bar driven at constant crank speed: a crank-rocker",
      "four-bar-spring        3      4   1  Four-bar on a spring: the rocker held by a torsional spring",
      "gear-train             2      3   1  Gear train: a motor's pinion drives a loaded gear",
      "quick-return           4      6   0  Quick-return: a crank driving a slotted lever and a ram",
      "rolling-disc           2      2   2  Rolling disc and hoop: which rolls down the incline faster",
      "slider-crank           3      4   1  Slider-crank: crank, connecting rod and piston on a slider",
      "spring-pendulum        1      0   3  Spring pendulum: a disc on a spring-damper from a fixed point",
      "triple-pendulum        3      3   3  Triple compound pendulum: a rod, a plate and a disc",
      "two-blocks             2      1   4  Two identical uniform blocks joined by a frictionless pin",
      "unequal-blocks         2      1   4  Two different blocks joined by a pin away from their middles",
      "welded-pendulum        2      2   1  Welded pendulum: two rods welded square into one swinging L"};
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(lines[i + 1], rows[i]);
  for (const std::string& line : lines) EXPECT_LE(line.size(), 100u) << line;
}

TEST(MechanismsCommand, DescribesOne) {
  const test::RunResult r = test::run_linkage({"mechanisms", "four-bar"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  EXPECT_EQ(lines.at(0), "four-bar: Four-bar linkage: a Grashof crank-rocker");
  EXPECT_EQ(lines.at(1), "(built-in four-bar.toml)");
  for (const std::string& line : lines) EXPECT_LE(line.size(), 80u) << line;
  for (const std::string& piece :
       {std::string("\nA closed loop: crank 2 and rocker 4"), std::string("\n  a   = 0.1\n"),
        std::string("Ground points: O2 = (0, 0), O4 = (d, 0)\n"),
        std::string("  2  rod, mass ma, length a\n     points O2 = (-a/2, 0), A = (a/2, 0)\n"),
        std::string("  O2  pin  ground.O2 - 2.O2  tree, adds 2.theta\n"),
        std::string("  B   pin  3.B - 4.B         loop\n"), std::string("Degrees of freedom: 1\n"),
        std::string("Generalized coordinates (Case 2 and Case 3): 2.theta, 3.theta, 4.theta\n"),
        std::string("Loop joints (their forces stay in Case 2 and Case 3): B\n"),
        std::string("  2.theta     1         3\n"),
        std::string("  independent (kept when the loops are closed): 2.theta\n")})
    EXPECT_NE(r.out.find(piece), std::string::npos) << piece << "\n" << r.out;

  for (const std::string name :
       {"double-pendulum", "slider-crank", "spring-pendulum", "triple-pendulum", "two-blocks", "unequal-blocks"}) {
    const test::RunResult each = test::run_linkage({"mechanisms", name});
    ASSERT_EQ(each.exit_code, 0) << name << ": " << each.err;
    for (const std::string& line : lines_of(each.out)) EXPECT_LE(line.size(), 80u) << name << ": " << line;
  }

  const test::RunResult spring = test::run_linkage({"mechanisms", "spring-pendulum"});
  ASSERT_EQ(spring.exit_code, 0) << spring.err;
  EXPECT_NE(spring.out.find("  k1  ground.O - 1.C  stiffness k, rest length l0, damping c\n"), std::string::npos)
      << spring.out;
  EXPECT_NE(spring.out.find("Generalized coordinates (Case 2 and Case 3): 1.x, 1.y, 1.theta\n"), std::string::npos);
}

TEST(MechanismsCommand, DescribesAFile) {
  test::TempDir dir;
  test::write_text(dir / "rod.toml",
                   "title = \"One rod\"\n[ground]\npoints = { O = [0, 0] }\n[[body]]\nname = \"r\"\nshape = \"rod\"\n"
                   "mass = 1\nlength = 0.5\npoints = { O = [-0.25, 0] }\n[[joint]]\nname = \"O\"\ntype = \"pin\"\n"
                   "bodies = [\"ground\", \"r\"]\npoints = [\"O\", \"O\"]\n"
                   "[[torque]]\nbody = \"r\"\nvalue = \"sin(t)\"\n[initial]\nr = { theta = 0.5 }\n");
  const test::RunResult r = test::run_linkage({"mechanisms", (dir / "rod.toml").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("rod: One rod\n(" + (dir / "rod.toml").string() + ")\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("Gravity: none\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  torque  on r  sin(t)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  r.theta     0.5    0\n"), std::string::npos) << r.out;
}

TEST(MechanismsCommand, BadFileOrNameExitsTwoInOneLine) {
  test::TempDir dir;
  const std::string file = (dir / "bad.toml").string();
  test::write_text(dir / "bad.toml", "[[body]]\nname = \"1\"\nshape = \"circle\"\nmass = 1\n");
  expect_one_line_error(
      test::run_linkage({"mechanisms", file}),
      {file + ":3:9: body '1': 'shape' = 'circle' is not valid", "valid: rectangle, rod, disc, ring, point"});
  expect_one_line_error(
      test::run_linkage({"mechanisms", "to-blocks"}),
      {"mechanisms: 'to-blocks' is not a shipped mechanism (did you mean 'two-blocks'?)",
       "valid: cart-pendulum, coupled-pendulums, double-pendulum, engine, four-bar", "or a file path"});
  expect_one_line_error(test::run_linkage({"mechanisms", (dir / "none.toml").string()}),
                        {"mechanisms: file", "none.toml' does not exist"});
  expect_one_line_error(test::run_linkage({"mechanisms", dir.path().string() + "/"}), {"is a folder"});
}

}  // namespace
}  // namespace linkage
