// `linkage mechanisms [NAME|FILE]`: the shipped mechanisms as a table, or one described.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/write_stdout.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "model/mechanism_toml.hpp"
#include "model/spanning_tree.hpp"

namespace linkage::cli {
namespace {

constexpr std::size_t kWidth = 80;

std::string pad(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string pad_left(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

// Words of `text` in lines of at most kWidth columns (a longer word gets its own line).
std::string wrap(const std::string& text, const std::string& indent) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, end - start);
    start = end + 1;
    if (word.empty()) continue;
    if (!line.empty() && indent.size() + line.size() + 1 + word.size() > kWidth) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += indent + line + "\n";
  return out;
}

std::string vector_text(const Vector2Quantity& v) { return "(" + v.x.text + ", " + v.y.text + ")"; }

std::string points_text(const std::vector<NamedPoint>& points) {
  std::string out;
  for (const NamedPoint& p : points) out += (out.empty() ? "" : ", ") + p.name + " = " + vector_text(p.at);
  return out.empty() ? "none" : out;
}

// Rows of cells as aligned columns, two spaces apart (one before a right-aligned column,
// whose short numbers stand apart already), each line indented.
std::string table(const std::vector<std::vector<std::string>>& rows, const std::string& indent,
                  const std::vector<bool>& right = {}) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (widths.size() <= i) widths.push_back(0);
      widths[i] = std::max(widths[i], row[i].size());
    }
  std::string out;
  for (const auto& row : rows) {
    std::string line = indent;
    for (std::size_t i = 0; i < row.size(); ++i) {
      const bool last = i + 1 == row.size();
      const bool align_right = i < right.size() && right[i];
      line += align_right ? pad_left(row[i], widths[i]) : last ? row[i] : pad(row[i], widths[i]);
      if (!last) line += i + 1 < right.size() && right[i + 1] ? " " : "  ";
    }
    out += line + "\n";
  }
  return out;
}

std::string list_mechanisms() {
  std::vector<std::vector<std::string>> rows{{"name", "bodies", "joints", "dof", "title"}};
  for (const std::string& name : shipped_mechanism_names()) {
    const Mechanism m = load_mechanism(name);
    rows.push_back({name, std::to_string(m.bodies.size()), std::to_string(m.joints.size()),
                    std::to_string(degrees_of_freedom(m)), m.title});
  }
  return table(rows, "", {false, true, true, true, false}) +
         "\n'linkage mechanisms NAME' describes one; a FILE of your own works too (mechanisms/README.md).\n";
}

std::string body_sizes(const Body& body) {
  std::string out = std::string(kShapeNames[static_cast<std::size_t>(body.shape)]) + ", mass " + body.mass.text;
  if (body.length) out += ", length " + body.length->text;
  if (body.width) out += ", width " + body.width->text;
  if (body.radius) out += ", radius " + body.radius->text;
  if (body.inertia) out += ", inertia " + body.inertia->text;
  return out;
}

