// The mechanism file reader: every shipped file reads as documented, and every structural
// mistake is one line "FILE:LINE:COLUMN: what is wrong; valid: ..." (exit code 2).
#include "model/mechanism_toml.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

#include "core/error.hpp"
#include "model/inputs.hpp"
#include "model/spanning_tree.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

namespace fs = std::filesystem;

// A pendulum: one rod from a ground pin. Cases below change one line of it.
const std::vector<std::string> kPendulum{
    "title = \"A rod from a pin\"",                      // 1
    "gravity = \"g\"",                                   // 2
    "[parameters]",                                      // 3
    "l = 0.3",                                           // 4
    "m = 0.2",                                           // 5
    "g = 9.81",                                          // 6
    "[ground]",                                          // 7
    "points = { O = [0, 0] }",                           // 8
    "[[body]]",                                          // 9
    "name = \"1\"",                                      // 10
    "shape = \"rod\"",                                   // 11
    "mass = \"m\"",                                      // 12
    "length = \"l\"",                                    // 13
    "points = { O = [\"-l/2\", 0], A = [\"l/2\", 0] }",  // 14
    "[[joint]]",                                         // 15
    "name = \"O\"",                                      // 16
    "type = \"pin\"",                                    // 17
    "bodies = [\"ground\", \"1\"]",                      // 18
    "points = [\"O\", \"O\"]",                           // 19
    "[initial]",                                         // 20
    "\"1\" = { theta = -1, theta_dot = 0.5 }",           // 21
};

// The pendulum with lines (1-based) replaced by other text (which may hold several lines).
std::string pendulum_with(const std::map<std::size_t, std::string>& edits) {
  std::string out;
  for (std::size_t i = 0; i < kPendulum.size(); ++i) {
    const auto edit = edits.find(i + 1);
    out += (edit != edits.end() ? edit->second : kPendulum[i]) + "\n";
  }
  return out;
}

std::string pendulum_with(std::size_t line, const std::string& text) { return pendulum_with({{line, text}}); }

std::string pendulum() { return pendulum_with({}); }

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

std::string read_error(const std::string& text) {
  return error_of([&] { (void)read_mechanism(text, "m.toml"); });
}

// The message starts with the position and holds every piece, on one line.
void expect_error(const std::string& text, const std::string& position, const std::vector<std::string>& pieces) {
  const std::string message = read_error(text);
  EXPECT_EQ(message.rfind("m.toml:" + position + ": ", 0), 0u) << "expected at " << position << ": " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  for (const std::string& piece : pieces) EXPECT_NE(message.find(piece), std::string::npos) << piece << "\n" << message;
}

fs::path mechanisms_dir() { return fs::path(LINKAGE_SOURCE_DIR) / "mechanisms"; }

TEST(MechanismToml, ThePendulumReadsWithPositions) {
  const Mechanism m = read_mechanism(pendulum(), "dir/m.toml");
  EXPECT_EQ(m.name, "m");
  EXPECT_EQ(m.source, "dir/m.toml");
  EXPECT_EQ(m.title, "A rod from a pin");
  ASSERT_TRUE(m.gravity.has_value());
  EXPECT_EQ(m.gravity->text, "g");
  ASSERT_EQ(m.parameters.size(), 3u);
  // File order, not toml++'s sorted order.
  EXPECT_EQ(m.parameters[0].name, "l");
  EXPECT_EQ(m.parameters[1].name, "m");
  EXPECT_EQ(m.parameters[2].name, "g");
  EXPECT_EQ(m.parameters[0].value, 0.3);
  EXPECT_EQ(m.parameters[0].pos.file, "dir/m.toml");
  EXPECT_EQ(m.parameters[0].pos.line, 4);
  EXPECT_EQ(m.parameters[0].pos.column, 5);
  ASSERT_EQ(m.bodies.size(), 1u);
  const Body& rod = m.bodies[0];
  EXPECT_EQ(rod.shape, Shape::rod);
  EXPECT_EQ(rod.mass.text, "m");
  EXPECT_EQ(rod.mass.pos.line, 12);
  EXPECT_EQ(rod.mass.pos.column, 8);
  ASSERT_TRUE(rod.length.has_value());
  EXPECT_FALSE(rod.width.has_value());
  ASSERT_EQ(rod.points.size(), 2u);
  EXPECT_EQ(rod.points[0].name, "O");
  EXPECT_EQ(rod.points[0].at.x.text, "-l/2");
  EXPECT_EQ(rod.points[0].at.y.text, "0");
  EXPECT_EQ(rod.points[1].name, "A");
  EXPECT_EQ(rod.points[1].pos.line, 14);
  ASSERT_EQ(m.ground_points.size(), 1u);
  EXPECT_EQ(m.ground_points[0].name, "O");
  ASSERT_EQ(m.joints.size(), 1u);
  EXPECT_EQ(m.joints[0].bodies[0], "ground");
  EXPECT_EQ(m.joints[0].points[1], "O");
  EXPECT_EQ(m.joints[0].type, JointType::pin);
  ASSERT_EQ(m.initial.size(), 2u);
  EXPECT_EQ(m.initial[0].key, "1.theta");
  EXPECT_EQ(m.initial[0].value, -1);
  EXPECT_EQ(m.initial[1].key, "1.theta_dot");
  EXPECT_EQ(m.initial[1].value, 0.5);
  EXPECT_EQ(m.initial[1].pos.line, 21);
}

TEST(MechanismToml, NumbersKeepTheirShortestTextAndExpressionsTheirs) {
  const Mechanism m =
      read_mechanism(pendulum_with(13, "length = 0.30000000000000004") + "[definitions]\nD = 0.1\n", "m.toml");
  EXPECT_EQ(m.bodies[0].length->text, "0.30000000000000004");
  const Mechanism n = read_mechanism(pendulum_with(13, "length = 3e-1"), "m.toml");
  EXPECT_EQ(n.bodies[0].length->text, "0.3");
  const Mechanism e = read_mechanism(pendulum_with(13, "length = \" l * 2 \""), "m.toml");
  EXPECT_EQ(e.bodies[0].length->text, " l * 2 ");
  ASSERT_EQ(m.definitions.size(), 1u);
  EXPECT_EQ(m.definitions[0].value.text, "0.1");
}

TEST(MechanismToml, EveryShippedMechanismReads) {
  const std::vector<std::string> names = shipped_mechanism_names();
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(mechanisms_dir()))
    if (entry.path().extension() == ".toml") files.push_back(entry.path().stem().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(names, files);
  EXPECT_EQ(names, (std::vector<std::string>{"cart-pendulum", "coupled-pendulums", "double-pendulum", "engine",
                                             "four-bar", "four-bar-driven", "four-bar-spring", "gear-train",
                                             "quick-return", "rolling-disc", "slider-crank", "spring-pendulum",
                                             "triple-pendulum", "two-blocks", "unequal-blocks", "welded-pendulum"}));
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const Mechanism built_in = load_mechanism(name);
    const Mechanism file = load_mechanism((mechanisms_dir() / (name + ".toml")).string());
    EXPECT_EQ(built_in.name, name);
    EXPECT_EQ(built_in.source, "built-in " + name + ".toml");
    EXPECT_EQ(file.name, name);
    // The program carries the files as they are in the tree.
    EXPECT_EQ(built_in.title, file.title);
    EXPECT_EQ(built_in.description, file.description);
    EXPECT_EQ(built_in.bodies.size(), file.bodies.size());
    EXPECT_EQ(built_in.initial.size(), file.initial.size());
    EXPECT_FALSE(built_in.title.empty());
    EXPECT_EQ(built_in.title.find('\n'), std::string::npos);
    EXPECT_GT(built_in.description.size(), 200u) << "one paragraph on what it teaches";
    ASSERT_TRUE(built_in.gravity.has_value());
    EXPECT_EQ(built_in.gravity->text, "g");
  }
}

TEST(MechanismToml, ShippedMechanismsHaveTheDocumentedStructure) {
  struct Expected {
    std::string name;
    std::size_t bodies, joints;
    int dof;
    std::size_t loops;
  };
  for (const Expected& e : std::vector<Expected>{{"two-blocks", 2, 1, 4, 0},
                                                 {"unequal-blocks", 2, 1, 4, 0},
                                                 {"double-pendulum", 2, 2, 2, 0},
                                                 {"triple-pendulum", 3, 3, 3, 0},
                                                 {"spring-pendulum", 1, 0, 3, 0},
                                                 {"slider-crank", 3, 4, 1, 1},
                                                 {"four-bar", 3, 4, 1, 1},
                                                 {"four-bar-spring", 3, 4, 1, 1},
                                                 {"coupled-pendulums", 3, 3, 3, 0},
                                                 {"welded-pendulum", 2, 2, 1, 0},
                                                 {"rolling-disc", 2, 2, 2, 0},
                                                 {"gear-train", 2, 3, 1, 1},
                                                 {"quick-return", 4, 6, 0, 2}}) {
    SCOPED_TRACE(e.name);
    const Mechanism m = load_mechanism(e.name);
    EXPECT_EQ(m.bodies.size(), e.bodies);
    EXPECT_EQ(m.joints.size(), e.joints);
    EXPECT_EQ(degrees_of_freedom(m), e.dof);
    EXPECT_EQ(spanning_tree(m).loop_joints.size(), e.loops);
  }
  const Mechanism triple = load_mechanism("triple-pendulum");
  EXPECT_EQ(triple.bodies[0].shape, Shape::rod);
  EXPECT_EQ(triple.bodies[1].shape, Shape::rectangle);
  EXPECT_EQ(triple.bodies[2].shape, Shape::disc);
  const Mechanism spring = load_mechanism("spring-pendulum");
  ASSERT_EQ(spring.springs.size(), 1u);
  EXPECT_EQ(spring.springs[0].between[0].body, "ground");
  EXPECT_EQ(spring.springs[0].damping.text, "c");
  EXPECT_EQ(load_mechanism("four-bar").independent, std::vector<std::string>{"2.theta"});
  EXPECT_EQ(load_mechanism("slider-crank").independent, std::vector<std::string>{"2.theta"});
}

double parameter(const Mechanism& m, const std::string& name) {
  for (const Parameter& p : m.parameters)
    if (p.name == name) return p.value;
  ADD_FAILURE() << name;
  return NAN;
}

double initial(const Mechanism& m, const std::string& key) {
  for (const InitialValue& v : m.initial)
    if (v.key == key) return v.value;
  return 0;
}

// The homework exactly as the spec's example (assets/spec/example.json).
// [picture]: the render's defaults a file states; the homework's are its clip's look.
TEST(MechanismToml, PictureGivesTheTitleTrailAndEnsembleCoordinate) {
  const Mechanism m = load_mechanism("two-blocks");
  EXPECT_EQ(m.picture.title, "Two blocks joined by a pin, falling freely");
  EXPECT_EQ(m.picture.trails, (std::vector<std::string>{"1.P"}));
  EXPECT_EQ(m.picture.ensemble, "1.theta");
  EXPECT_EQ(m.unaliased("theta1"), "1.theta");
  EXPECT_EQ(m.unaliased("L"), "L");
  const Mechanism plain = load_mechanism("four-bar");
  EXPECT_TRUE(plain.picture.title.empty());
  EXPECT_TRUE(plain.picture.trails.empty());
  const std::string point_mass =
      "[[body]]\nname = \"1\"\nshape = \"point\"\nmass = 1\npoints = { P = [0, 0] }\n[initial]\n\"1\" = { x = 0, y = "
      "0 }\n[picture]\n";
  EXPECT_EQ(read_mechanism(point_mass + "trail = [\"1.P\", \"1.P\"]\n", "m.toml").picture.trails.size(), 2U);
  try {
    (void)read_mechanism(point_mass + "trail = [\"1.P\", \"2.P\"]\n", "m.toml");
    ADD_FAILURE() << "a trail of no point read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("m.toml:9:17: [picture]: trail '2.P' is not a named point", 0), 0U)
        << e.what();
  }
}

// [table]: the default table of an interface built on the file; two-blocks' is the
// spec's (the homework's CSV columns through its [aliases]), in its order.
TEST(MechanismToml, TableGivesTheInterfacesColumnsInOrder) {
  const Mechanism m = load_mechanism("two-blocks");
  std::string names;
  for (const TableColumn& c : m.table) {
    if (!names.empty()) names += ',';
    names += m.aliased(c.name);
  }
  EXPECT_EQ(names,
            "t,x1,y1,theta1,theta2,x1_dot,y1_dot,theta1_dot,theta2_dot,x2,y2,x2_dot,y2_dot,x1_ddot,y1_ddot,"
            "theta1_ddot,theta2_ddot,F_x,F_y,energy,momentum_x,momentum_y,angular_momentum,"
            "constraint_position_error,constraint_velocity_error");
  EXPECT_TRUE(load_mechanism("four-bar").table.empty());
  const std::string point_mass =
      "[[body]]\nname = \"1\"\nshape = \"point\"\nmass = 1\n[initial]\n\"1\" = { x = 0, y = 0 }\n[table]\n";
  const Mechanism two = read_mechanism(point_mass + "columns = [\"t\", \"1.x\"]\n", "m.toml");
  ASSERT_EQ(two.table.size(), 2U);
  EXPECT_EQ(two.table[1].name, "1.x");
  EXPECT_EQ(two.table[1].pos.line, 8);
  EXPECT_EQ(two.table[1].pos.column, 17);
}