std::string describe_mechanism(const Mechanism& m) {
  const SpanningTree tree = spanning_tree(m);
  std::string out = m.name + ": " + m.title + "\n(" + m.source + ")\n";
  if (!m.description.empty()) out += "\n" + wrap(m.description, "");

  auto section = [&](const std::string& heading, const std::string& body) {
    out += "\n" + heading + "\n" + (body.empty() ? "  none\n" : body);
  };
  std::vector<std::vector<std::string>> rows;
  for (const Parameter& p : m.parameters) rows.push_back({p.name, "= " + format_roundtrip(p.value)});
  section("Parameters", rows.empty() ? "" : table(rows, "  "));
  rows.clear();
  for (const Definition& d : m.definitions) rows.push_back({d.name, "= " + d.value.text});
  section("Definitions", rows.empty() ? "" : table(rows, "  "));
  out += "\nGravity: " + (m.gravity ? m.gravity->text + " along -y" : std::string("none")) + "\n";
  out += "Ground points: " + points_text(m.ground_points) + "\n";

  // Each body on two lines: what it is, then its points (a long list wraps).
  std::size_t name_width = 0;
  for (const Body& b : m.bodies) name_width = std::max(name_width, b.name.size());
  std::string bodies;
  for (const Body& b : m.bodies)
    bodies += "  " + pad(b.name, name_width) + "  " + body_sizes(b) + "\n" +
              wrap("points " + points_text(b.points), std::string(name_width + 4, ' '));
  section("Bodies", bodies);

  rows.clear();
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    const Joint& joint = m.joints[j];
    std::string role = "loop";
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      if (tree.bodies[i].joint != static_cast<int>(j)) continue;
      role = "tree, adds no coordinate";  // a weld's child (or a point mass on a pin)
      for (const Coordinate& c : tree.coordinates)
        if (c.body == static_cast<int>(i)) role = "tree, adds " + c.key;
    }
    std::string extra;
    if (joint.axis) extra += ", axis " + vector_text(*joint.axis);
    if (joint.radius) extra += ", radius " + joint.radius->text;
    if (joint.stiffness) extra += ", stiffness " + joint.stiffness->text;
    if (joint.damping) extra += ", damping " + joint.damping->text;
    if (joint.rest_angle) extra += ", rest angle " + joint.rest_angle->text;
    if (joint.angle) extra += ", angle " + joint.angle->text;
    if (joint.radii)
      extra += ", radii " + (*joint.radii)[0].text + ", " + (*joint.radii)[1].text + ", carrier " + joint.carrier +
               (joint.internal ? ", internal" : "");
    rows.push_back({joint.name, kJointTypeNames[static_cast<std::size_t>(joint.type)],
                    joint.bodies[0] + "." + joint.points[0] + " - " + joint.bodies[1] + "." + joint.points[1],
                    role + extra});
  }
  section("Joints (force reported: what the second body exerts on the first)", rows.empty() ? "" : table(rows, "  "));

  rows.clear();
  for (const Spring& s : m.springs)
    rows.push_back(
        {s.name, s.between[0].body + "." + s.between[0].point + " - " + s.between[1].body + "." + s.between[1].point,
         "stiffness " + s.stiffness.text + ", rest length " + s.rest_length.text + ", damping " + s.damping.text});
  section("Springs", rows.empty() ? "" : table(rows, "  "));

  rows.clear();
  for (const AppliedForce& f : m.forces)
    rows.push_back({"force", "on " + f.body + "." + f.point, vector_text(f.value)});
  for (const AppliedTorque& t : m.torques) rows.push_back({"torque", "on " + t.body, t.value.text});
  section("Applied loads", rows.empty() ? "" : table(rows, "  "));

  std::string coordinates;
  for (const Coordinate& c : tree.coordinates) coordinates += (coordinates.empty() ? "" : ", ") + c.key;
  std::string loops;
  for (int j : tree.loop_joints) loops += (loops.empty() ? "" : ", ") + m.joints[static_cast<std::size_t>(j)].name;
  out += "\nDegrees of freedom: " + std::to_string(degrees_of_freedom(m)) + "\n";
  out += "Generalized coordinates (Case 2 and Case 3): " + coordinates + "\n";
  out += "Loop joints (their forces stay in Case 2 and Case 3): " + (loops.empty() ? "none" : loops) + "\n";

  rows = {{"coordinate", "value", "rate"}};
  auto value_of = [&](const std::string& key) -> std::string {
    for (const InitialValue& v : m.initial)
      if (v.key == key) return format_roundtrip(v.value);
    return "0";
  };
  for (const Coordinate& c : tree.coordinates) rows.push_back({c.key, value_of(c.key), value_of(c.key + "_dot")});
  std::string initial = table(rows, "  ");
  if (!m.independent.empty()) {
    std::string kept;
    for (const std::string& k : m.independent) kept += (kept.empty() ? "" : ", ") + k;
    initial += "  independent (kept when the loops are closed): " + kept + "\n";
  }
  section("Initial state (rates not given are 0)", initial);
  return out;
}

void run_mechanisms(const std::string& which) {
  if (which.empty()) {
    write_stdout(list_mechanisms(), "the list of mechanisms");
    return;
  }
  try {
    write_stdout(describe_mechanism(load_mechanism(which)), "the description");
  } catch (const Error& e) {
    // The mechanism is the command's argument here, not a --mechanism flag.
    if (e.setting() == "mechanism") throw e.rephrased("mechanisms: " + e.detail());
    throw;
  }
}

}  // namespace

void register_mechanisms(CLI::App& app) {
  auto which = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "mechanisms",
      "List the shipped mechanisms (name, bodies, joints, degrees of freedom, title), or describe one: its "
      "parameters, bodies, joints, loads, generalized coordinates, loop joints and initial state");
  sub->add_option("mechanism", *which,
                  "A shipped mechanism's NAME, or a mechanism FILE (with '/' or ending in .toml; the format is in "
                  "mechanisms/README.md)")
      ->type_name("NAME|FILE");
  add_runner(sub, [which] { run_mechanisms(*which); });
}

}  // namespace linkage::cli