TEST(MechanismToml, TwoBlocksIsTheSpecExample) {
  const Mechanism m = load_mechanism("two-blocks");
  const auto& example = test::spec_example();
  for (const char* name : {"L", "w", "b", "m", "g"})
    EXPECT_EQ(parameter(m, name), example["parameters"][name].get<double>()) << name;
  const std::vector<std::pair<std::string, std::string>> state{
      {"1.x", "x1"},         {"1.y", "y1"},         {"1.theta", "theta1"},         {"2.theta", "theta2"},
      {"1.x_dot", "x1_dot"}, {"1.y_dot", "y1_dot"}, {"1.theta_dot", "theta1_dot"}, {"2.theta_dot", "theta2_dot"}};
  for (const auto& [key, spec] : state) EXPECT_EQ(initial(m, key), example["state"][spec].get<double>()) << key;
  ASSERT_EQ(m.definitions.size(), 1u);
  EXPECT_EQ(m.definitions[0].name, "D");
  EXPECT_EQ(m.definitions[0].value.text, "L/2 - b");
  for (const Body& body : m.bodies) {
    EXPECT_EQ(body.shape, Shape::rectangle);
    EXPECT_EQ(body.mass.text, "m");
    EXPECT_EQ(body.length->text, "L");
    EXPECT_EQ(body.width->text, "w");
    EXPECT_FALSE(body.inertia.has_value());
  }
  EXPECT_EQ(m.bodies[0].points[0].at.x.text, "D");
  EXPECT_EQ(m.bodies[1].points[0].at.x.text, "-D");
  EXPECT_EQ(m.joints[0].name, "P");
  EXPECT_EQ(m.joints[0].bodies, (std::array<std::string, 2>{"1", "2"}));
}

// The homework's flags land on two-blocks.toml under their mechanism names, with their
// origin; values left at their defaults keep the file's positions.
TEST(MechanismToml, HomeworkInputsSetTheTwoBlocksFile) {
  const Mechanism plain = default_mechanism(Inputs{});
  for (const InputKey& key : kInputKeys) {
    const std::string name(key.mechanism_key);
    const bool is_parameter = key.parameter;
    EXPECT_EQ(is_parameter ? parameter(plain, name) : initial(plain, name), Inputs{}.value(key)) << name;
  }
  Inputs inputs;
  inputs.set(*find_input_key("theta2_dot"), 1.25, "--theta2-dot");
  inputs.set(*find_input_key("L"), 0.5, "run.toml:2:5");
  const Mechanism set = default_mechanism(inputs);
  EXPECT_EQ(initial(set, "2.theta_dot"), 1.25);
  EXPECT_EQ(parameter(set, "L"), 0.5);
  for (const Parameter& p : set.parameters)
    EXPECT_EQ(p.pos.file, p.name == "L" ? "run.toml:2:5" : "two-blocks.toml") << p.name;
}

// The loops of the shipped closed mechanisms are closed to the six digits written.
TEST(MechanismToml, ShippedLoopsAreNearlyClosed) {
  const Mechanism four = load_mechanism("four-bar");
  const double a = parameter(four, "a"), b = parameter(four, "b"), c = parameter(four, "c"), d = parameter(four, "d");
  const double t2 = initial(four, "2.theta"), t3 = initial(four, "3.theta"), t4 = initial(four, "4.theta");
  EXPECT_NEAR(a * std::cos(t2) + b * std::cos(t3), d + c * std::cos(t4), 1e-6);
  EXPECT_NEAR(a * std::sin(t2) + b * std::sin(t3), c * std::sin(t4), 1e-6);
  const double w2 = initial(four, "2.theta_dot"), w3 = initial(four, "3.theta_dot"), w4 = initial(four, "4.theta_dot");
  EXPECT_NEAR(-a * std::sin(t2) * w2 - b * std::sin(t3) * w3, -c * std::sin(t4) * w4, 1e-6);
  EXPECT_NEAR(a * std::cos(t2) * w2 + b * std::cos(t3) * w3, c * std::cos(t4) * w4, 1e-6);

  const Mechanism crank = load_mechanism("slider-crank");
  const double r = parameter(crank, "r"), l = parameter(crank, "l");
  const double q2 = initial(crank, "2.theta"), q3 = initial(crank, "3.theta"), s = initial(crank, "S.s");
  EXPECT_NEAR(r * std::cos(q2) + l * std::cos(q3), s, 1e-6);
  EXPECT_NEAR(r * std::sin(q2) + l * std::sin(q3), 0, 1e-6);
  const double v2 = initial(crank, "2.theta_dot"), v3 = initial(crank, "3.theta_dot");
  EXPECT_NEAR(-r * std::sin(q2) * v2 - l * std::sin(q3) * v3, initial(crank, "S.s_dot"), 1e-6);
  EXPECT_NEAR(r * std::cos(q2) * v2 + l * std::cos(q3) * v3, 0, 1e-6);
  // A Grashof crank-rocker: shortest + longest < the other two, the crank the shortest.
  const double shortest = std::min({a, b, c, d}), longest = std::max({a, b, c, d});
  EXPECT_LT(shortest + longest, a + b + c + d - shortest - longest);
  EXPECT_EQ(shortest, a);
}

TEST(MechanismToml, SyntaxAndUnknownKeys) {
  expect_error(pendulum_with(12, "mass = = 1"), "12:8", {});
  expect_error(
      pendulum_with(1, "titel = \"x\""), "1:1",
      {"the top level: unknown key 'titel' (did you mean 'title'?)", "valid keys: title, description, gravity"});
  expect_error(pendulum_with(13, "lenght = \"l\""), "13:1",
               {"[[body]] number 1: unknown key 'lenght' (did you mean 'length'?)", "valid keys: name, shape, mass"});
  expect_error(pendulum_with(17, "typ = \"pin\""), "17:1", {"unknown key 'typ'", "(did you mean 'type'?)"});
  expect_error(pendulum_with(8, "point = { O = [0, 0] }"), "8:1",
               {"[ground]: unknown key 'point'", "valid keys: points"});
  expect_error(pendulum_with(21, "\"1\" = { thta = -1 }"), "21:9",
               {"[initial] '1': unknown key 'thta' (did you mean 'theta'?)",
                "valid keys: x, y, theta, x_dot, y_dot, theta_dot"});
  expect_error(pendulum_with(21, "\"2\" = { theta = -1 }"), "21:1",
               {"[initial]: '2' is not a body or slider joint", "valid: independent, 1"});
  expect_error(pendulum_with(21, "O = { s = 1 }"), "21:1", {"'O' is a pin"});
  // Points of one body, and keys of one table, are unique by TOML itself.
  expect_error(pendulum_with(14, "points = { O = [0, 0], O = [1, 0] }"), "14:28", {"cannot redefine"});
}

TEST(MechanismToml, WrongTypes) {
  expect_error(pendulum_with(12, "mass = true"), "12:8",
               {"body '1': 'mass' must be a number or an expression string, got a boolean"});
  expect_error(pendulum_with(1, "title = 3"), "1:9", {"'title' must be a string, got an integer"});
  expect_error(pendulum_with(1, "title = \"two\\nlines\""), "1:9", {"the title must be one line"});
  expect_error(pendulum_with(4, "l = \"0.3\""), "4:5",
               {"parameter 'l' must be a number or { value = NUMBER, unit = \"...\", meaning = \"...\" }, got a "
                "string; an expression belongs in [definitions]"});
  expect_error("body = 3\n", "1:8", {"'body' must be a list of tables, each written [[body]]"});
  expect_error(pendulum_with(14, "points = { O = [0] }"), "14:16",
               {"point 'O' must be [x, y], two numbers or expressions, got an array of 1 entries"});
  expect_error(pendulum_with(18, "bodies = \"ground\""), "18:10", {"'bodies' must be a list of two strings"});
  expect_error(pendulum_with(18, "bodies = [\"ground\", 1]"), "18:21",
               {"every entry of 'bodies' must be a string, got an integer"});
  expect_error(pendulum_with(21, "\"1\" = 3"), "21:7", {"[initial] '1' must be a table"});
  expect_error(pendulum_with(21, "\"1\" = { theta = \"-1\" }"), "21:17",
               {"[initial] '1': 'theta' must be a number, got a string"});
  expect_error(pendulum_with(13, "length = \"  \""), "13:10", {"'length' is an empty expression"});
  expect_error(pendulum_with({{1, "initial = [1]"}, {20, ""}, {21, ""}}), "1:11",
               {"'initial' must be a table, got an array"});
}

TEST(MechanismToml, ShapesAndTheirSizes) {
  expect_error(pendulum_with(11, "shape = \"circle\""), "11:9",
               {"body '1': 'shape' = 'circle' is not valid", "valid: rectangle, rod, disc, ring, point"});
  expect_error(pendulum_with(11, "shape = \"dics\""), "11:9", {"(did you mean 'disc'?)"});
  expect_error(pendulum_with(11, "shape = \"disc\""), "13:10", {"a disc has no 'length'; a disc takes radius"});
  expect_error(pendulum_with(11, "shape = \"point\""), "13:10", {"a point has no 'length'; a point takes no sizes"});
  expect_error(pendulum_with(11, "shape = \"rectangle\""), "9:1",
               {"body '1': a rectangle needs 'width'; a rectangle takes length, width"});
  expect_error(pendulum_with(13, "radius = 0.1"), "9:1", {"a rod needs 'length'"});
  expect_error(pendulum_with(11, "# no shape"), "9:1", {"body '1': the key 'shape' is required"});
  expect_error(pendulum_with(12, "# no mass"), "9:1", {"body '1': the key 'mass' is required"});
  // A disc with its radius and a point with no sizes read.
  const Mechanism disc =
      read_mechanism(pendulum_with({{11, "shape = \"disc\""}, {13, "radius = 0.1\ninertia = 1"}}), "m.toml");
  EXPECT_EQ(disc.bodies[0].shape, Shape::disc);
  EXPECT_EQ(disc.bodies[0].radius->text, "0.1");
  EXPECT_EQ(disc.bodies[0].inertia->text, "1");
  EXPECT_FALSE(disc.bodies[0].length.has_value());
  // A point mass has no angle: on a pin it has no coordinate at all.
  const Mechanism point = read_mechanism(
      pendulum_with({{11, "shape = \"point\""}, {13, ""}, {14, "points = { O = [0, 0] }"}, {21, ""}}), "m.toml");
  EXPECT_EQ(point.bodies[0].shape, Shape::point);
  EXPECT_FALSE(point.bodies[0].length.has_value());
  expect_error(pendulum_with({{11, "shape = \"point\""}, {13, ""}, {14, "points = { O = [0, 0] }"}}), "21:17",
               {"[initial] 1.theta is not a generalized coordinate or rate of this mechanism (body '1' is carried by "
                "pin 'O', a point mass with no angle: its coordinates: none); valid: none"});
}

TEST(MechanismToml, PlainNumbersOutOfRange) {
  expect_error(pendulum_with(12, "mass = 0"), "12:8", {"body '1': 'mass' = 0 kg is out of range; valid: a number > 0"});
  expect_error(pendulum_with(12, "mass = -1.5"), "12:8", {"'mass' = -1.5 kg is out of range"});
  expect_error(pendulum_with(13, "length = -0.3"), "13:10", {"'length' = -0.3 m is out of range"});
  expect_error(pendulum_with(13, "length = \"l\"\ninertia = 0"), "14:11", {"'inertia' = 0 kg m^2 is out of range"});
  expect_error(pendulum_with(12, "mass = inf"), "12:8", {"'mass' = inf is not a finite number"});
  expect_error(pendulum_with(12, "mass = nan"), "12:8", {"'mass' = nan is not a finite number"});
  expect_error(pendulum_with(5, "m = -inf"), "5:5", {"parameter 'm' = -inf is not a finite number"});
  expect_error(pendulum_with(14, "points = { O = [nan, 0], A = [0, 0] }"), "14:17", {"point 'O'[0] = nan"});
  expect_error(pendulum_with(21, "\"1\" = { theta = inf }"), "21:17",
               {"[initial] '1': 'theta' = inf is not a finite number"});
  expect_error(pendulum_with(2, "gravity = -9.81"), "2:11", {"gravity = -9.81 m/s^2 is out of range"});
  // Expressions are the symbolic layer's to check at the parameter values.
  EXPECT_NO_THROW((void)read_mechanism(pendulum_with(12, "mass = \"-m\""), "m.toml"));
}

// Issue 22 F14: a TOML table has no order, so a definition may use one defined below it.
TEST(MechanismToml, DefinitionsAreOrderedByUse) {
  const Mechanism m = read_mechanism(pendulum() + "[definitions]\nA = \"B + C\"\nB = \"2*C\"\nC = \"l\"\n", "m.toml");
  ASSERT_EQ(m.definitions.size(), 3u);
  EXPECT_EQ(m.definitions[0].name, "C");
  EXPECT_EQ(m.definitions[1].name, "B");
  EXPECT_EQ(m.definitions[2].name, "A");
  // Numbers and exponents are not names.
  const Mechanism n = read_mechanism(pendulum() + "[definitions]\nA = \"1e-3*B\"\nB = \"2.5E+2\"\n", "m.toml");
  EXPECT_EQ(n.definitions[0].name, "B");
  expect_error(pendulum() + "[definitions]\nA = \"B\"\nB = \"C + 1\"\nC = \"A\"\n", "23:5",
               {"definition 'A' depends on itself: A -> B -> C -> A"});
  expect_error(pendulum() + "[definitions]\nA = \"2*A\"\n", "23:5", {"definition 'A' depends on itself: A -> A"});
}

// Issue 22 F04: a value below double precision's normal range trapped in CLN.
TEST(MechanismToml, SubnormalValuesAreRefusedWhereRead) {
  expect_error(pendulum_with(4, "l = 5e-324"), "4:5",
               {"parameter 'l' = 5e-324 is out of range; valid: 0 or a magnitude of at least "
                "2.2250738585072014e-308 (double's normal range)"});
  expect_error(pendulum_with(21, "\"1\" = { theta = -1, theta_dot = -1e-310 }"), "21:33",
               {"theta_dot = -1e-310 is out of range"});
  Mechanism m = read_mechanism(pendulum(), "m.toml");
  EXPECT_NE(error_of([&] {
              set_value(m, "l", 1e-320, "--set l=1e-320");
            }).find("l = 1e-320 (--set l=1e-320) is out of range; valid: 0 or a magnitude of at least"),
            std::string::npos);
  EXPECT_NO_THROW(set_value(m, "l", 0, "--set l=0"));
  EXPECT_NO_THROW(set_value(m, "l", 2.2250738585072014e-308, "--set l=2.2250738585072014e-308"));
  EXPECT_NO_THROW(set_value(m, "l", 1e308, "--set l=1e308"));  // refused where it overflows, if it does
}

TEST(MechanismToml, Names) {
  expect_error(pendulum_with(4, "t = 0.3"), "4:1", {"parameter name 't' is reserved", "reserved: ground, t, pi, sin"});
  expect_error(pendulum_with(4, "pi = 3"), "4:1", {"parameter name 'pi' is reserved"});
  expect_error(pendulum_with(4, "sqrt = 3"), "4:1", {"parameter name 'sqrt' is reserved"});
  expect_error(pendulum_with(4, "2l = 3"), "4:1",
               {"parameter name '2l' is not valid; valid: a letter, then letters, digits or '_'"});
  expect_error(pendulum_with(4, "l-1 = 3"), "4:1", {"parameter name 'l-1' is not valid"});
  expect_error(pendulum() + "[definitions]\nl = \"2*m\"\n", "23:1",
               {"definition 'l' has the name of the parameter at line 4; names must be unique"});
  expect_error(pendulum() + "[definitions]\nexp = \"2*m\"\n", "23:1", {"definition name 'exp' is reserved"});
  expect_error(pendulum_with(10, "name = \"ground\""), "10:8", {"body name 'ground' is reserved"});
  expect_error(pendulum_with(10, "name = \"a.b\""), "10:8",
               {"body name 'a.b' is not valid; valid: a letter or digit, then letters, digits, '_' or '-'"});
  expect_error(pendulum_with(10, "name = \"\""), "10:8", {"body name '' is not valid"});
  expect_error(pendulum_with(16, "name = \"-O\""), "16:8", {"joint name '-O' is not valid"});
  expect_error(pendulum_with(14, "points = { \"O.1\" = [0, 0] }"), "14:12", {"point name 'O.1' is not valid"});
}

TEST(MechanismToml, DuplicateNames) {
  const std::string second_body =
      "[[body]]\nname = \"1\"\nshape = \"disc\"\nmass = 1\nradius = 0.1\npoints = { O = [0, 0] }\n";
  expect_error(pendulum() + second_body, "23:8", {"body name '1' is used twice (first at line 10)"});
  const std::string second_joint =
      "[[joint]]\nname = \"O\"\ntype = \"pin\"\nbodies = [\"ground\", \"1\"]\npoints = [\"O\", \"A\"]\n";
  expect_error(pendulum() + second_joint, "23:8", {"joint name 'O' is used twice (first at line 16)"});
  const std::string spring =
      "[[spring]]\nname = \"k\"\nbetween = [\"ground.O\", \"1.A\"]\nstiffness = 1\n"
      "rest_length = 0.1\n";
  expect_error(pendulum() + spring + spring, "28:8", {"spring name 'k' is used twice (first at line 23)"});
}

// The joint types' rows (model/joint_types.hpp) name the types in the messages about
// their keys: every type that does not take a key is told which types do.
TEST(MechanismToml, JointKeyMessagesNameTheTypesThatTakeThem) {
  EXPECT_EQ(joint_types_with(&JointTypeInfo::torsional_spring), "pins");
  EXPECT_EQ(joint_types_with(&JointTypeInfo::axis), "sliders, rolling joints and pin-slots");
  EXPECT_EQ(joint_types_with(&JointTypeInfo::radius), "rolling joints");
  int checked = 0;
  for (const JointTypeInfo& info : kJointTypes) {
    const std::string type = std::string("type = \"") + info.name + "\"\naxis = [1, 0]\n";
    const std::string takes = std::string("; a ") + info.name + " takes: " + info.options;
    if (!info.torsional_spring) {
      expect_error(pendulum_with(17, type + "damping = 0.5"), "19:11",
                   {"'damping' is for " + joint_types_with(&JointTypeInfo::torsional_spring) +
                    " only (a torsional spring-damper)" + takes});
      ++checked;
    }
    if (!info.axis) {
      expect_error(pendulum_with(17, type), "18:8",
                   {"'axis' is for " + joint_types_with(&JointTypeInfo::axis) + " only" + takes});
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

// A rolling joint's radius is its own, or by default its rolling body's disc radius (the
// quantity with its position); the line's axis is required as a slider's; two rows.
TEST(MechanismToml, RollingJointRadius) {
  const std::string head =
      "[parameters]\nr = 0.2\n[ground]\npoints = { O = [0, 0] }\n[[body]]\nname = \"w\"\nshape = \"disc\"\n"
      "mass = 1\nradius = \"r\"\npoints = { C = [0, 0] }\n[[joint]]\nname = \"R\"\ntype = \"rolling\"\n"
      "bodies = [\"ground\", \"w\"]\npoints = [\"O\", \"C\"]\n";
  const std::string initial = "[initial]\nw = { theta = 0 }\n";
  const Mechanism by_default = read_mechanism(head + "axis = [1, 0]\n" + initial, "m.toml");
  ASSERT_TRUE(by_default.joints[0].radius.has_value());
  EXPECT_EQ(by_default.joints[0].radius->text, "r");
  EXPECT_EQ(by_default.joints[0].radius->pos.line, 9);
  EXPECT_EQ(degrees_of_freedom(by_default), 1);
  const Mechanism own = read_mechanism(head + "axis = [1, 0]\nradius = \"r/2\"\n" + initial, "m.toml");
  EXPECT_EQ(own.joints[0].radius->text, "r/2");
  expect_error(head + initial, "11:1", {"joint 'R': a rolling needs 'axis'"});
}

TEST(MechanismToml, Joints) {
  expect_error(pendulum_with(18, "bodies = [\"ground\", \"2\"]"), "18:21",
               {"joint 'O': '2' is not a body; valid: ground, 1"});
  expect_error(pendulum_with(18, "bodies = [\"grund\", \"1\"]"), "18:11", {"(did you mean 'ground'?)"});
  expect_error(pendulum_with(19, "points = [\"O\", \"B\"]"), "19:16",
               {"joint 'O': body '1' has no point 'B'; valid: O, A"});
  expect_error(pendulum_with(19, "points = [\"Q\", \"O\"]"), "19:11", {"the ground has no point 'Q'; valid: O"});
  expect_error(pendulum_with(18, "bodies = [\"1\", \"1\"]"), "18:16",
               {"joint 'O' joins '1' to itself; give two different bodies"});
  expect_error(pendulum_with(17, "type = \"hinge\""), "17:8",
               {"joint 'O': 'type' = 'hinge' is not valid; valid: pin, slider"});
  expect_error(pendulum_with(19, "points = [\"O\", \"O\"]\naxis = [1, 0]"), "20:8",
               {"joint 'O': 'axis' is for sliders, rolling joints and pin-slots only; a pin takes: stiffness, damping, "
                "rest_angle"});
  expect_error(pendulum_with(17, "type = \"slider\""), "15:1",
               {"joint 'O': a slider needs 'axis', its direction [x, y] in the frame of 'ground'"});
  expect_error(pendulum_with(17, "type = \"slider\"\naxis = [1, 0]\nstiffness = 2"), "19:13",
               {"'stiffness' is for pins only"});
  expect_error(pendulum_with(17, "type = \"slider\"\naxis = [1, 0]\nrest_angle = 0.1"), "19:14",
               {"'rest_angle' is for pins only"});
  expect_error(pendulum_with(17, "type = \"slider\"\naxis = [0, 0.0]"), "18:9",
               {"'axis' = [0, 0] has no direction; valid: a nonzero vector"});
  expect_error(pendulum_with(19, "points = [\"O\", \"O\"]\nstiffness = -1"), "20:13",
               {"'stiffness' = -1 N m/rad is out of range; valid: a number >= 0"});
  expect_error(pendulum_with(19, "# none"), "15:1", {"joint 'O': the key 'points' is required"});

  const Mechanism spring_pin = read_mechanism(
      pendulum_with(19, "points = [\"O\", \"O\"]\nstiffness = \"k\"\ndamping = 0.1\nrest_angle = -1"), "m.toml");
  EXPECT_EQ(spring_pin.joints[0].stiffness->text, "k");
  EXPECT_EQ(spring_pin.joints[0].damping->text, "0.1");
  EXPECT_EQ(spring_pin.joints[0].rest_angle->text, "-1");
  EXPECT_FALSE(spring_pin.joints[0].axis.has_value());
}

// The contract's example of a slider: a block on a ground slider.
TEST(MechanismToml, SliderReads) {
  const std::string text =
      "[ground]\npoints = { O = [0, 0] }\n[[body]]\nname = \"block\"\nshape = \"rectangle\"\nmass = 1\nlength = 0.2\n"
      "width = 0.1\npoints = { C = [0, 0] }\n[[joint]]\nname = \"slide\"\ntype = \"slider\"\nbodies = [\"ground\", "
      "\"block\"]\npoints = [\"O\", \"C\"]\naxis = [\"cos(pi/6)\", 0.5]\n[initial]\nslide = { s = 0.1, s_dot = 2 }\n";
  const Mechanism m = read_mechanism(text, "slide.toml");
  ASSERT_TRUE(m.joints[0].axis.has_value());
  EXPECT_EQ(m.joints[0].axis->x.text, "cos(pi/6)");
  EXPECT_EQ(m.joints[0].axis->y.text, "0.5");
  EXPECT_EQ(m.initial[0].key, "slide.s");
  EXPECT_EQ(m.initial[1].key, "slide.s_dot");
  EXPECT_FALSE(m.gravity.has_value());
  EXPECT_EQ(m.title, "slide");  // no title: the file's name
  // A body carried by a slider has no theta coordinate.
  const std::string wrong = text.substr(0, text.find("slide = {")) + "block = { theta = 0 }\nslide = { s = 0 }\n";
  const std::string message = read_error(wrong);
  EXPECT_EQ(message.rfind("m.toml:17:19: [initial] block.theta is not a generalized coordinate", 0), 0u) << message;
  EXPECT_NE(message.find("(body 'block' is carried by slider 'slide': its coordinates: slide.s)"), std::string::npos)
      << message;
}

// [[driver]] (issue 25): read with its position; each mistake one line at its key.
TEST(MechanismToml, Drivers) {
  const std::string driver = "points = [\"O\", \"O\"]\n[[driver]]\nname = \"M\"\njoint = \"O\"\nmotion = \"w*t\"";
  const Mechanism m = read_mechanism(pendulum_with(19, driver), "m.toml");
  ASSERT_EQ(m.drivers.size(), 1u);
  EXPECT_EQ(m.drivers[0].name, "M");
  EXPECT_EQ(m.drivers[0].joint, "O");
  EXPECT_EQ(m.drivers[0].motion.text, "w*t");
  EXPECT_EQ(m.drivers[0].motion.pos.line, 23);
  EXPECT_EQ(m.drivers[0].motion.pos.column, 10);
  EXPECT_EQ(m.drivers[0].pos.line, 20);
  EXPECT_EQ(degrees_of_freedom(m), 0);  // the pendulum's one degree of freedom, taken by M
  EXPECT_EQ(degrees_of_freedom(read_mechanism(pendulum(), "m.toml")), 1);

  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = driver;
    text.replace(text.find(from), from.size(), to);
    return pendulum_with(19, text);
  };
  expect_error(with("joint = \"O\"", "joint = \"P\""), "22:9", {"driver 'M': 'P' is not a joint; valid: O"});
  expect_error(with("joint = \"O\"", "joint = \"o\""), "22:9", {"(did you mean 'O'?)"});
  expect_error(pendulum_with(19, driver + "\n[[driver]]\nname = \"N\"\njoint = \"O\"\nmotion = 0"), "26:9",
               {"driver 'N': joint 'O' is already driven by 'M' (line 20); a joint takes one driver"});
  expect_error(pendulum_with(19, driver + "\n[[driver]]\nname = \"M\"\njoint = \"O\"\nmotion = 0"), "25:8",
               {"driver name 'M' is used twice (first at line 21)"});
  expect_error(with("name = \"M\"", "name = \"1\""), "21:8",
               {"driver name '1' is the name of the body at line 9; a driver's name must differ from every body and "
                "joint name"});
  expect_error(with("name = \"M\"", "name = \"O\""), "21:8", {"driver name 'O' is the name of the joint at line 15"});
  expect_error(with("name = \"M\"", "name = \"ground\""), "21:8", {"driver name 'ground' is reserved"});
  expect_error(
      with("w*t", "w*t + 1.theta_dot"), "23:10",
      {"driver 'M': the motion \"w*t + 1.theta_dot\" uses the state '1.theta_dot'; valid: an expression in t"});
  expect_error(with("w*t", "sin(O.s)"), "23:10", {"uses the state 'O.s'"});
  expect_error(with("motion = \"w*t\"", "moton = 1"), "23:1", {"'moton'", "(did you mean 'motion'?)"});
  expect_error(with("motion = \"w*t\"", "# none"), "20:1", {"driver 'M': the key 'motion' is required"});
  // A number before a '.' is not a state, nor is a name that is no body or joint.
  EXPECT_EQ(read_mechanism(with("w*t", "1.5*t + w.x"), "m.toml").drivers[0].motion.text, "1.5*t + w.x");
}

TEST(MechanismToml, SpringsAndLoads) {
  const std::string loads =
      "[[spring]]\nname = \"k1\"\nbetween = [\"ground.O\", \"1.A\"]\nstiffness = \"2*m\"\nrest_length = 0.1\n"
      "[[force]]\nbody = \"1\"\npoint = \"A\"\nvalue = [\"0\", \"-sin(t)\"]\n"
      "[[torque]]\nbody = \"1\"\nvalue = \"0.1*cos(t)\"\n";
  const Mechanism m = read_mechanism(pendulum() + loads, "m.toml");
  ASSERT_EQ(m.springs.size(), 1u);
  EXPECT_EQ(m.springs[0].between[1].body, "1");
  EXPECT_EQ(m.springs[0].between[1].point, "A");
  EXPECT_EQ(m.springs[0].between[1].pos.line, 24);
  EXPECT_EQ(m.springs[0].between[1].pos.column, 24);
  EXPECT_EQ(m.springs[0].damping.text, "0");  // the default
  ASSERT_EQ(m.forces.size(), 1u);
  EXPECT_EQ(m.forces[0].value.y.text, "-sin(t)");
  ASSERT_EQ(m.torques.size(), 1u);
  EXPECT_EQ(m.torques[0].value.text, "0.1*cos(t)");

  const std::string spring_head = "[[spring]]\nname = \"k1\"\nstiffness = 1\nrest_length = 0.1\n";
  expect_error(pendulum() + spring_head + "between = [\"ground.O\", \"1.Q\"]\n", "26:24",
               {"spring 'k1': body '1' has no point 'Q'; valid: O, A"});
  expect_error(pendulum() + spring_head + "between = [\"ground.O\", \"3.A\"]\n", "26:24",
               {"spring 'k1': '3' is not a body; valid: ground, 1"});
  expect_error(pendulum() + spring_head + "between = [\"O\", \"1.A\"]\n", "26:12",
               {"'O' is not BODY.POINT; valid: e.g. \"ground.O\""});
  expect_error(pendulum() + spring_head + "between = [\"1.A\", \"1.A\"]\n", "26:19",
               {"spring 'k1' joins '1.A' to itself"});
  expect_error(pendulum() + spring_head + "between = [\"1.A\", \"ground.O\"]\ndamping = -2\n", "27:11",
               {"'damping' = -2 N s/m is out of range"});
  expect_error(pendulum() + "[[force]]\nbody = \"ground\"\npoint = \"O\"\nvalue = [0, 1]\n", "23:8",
               {"[[force]] number 1: 'ground' is not a body; valid: 1"});
  expect_error(pendulum() + "[[force]]\nbody = \"1\"\npoint = \"Z\"\nvalue = [0, 1]\n", "24:9",
               {"body '1' has no point 'Z'"});
  expect_error(pendulum() + "[[force]]\nbody = \"1\"\npoint = \"A\"\nvalue = 1\n", "25:9", {"'value' must be [x, y]"});
  expect_error(pendulum() + "[[torque]]\nbody = \"1\"\n", "22:1", {"[[torque]] number 1: the key 'value' is required"});
}

TEST(MechanismToml, NoBodies) {
  expect_error("title = \"nothing\"\n[initial]\n", "1:1", {"no [[body]]: a mechanism needs at least one body"});
}

TEST(MechanismToml, InitialState) {
  expect_error(pendulum_with(21, "\"1\" = { theta = -1, x = 0 }"), "21:25",
               {"[initial] 1.x is not a generalized coordinate or rate of this mechanism",
                "(body '1' is carried by pin 'O': its coordinates: 1.theta)",
                "valid: 1.theta and their rates (1.theta_dot, ...)"});
  expect_error(pendulum_with(21, "\"1\" = { theta_dot = 0 }"), "20:1",
               {"[initial] misses 1.theta; give every generalized coordinate: 1.theta (rates default to 0)"});
  expect_error(pendulum_with({{20, ""}, {21, ""}}), "1:1", {"[initial] misses 1.theta"});
  expect_error(pendulum_with(21, "independent = [\"1.x\"]\n\"1\" = { theta = 0 }"), "21:15",
               {"[initial] independent names '1.x', which is not a generalized coordinate; valid: 1.theta"});
  expect_error(pendulum_with(21, "independent = \"1.theta\"\n\"1\" = { theta = 0 }"), "21:15",
               {"'independent' must be a list of coordinates"});
  // Missing rates are fine: they default to 0.
  const Mechanism m = read_mechanism(pendulum_with(21, "\"1\" = { theta = 0.5 }"), "m.toml");
  ASSERT_EQ(m.initial.size(), 1u);
  EXPECT_EQ(m.initial[0].key, "1.theta");
  EXPECT_EQ(m.initial_pos.line, 20);
}

TEST(MechanismToml, SetValue) {
  Mechanism m = load_mechanism("two-blocks");
  set_value(m, "L", 0.4, "--set L=0.4");
  EXPECT_EQ(parameter(m, "L"), 0.4);
  set_value(m, "2.theta", 0.3, "--set");
  EXPECT_EQ(initial(m, "2.theta"), 0.3);
  const std::size_t before = m.initial.size();
  set_value(m, "2.theta_dot", -1, "lesson.toml:4:3");
  EXPECT_EQ(initial(m, "2.theta_dot"), -1);
  EXPECT_EQ(m.initial.size(), before);  // replaced, not added
  for (const InitialValue& v : m.initial)
    if (v.key == "2.theta_dot") {
      EXPECT_EQ(where(v.pos), "lesson.toml:4:3: ");
    }

  Mechanism pendulum_m = read_mechanism(pendulum(), "m.toml");
  set_value(pendulum_m, "1.theta_dot", 2, "--set");
  EXPECT_EQ(initial(pendulum_m, "1.theta_dot"), 2);

  const auto set_error = [&](const std::string& name, double value) {
    try {
      set_value(m, name, value, "--set " + name);
    } catch (const Error& e) {
      EXPECT_EQ(e.setting(), "set");
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      return e.detail();
    }
    ADD_FAILURE() << name;
    return std::string();
  };
  const std::string unknown = set_error("Lx", 1);
  EXPECT_EQ(unknown,
            "'Lx' (--set Lx) is not a parameter or initial coordinate of 'two-blocks' (did you mean 'L'?); valid "
            "parameters: L, w, b, m, g; coordinates: 1.x, 1.y, 1.theta, 2.theta and their rates (1.x_dot, ...)");
  EXPECT_NE(set_error("2.x", 1).find("is not a parameter or initial coordinate"), std::string::npos);
  EXPECT_NE(set_error("D", 1).find("'D' (--set D) is a definition (D = L/2 - b), not a parameter"), std::string::npos);
  EXPECT_NE(set_error("L", INFINITY).find("is not a finite number"), std::string::npos);
}

TEST(MechanismToml, LoadByNameOrFile) {
  const auto invalid = [](const std::string& name_or_file) {
    try {
      (void)load_mechanism(name_or_file);
    } catch (const Error& e) {
      EXPECT_EQ(e.setting(), "mechanism");
      return e.detail();
    }
    ADD_FAILURE() << name_or_file;
    return std::string();
  };
  EXPECT_EQ(
      invalid("for-bar"),
      "'for-bar' is not a shipped mechanism (did you mean 'four-bar'?); valid: cart-pendulum, coupled-pendulums, "
      "double-pendulum, engine, four-bar, four-bar-driven, four-bar-spring, gear-train, quick-return, rolling-disc, "
      "slider-crank, spring-pendulum, triple-pendulum, two-blocks, unequal-blocks, welded-pendulum, or a file "
      "path (with '/' or "
      "ending in .toml)");
  EXPECT_FALSE(is_mechanism_file("four-bar"));
  EXPECT_TRUE(is_mechanism_file("my.toml"));
  EXPECT_TRUE(is_mechanism_file("sub/four-bar"));
  EXPECT_FALSE(is_mechanism_file(".tom"));
  test::TempDir dir;
  EXPECT_NE(invalid((dir / "missing.toml").string()).find("does not exist"), std::string::npos);
  EXPECT_NE(invalid(dir.path().string() + "/").find("is a folder"), std::string::npos);
  EXPECT_NE(invalid("missing.toml").find("does not exist"), std::string::npos);

  test::write_text(dir / "pendulum.toml", pendulum());
  const Mechanism m = load_mechanism((dir / "pendulum.toml").string());
  EXPECT_EQ(m.name, "pendulum");
  EXPECT_EQ(m.bodies[0].mass.pos.file, (dir / "pendulum.toml").string());
  test::write_text(dir / "bad.toml", pendulum_with(12, "mass = 0"));
  const std::string message = error_of([&] { (void)read_mechanism_file(dir / "bad.toml"); });
  EXPECT_EQ(message.rfind((dir / "bad.toml").string() + ":12:8: body '1': 'mass' = 0 kg", 0), 0u) << message;
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

TEST(MechanismToml, ParametersMayCarryUnitAndMeaning) {
  const Mechanism m = read_mechanism(R"(
[parameters]
L = { value = 0.3, unit = "m", meaning = "block length" }
g = 9.81
[[body]]
name = "1"
shape = "point"
mass = 1
[initial]
"1" = { x = 0, y = 0 }
)",
                                     "m.toml");
  ASSERT_EQ(m.parameters.size(), 2u);
  EXPECT_EQ(m.parameters[0].value, 0.3);
  EXPECT_EQ(m.parameters[0].unit, "m");
  EXPECT_EQ(m.parameters[0].meaning, "block length");
  EXPECT_EQ(m.parameters[1].unit, "");
  try {
    (void)read_mechanism("[parameters]\nL = { value = 0.3, units = \"m\" }\n", "m.toml");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("m.toml:2:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'unit'"), std::string::npos) << e.what();
  }
  try {
    (void)read_mechanism("[parameters]\nL = { unit = \"m\" }\n", "m.toml");
    ADD_FAILURE() << "a parameter without a value was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("m.toml:2:5: parameter 'L': the key 'value' is required"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace linkage
