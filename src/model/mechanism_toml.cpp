#include "model/mechanism_toml.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "model/inputs_toml.hpp"
#include "model/name_match.hpp"

namespace linkage {
namespace {

constexpr std::string_view kQuantity = "number or expression";
constexpr std::string_view kVector = "[x, y] of numbers or expressions";

constexpr MechanismKey kKeys[] = {
    {"top level", "title", "string", "the file name", "one line naming the mechanism"},
    {"top level", "description", "string", "none", "one paragraph: what the mechanism teaches"},
    {"top level", "gravity", kQuantity, "none",
     "magnitude of the gravitational acceleration along -y, m/s^2; 0 or absent for none"},
    {"top level", "parameters", "table of numbers or { value, unit, meaning }", "none",
     "symbols with their values, SI units; the unit (\"m\", \"kg\", \"m/s^2\") and meaning print in the reports"},
    {"top level", "definitions", "table of expressions", "none", "named expressions, printed as their own symbol"},
    {"top level", "ground", "table", "none", "the fixed frame's named points"},
    {"top level", "body", "list of tables", "(required)", "the moving bodies, at least one"},
    {"top level", "joint", "list of tables", "none", "pins and sliders between two bodies or a body and the ground"},
    {"top level", "spring", "list of tables", "none", "linear spring-dampers between two points"},
    {"top level", "force", "list of tables", "none", "applied forces at points, world frame"},
    {"top level", "torque", "list of tables", "none", "applied torques on bodies"},
    {"top level", "initial", "table", "(required)", "the generalized coordinates and rates at t = 0"},
    {"[ground]", "points", "table of [x, y]", "none", "named points of the fixed frame, world coordinates, m"},
    {"[[body]]", "name", "string", "(required)", "the body's name: letters, digits, '_' or '-' (e.g. \"1\")"},
    {"[[body]]", "shape", "string", "(required)", "rectangle, rod, disc or point"},
    {"[[body]]", "mass", kQuantity, "(required)", "mass, kg, > 0"},
    {"[[body]]", "length", kQuantity, "(required by rectangle and rod)", "length along the body x axis, m, > 0"},
    {"[[body]]", "width", kQuantity, "(required by rectangle)", "width across the body x axis, m, > 0"},
    {"[[body]]", "radius", kQuantity, "(required by disc)", "radius, m, > 0"},
    {"[[body]]", "inertia", kQuantity, "the shape's formula",
     "moment of inertia about the centre of mass, kg m^2, > 0"},
    {"[[body]]", "points", "table of [x, y]", "none",
     "named points in the body frame (origin at the centre of mass, x along the length), m"},
    {"[[joint]]", "name", "string", "(required)", "the joint's name: letters, digits, '_' or '-'"},
    {"[[joint]]", "type", "string", "(required)", "pin or slider"},
    {"[[joint]]", "bodies", "list of two strings", "(required)", "two different bodies, or a body and \"ground\""},
    {"[[joint]]", "points", "list of two strings", "(required)", "a named point of each body, in the order of bodies"},
    {"[[joint]]", "stiffness", kQuantity, "none", "pin only: torsional spring stiffness, N m/rad, >= 0"},
    {"[[joint]]", "damping", kQuantity, "none", "pin only: torsional damping, N m s/rad, >= 0"},
    {"[[joint]]", "rest_angle", kQuantity, "0", "pin only: relative angle at which the torsional spring is slack, rad"},
    {"[[joint]]", "axis", kVector, "(required by slider)",
     "slider only: the sliding direction in the frame of bodies[0], any length but not zero"},
    {"[[spring]]", "name", "string", "(required)", "the spring's name: letters, digits, '_' or '-'"},
    {"[[spring]]", "between", "list of two strings", "(required)", "two points as \"body.point\" (\"ground.O\")"},
    {"[[spring]]", "stiffness", kQuantity, "(required)", "N/m, >= 0"},
    {"[[spring]]", "rest_length", kQuantity, "(required)", "length at which the spring is slack, m, >= 0"},
    {"[[spring]]", "damping", kQuantity, "0", "N s/m, >= 0"},
    {"[[force]]", "body", "string", "(required)", "the body the force acts on"},
    {"[[force]]", "point", "string", "(required)", "the body's named point where it acts"},
    {"[[force]]", "value", kVector, "(required)", "force, world frame, N; may use the time t"},
    {"[[torque]]", "body", "string", "(required)", "the body the torque acts on"},
    {"[[torque]]", "value", kQuantity, "(required)", "torque, counter-clockwise, N m; may use the time t"},
    {"[initial]", "independent", "list of strings", "none",
     "coordinates the loop closure keeps as given (\"2.theta\"); the others are adjusted"},
    {"[initial.BODY]", "x", "number", "(required if a coordinate)", "x of the centre of mass, m"},
    {"[initial.BODY]", "y", "number", "(required if a coordinate)", "y of the centre of mass, m"},
    {"[initial.BODY]", "theta", "number", "(required if a coordinate)", "angle of the body x axis from +x, rad"},
    {"[initial.BODY]", "x_dot", "number", "0", "rate of x, m/s"},
    {"[initial.BODY]", "y_dot", "number", "0", "rate of y, m/s"},
    {"[initial.BODY]", "theta_dot", "number", "0", "rate of theta, rad/s"},
    {"[initial.SLIDER]", "s", "number", "(required if a coordinate)", "the slider's travel, m"},
    {"[initial.SLIDER]", "s_dot", "number", "0", "rate of s, m/s"},
};

std::vector<std::string> keys_of(std::string_view table) {
  std::vector<std::string> out;
  for (const MechanismKey& key : kKeys)
    if (key.table == table) out.emplace_back(key.name);
  return out;
}

const std::vector<std::string>& reserved_names() {
  static const std::vector<std::string> names{kGround, "t",     "pi",   "sin", "cos", "tan", "asin",  "acos",
                                              "atan",  "atan2", "sqrt", "exp", "log", "abs", "hypot", "log10"};
  return names;
}

bool is_reserved(const std::string& name) {
  const auto& names = reserved_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }
bool alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

// A name that becomes a symbol in expressions: [A-Za-z][A-Za-z0-9_]*.
bool is_symbol_name(const std::string& name) {
  return !name.empty() && alpha(name.front()) &&
         std::all_of(name.begin(), name.end(), [](char c) { return alnum(c) || c == '_'; });
}

// A body, joint, spring or point name: [A-Za-z0-9][A-Za-z0-9_-]*.
bool is_part_name(const std::string& name) {
  return !name.empty() && alnum(name.front()) &&
         std::all_of(name.begin(), name.end(), [](char c) { return alnum(c) || c == '_' || c == '-'; });
}

// 'text', built by appending ("literal" + std::string trips GCC 12's -Wrestrict, bug 105329).
std::string q(std::string_view text) {
  std::string out(1, '\'');
  out += text;
  out += '\'';
  return out;
}

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

// A table's entries in file order (toml++ keeps them sorted by key).
std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order(const toml::table& table) {
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(&key, &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return before(a.first->source().begin, b.first->source().begin);
  });
  return entries;
}

// A quantity as read, with its number when the file gave a plain number.
struct ReadQuantity {
  Quantity quantity;
  std::optional<double> number;
};

class MechanismReader {
 public:
  MechanismReader(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}

  Mechanism read() {
    check_keys(root_, "top level", "the top level");
    read_header();
    read_parameters();
    read_definitions();
    read_ground();
    read_bodies();
    read_joints();
    read_springs();
    read_loads();
    read_initial();
    return std::move(m_);
  }

 private:
  SourcePos pos(const toml::source_region& region) const {
    // A region toml++ did not record (line 0) stands for the file as a whole.
    if (region.begin.line == 0) return {file_, 1, 1};
    return {file_, static_cast<long>(region.begin.line), static_cast<long>(region.begin.column)};
  }
  [[noreturn]] void fail(const SourcePos& at, const std::string& message) const {
    throw Error::input(where(at) + message);
  }
  [[noreturn]] void fail(const toml::source_region& region, const std::string& message) const {
    fail(pos(region), message);
  }

  // The first key (in file order) that `table_name` does not allow.
  void check_keys(const toml::table& table, std::string_view table_name, const std::string& context) const {
    check_keys(table, keys_of(table_name), context);
  }
  void check_keys(const toml::table& table, const std::vector<std::string>& allowed, const std::string& context) const {
    const toml::key* first = nullptr;
    for (const auto& [key, node] : table) {
      if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
      if (first == nullptr || before(key.source().begin, first->source().begin)) first = &key;
    }
    if (first == nullptr) return;
    const std::string name(first->str());
    fail(first->source(),
         "unknown key " + q(name) + " in " + context + did_you_mean(name, allowed) + "; valid: " + join_names(allowed));
  }

  const toml::table* table_at(const toml::table& parent, std::string_view key, const std::string& context) const {
    const toml::node* node = parent.get(key);
    if (node == nullptr) return nullptr;
    const toml::table* table = node->as_table();
    if (table == nullptr) fail(node->source(), context + ": " + q(key) + " must be a table, got " + type_phrase(*node));
    return table;
  }

  // The tables of [[key]] (or key = [{...}, ...]).
  std::vector<const toml::table*> tables_at(std::string_view key) const {
    const toml::node* node = root_.get(key);
    if (node == nullptr) return {};
    const toml::array* array = node->as_array();
    std::string header = "[[";
    header += key;
    header += "]]";
    if (array == nullptr)
      fail(node->source(),
           q(key) + " must be a list of tables, each written " + header + ", got " + type_phrase(*node));
    std::vector<const toml::table*> out;
    for (const toml::node& element : *array) {
      const toml::table* table = element.as_table();
      if (table == nullptr)
        fail(element.source(),
             "every entry of " + q(key) + " must be a table (" + header + "), got " + type_phrase(element));
      out.push_back(table);
    }
    return out;
  }

  std::optional<std::pair<std::string, SourcePos>> string_at(const toml::table& table, std::string_view key,
                                                             const std::string& context, bool required) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) {
      if (required) fail(table.source(), context + ": the key " + q(key) + " is required");
      return std::nullopt;
    }
    const auto* text = node->as_string();
    if (text == nullptr) fail(node->source(), context + ": " + q(key) + " must be a string, got " + type_phrase(*node));
    return std::make_pair(text->get(), pos(node->source()));
  }

  ReadQuantity quantity_of(const toml::node& node, const std::string& what, const std::string& context) const {
    ReadQuantity out;
    out.quantity.pos = pos(node.source());
    if (const auto* i = node.as_integer()) {
      out.quantity.text = std::to_string(i->get());
      out.number = static_cast<double>(i->get());
    } else if (const auto* f = node.as_floating_point()) {
      if (!std::isfinite(f->get()))
        fail(node.source(), context + ": " + what + " = " + format_roundtrip(f->get()) +
                                " is not a finite number; valid: a finite number or an expression");
      out.quantity.text = format_roundtrip(f->get());
      out.number = f->get();
    } else if (const auto* s = node.as_string()) {
      out.quantity.text = s->get();
      const bool blank = std::all_of(out.quantity.text.begin(), out.quantity.text.end(),
                                     [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
      if (blank) fail(node.source(), context + ": " + what + " is an empty expression; give a number or an expression");
    } else {
      fail(node.source(),
           context + ": " + what + " must be a number or an expression string, got " + type_phrase(node));
    }
    return out;
  }

  std::optional<ReadQuantity> quantity_at(const toml::table& table, std::string_view key,
                                          const std::string& context) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    return quantity_of(*node, q(key), context);
  }

  ReadQuantity required_quantity(const toml::table& table, std::string_view key, const std::string& context) const {
    auto read = quantity_at(table, key, context);
    if (!read) fail(table.source(), context + ": the key " + q(key) + " is required");
    return *read;
  }

  // A plain number must satisfy the bound; an expression is checked at the parameter
  // values by the symbolic layer.
  void require_bound(const ReadQuantity& read, std::string_view key, const std::string& context, bool strict,
                     std::string_view unit) const {
    if (!read.number) return;
    const double v = *read.number;
    if (strict ? v > 0 : v >= 0) return;
    fail(read.quantity.pos, context + ": " + q(key) + " = " + read.quantity.text + " " + std::string(unit) +
                                " is out of range; valid: a number " + (strict ? "> 0" : ">= 0") + " or an expression");
  }

  Vector2Quantity vector_of(const toml::node& node, const std::string& what, const std::string& context) const {
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 2)
      fail(node.source(),
           context + ": " + what + " must be [x, y], two numbers or expressions, got " +
               (array == nullptr ? type_phrase(node) : "an array of " + std::to_string(array->size()) + " entries"));
    return {quantity_of(*array->get(0), what + "[0]", context).quantity,
            quantity_of(*array->get(1), what + "[1]", context).quantity};
  }

  std::array<std::pair<std::string, SourcePos>, 2> two_strings(const toml::table& table, std::string_view key,
                                                               const std::string& context,
                                                               std::string_view example) const {
    const toml::node* node = table.get(key);
    if (node == nullptr)
      fail(table.source(), context + ": the key " + q(key) + " is required, e.g. " + std::string(example));
    const toml::array* array = node->as_array();
    if (array == nullptr || array->size() != 2)
      fail(node->source(),
           context + ": " + q(key) + " must be a list of two strings, e.g. " + std::string(example) + ", got " +
               (array == nullptr ? type_phrase(*node) : "an array of " + std::to_string(array->size()) + " entries"));
    std::array<std::pair<std::string, SourcePos>, 2> out;
    for (std::size_t i = 0; i < 2; ++i) {
      const toml::node& element = *array->get(i);
      const auto* text = element.as_string();
      if (text == nullptr)
        fail(element.source(),
             context + ": every entry of " + q(key) + " must be a string, got " + type_phrase(element));
      out[i] = {text->get(), pos(element.source())};
    }
    return out;
  }

  void check_part_name(const std::string& name, const SourcePos& at, const std::string& what, bool reserve) const {
    if (!is_part_name(name))
      fail(at, what + " name " + q(name) +
                   " is not valid; valid: a letter or digit, then letters, digits, '_' or '-' (e.g. \"1\", \"crank\")");
    if (reserve && (name == kGround || name == "independent"))
      fail(at, what + " name " + q(name) + " is reserved (" +
                   (name == kGround ? "it names the fixed frame" : "a key of [initial]") + "); choose another name");
  }

  void check_symbol_name(const std::string& name, const SourcePos& at, const std::string& what) const {
    if (!is_symbol_name(name))
      fail(at, what + " name " + q(name) +
                   " is not valid; valid: a letter, then letters, digits or '_' (it becomes a symbol)");
    if (is_reserved(name))
      fail(at, what + " name " + q(name) + " is reserved; reserved: " + join_names(reserved_names()));
  }

  // --- the sections -----------------------------------------------------------------

  void read_header() {
    if (auto title = string_at(root_, "title", "title", false)) {
      if (title->first.find_first_of("\r\n") != std::string::npos)
        fail(title->second, "the title must be one line; put the rest in 'description'");
      m_.title = title->first;
    }
    if (auto description = string_at(root_, "description", "description", false)) {
      // One paragraph: line breaks and runs of spaces read as one space.
      for (char c : description->first) {
        const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
        if (space && (m_.description.empty() || m_.description.back() == ' ')) continue;
        m_.description += space ? ' ' : c;
      }
      if (!m_.description.empty() && m_.description.back() == ' ') m_.description.pop_back();
    }
    if (auto gravity = quantity_at(root_, "gravity", "gravity")) {
      if (gravity->number && *gravity->number < 0)
        fail(gravity->quantity.pos, "gravity = " + gravity->quantity.text +
                                        " m/s^2 is out of range; valid: a magnitude >= 0 (it acts along -y), or an "
                                        "expression");
      m_.gravity = gravity->quantity;
    }
  }

  void read_parameters() {
    const toml::table* table = table_at(root_, "parameters", "the top level");
    if (table == nullptr) return;
    for (const auto& [key, node] : in_file_order(*table)) {
      const std::string name(key->str());
      check_symbol_name(name, pos(key->source()), "parameter");
      const std::string context = "parameter " + q(name);
      // A number, or { value = 0.3, unit = "m", meaning = "block length" } for the reports.
      const toml::node* number = node;
      std::string unit, meaning;
      if (const auto* described = node->as_table()) {
        check_keys(*described, std::vector<std::string>{"value", "unit", "meaning"}, context);
        number = described->get("value");
        if (number == nullptr) fail(node->source(), context + ": the key \"value\" is required");
        if (auto u = string_at(*described, "unit", context, false)) unit = u->first;
        if (auto text = string_at(*described, "meaning", context, false)) meaning = text->first;
      }
      std::optional<double> value;
      if (const auto* i = number->as_integer()) value = static_cast<double>(i->get());
      if (const auto* f = number->as_floating_point()) value = f->get();
      if (!value)
        fail(number->source(), context +
                                   " must be a number or { value = NUMBER, unit = \"...\", meaning = \"...\" }, "
                                   "got " +
                                   type_phrase(*number) + "; an expression belongs in [definitions]");
      if (!std::isfinite(*value))
        fail(number->source(), context + " = " + format_roundtrip(*value) + " is not a finite number");
      m_.parameters.push_back({name, *value, pos(number->source()), unit, meaning});
    }
  }

  void read_definitions() {
    const toml::table* table = table_at(root_, "definitions", "the top level");
    if (table == nullptr) return;
    for (const auto& [key, node] : in_file_order(*table)) {
      const std::string name(key->str());
      const SourcePos at = pos(key->source());
      check_symbol_name(name, at, "definition");
      for (const Parameter& p : m_.parameters)
        if (p.name == name)
          fail(at, "definition " + q(name) + " has the name of the parameter at line " + std::to_string(p.pos.line) +
                       "; names must be unique");
      m_.definitions.push_back({name, quantity_of(*node, q(name), "definition " + q(name)).quantity, at});
    }
  }

  std::vector<NamedPoint> read_points(const toml::table& owner, const std::string& context) const {
    const toml::table* table = table_at(owner, "points", context);
    if (table == nullptr) return {};
    std::vector<NamedPoint> points;
    for (const auto& [key, node] : in_file_order(*table)) {
      const std::string name(key->str());
      const SourcePos at = pos(key->source());
      check_part_name(name, at, context + ": point", false);
      points.push_back({name, vector_of(*node, "point " + q(name), context), at});
    }
    return points;
  }

  void read_ground() {
    const toml::table* table = table_at(root_, "ground", "the top level");
    if (table == nullptr) return;
    check_keys(*table, "[ground]", "[ground]");
    m_.ground_points = read_points(*table, "[ground]");
  }

  void read_bodies() {
    std::map<std::string, long> lines;
    std::size_t index = 0;
    for (const toml::table* table : tables_at("body")) {
      ++index;
      const std::string numbered = "[[body]] number " + std::to_string(index);
      check_keys(*table, "[[body]]", numbered);
      Body body;
      body.pos = pos(table->source());
      const auto name = string_at(*table, "name", numbered, true);
      body.name = name->first;
      check_part_name(body.name, name->second, "body", true);
      if (const auto seen = lines.find(body.name); seen != lines.end())
        fail(name->second, "body name " + q(body.name) + " is used twice (first at line " +
                               std::to_string(seen->second) + "); names must be unique");
      lines[body.name] = name->second.line;
      const std::string context = "body " + q(body.name);

      const auto shape = string_at(*table, "shape", context, true);
      const std::vector<std::string> shapes(kShapeNames.begin(), kShapeNames.end());
      const auto found = std::find(shapes.begin(), shapes.end(), shape->first);
      if (found == shapes.end())
        fail(shape->second, context + ": shape " + q(shape->first) + " is not a shape" +
                                did_you_mean(shape->first, shapes) + "; valid: " + join_names(shapes));
      body.shape = static_cast<Shape>(found - shapes.begin());

      const ReadQuantity mass = required_quantity(*table, "mass", context);
      require_bound(mass, "mass", context, true, "kg");
      body.mass = mass.quantity;
      read_sizes(*table, body, context);
      if (auto inertia = quantity_at(*table, "inertia", context)) {
        require_bound(*inertia, "inertia", context, true, "kg m^2");
        body.inertia = inertia->quantity;
      }
      body.points = read_points(*table, context);
      m_.bodies.push_back(std::move(body));
    }
    if (m_.bodies.empty())
      fail(pos(root_.source()), "no [[body]]: a mechanism needs at least one body; see mechanisms/README.md");
  }

  // The sizes the shape takes, each required; any other size is a mistake.
  void read_sizes(const toml::table& table, Body& body, const std::string& context) const {
    struct Size {
      std::string_view key;
      std::optional<Quantity> Body::*member;
    };
    static constexpr std::array<Size, 3> kSizes{
        {{"length", &Body::length}, {"width", &Body::width}, {"radius", &Body::radius}}};
    std::vector<std::string> takes;
    if (body.shape == Shape::rectangle) takes = {"length", "width"};
    if (body.shape == Shape::rod) takes = {"length"};
    if (body.shape == Shape::disc) takes = {"radius"};
    const std::string shape = kShapeNames[static_cast<std::size_t>(body.shape)];
    for (const Size& size : kSizes) {
      const bool used = std::find(takes.begin(), takes.end(), size.key) != takes.end();
      const toml::node* node = table.get(size.key);
      if (!used && node != nullptr)
        fail(node->source(), context + ": a " + shape + " has no " + q(size.key) + "; a " + shape + " takes " +
                                 (takes.empty() ? std::string("no sizes") : join_names(takes)));
      if (!used) continue;
      if (node == nullptr)
        fail(table.source(),
             context + ": a " + shape + " needs " + q(size.key) + "; a " + shape + " takes " + join_names(takes));
      const ReadQuantity read = quantity_of(*node, q(size.key), context);
      require_bound(read, size.key, context, true, "m");
      body.*size.member = read.quantity;
    }
  }

  // The names valid where a body is expected: the bodies, and the ground when allowed.
  std::vector<std::string> body_names(bool with_ground) const {
    std::vector<std::string> names;
    if (with_ground) names.emplace_back(kGround);
    for (const Body& body : m_.bodies) names.push_back(body.name);
    return names;
  }

  const std::vector<NamedPoint>* points_of(const std::string& body_name) const {
    if (body_name == kGround) return &m_.ground_points;
    const Body* body = m_.find_body(body_name);
    return body == nullptr ? nullptr : &body->points;
  }

  void check_body(const std::string& name, const SourcePos& at, const std::string& context, bool with_ground) const {
    if (points_of(name) != nullptr && (with_ground || name != kGround)) return;
    const std::vector<std::string> valid = body_names(with_ground);
    fail(at, context + ": " + q(name) + " is not a body" + did_you_mean(name, valid) + "; valid: " + join_names(valid));
  }

  void check_point(const std::string& body_name, const std::string& point, const SourcePos& at,
                   const std::string& context) const {
    const std::vector<NamedPoint>& points = *points_of(body_name);
    std::vector<std::string> names;
    for (const NamedPoint& p : points) {
      if (p.name == point) return;
      names.push_back(p.name);
    }
    const std::string owner = body_name == kGround ? std::string("the ground") : "body " + q(body_name);
    if (names.empty()) fail(at, context + ": " + owner + " has no point " + q(point) + "; it has no points");
    fail(at, context + ": " + owner + " has no point " + q(point) + did_you_mean(point, names) +
                 "; valid: " + join_names(names));
  }

  void read_joints() {
    std::map<std::string, long> lines;
    std::size_t index = 0;
    for (const toml::table* table : tables_at("joint")) {
      ++index;
      const std::string numbered = "[[joint]] number " + std::to_string(index);
      check_keys(*table, "[[joint]]", numbered);
      Joint joint;
      joint.pos = pos(table->source());
      const auto name = string_at(*table, "name", numbered, true);
      joint.name = name->first;
      check_part_name(joint.name, name->second, "joint", true);
      if (const auto seen = lines.find(joint.name); seen != lines.end())
        fail(name->second, "joint name " + q(joint.name) + " is used twice (first at line " +
                               std::to_string(seen->second) + "); names must be unique");
      lines[joint.name] = name->second.line;
      const std::string context = "joint " + q(joint.name);

      const auto type = string_at(*table, "type", context, true);
      const std::vector<std::string> types(kJointTypeNames.begin(), kJointTypeNames.end());
      const auto found = std::find(types.begin(), types.end(), type->first);
      if (found == types.end())
        fail(type->second, context + ": type " + q(type->first) + " is not a joint type" +
                               did_you_mean(type->first, types) + "; valid: " + join_names(types));
      joint.type = static_cast<JointType>(found - types.begin());

      const auto bodies = two_strings(*table, "bodies", context, "[\"ground\", \"1\"]");
      for (const auto& [body, at] : bodies) check_body(body, at, context, true);
      if (bodies[0].first == bodies[1].first)
        fail(bodies[1].second, context + " joins " + q(bodies[0].first) +
                                   " to itself; give two different bodies (or a body and \"ground\")");
      const auto points = two_strings(*table, "points", context, "[\"O\", \"A\"]");
      for (std::size_t i = 0; i < 2; ++i) {
        joint.bodies[i] = bodies[i].first;
        joint.points[i] = points[i].first;
        check_point(bodies[i].first, points[i].first, points[i].second, context);
      }
      read_joint_options(*table, joint, context);
      m_.joints.push_back(std::move(joint));
    }
  }

  void read_joint_options(const toml::table& table, Joint& joint, const std::string& context) const {
    const bool pin = joint.type == JointType::pin;
    for (const std::string_view key : {"stiffness", "damping", "rest_angle"}) {
      const toml::node* node = table.get(key);
      if (node == nullptr) continue;
      if (!pin)
        fail(node->source(),
             context + ": " + q(key) + " is for pins only (a torsional spring-damper); a slider takes: axis");
      const ReadQuantity read = quantity_of(*node, q(key), context);
      if (key == "stiffness") {
        require_bound(read, key, context, false, "N m/rad");
        joint.stiffness = read.quantity;
      } else if (key == "damping") {
        require_bound(read, key, context, false, "N m s/rad");
        joint.damping = read.quantity;
      } else {
        joint.rest_angle = read.quantity;
      }
    }
    const toml::node* axis = table.get("axis");
    if (pin && axis != nullptr)
      fail(axis->source(), context + ": 'axis' is for sliders only; a pin takes: stiffness, damping, rest_angle");
    if (pin) return;
    if (axis == nullptr)
      fail(table.source(),
           context + ": a slider needs 'axis', its direction [x, y] in the frame of " + q(joint.bodies[0]));
    joint.axis = vector_of(*axis, "'axis'", context);
    const auto is_zero = [](const Quantity& c) {
      const auto* end = c.text.data() + c.text.size();
      double v = 1;
      const auto [ptr, ec] = std::from_chars(c.text.data(), end, v);
      return ec == std::errc() && ptr == end && v == 0;
    };
    if (is_zero(joint.axis->x) && is_zero(joint.axis->y))
      fail(joint.axis->x.pos, context + ": 'axis' = [0, 0] has no direction; valid: a nonzero vector such as [1, 0]");
  }

  PointRef point_ref(const std::pair<std::string, SourcePos>& text, const std::string& context) const {
    const std::size_t dot = text.first.find('.');
    if (dot == std::string::npos)
      fail(text.second, context + ": " + q(text.first) + " is not BODY.POINT; valid: e.g. \"ground.O\" or \"1.P\"");
    PointRef ref{text.first.substr(0, dot), text.first.substr(dot + 1), text.second};
    check_body(ref.body, ref.pos, context, true);
    check_point(ref.body, ref.point, ref.pos, context);
    return ref;
  }

  void read_springs() {
    std::map<std::string, long> lines;
    std::size_t index = 0;
    for (const toml::table* table : tables_at("spring")) {
      ++index;
      const std::string numbered = "[[spring]] number " + std::to_string(index);
      check_keys(*table, "[[spring]]", numbered);
      Spring spring;
      spring.pos = pos(table->source());
      const auto name = string_at(*table, "name", numbered, true);
      spring.name = name->first;
      check_part_name(spring.name, name->second, "spring", false);
      if (const auto seen = lines.find(spring.name); seen != lines.end())
        fail(name->second, "spring name " + q(spring.name) + " is used twice (first at line " +
                               std::to_string(seen->second) + "); names must be unique");
      lines[spring.name] = name->second.line;
      const std::string context = "spring " + q(spring.name);
      const auto between = two_strings(*table, "between", context, "[\"ground.O\", \"1.P\"]");
      for (std::size_t i = 0; i < 2; ++i) spring.between[i] = point_ref(between[i], context);
      if (between[0].first == between[1].first)
        fail(between[1].second, context + " joins " + q(between[0].first) + " to itself; give two different points");
      const ReadQuantity stiffness = required_quantity(*table, "stiffness", context);
      require_bound(stiffness, "stiffness", context, false, "N/m");
      spring.stiffness = stiffness.quantity;
      const ReadQuantity rest = required_quantity(*table, "rest_length", context);
      require_bound(rest, "rest_length", context, false, "m");
      spring.rest_length = rest.quantity;
      spring.damping = {"0", spring.pos};
      if (auto damping = quantity_at(*table, "damping", context)) {
        require_bound(*damping, "damping", context, false, "N s/m");
        spring.damping = damping->quantity;
      }
      m_.springs.push_back(std::move(spring));
    }
  }

  void read_loads() {
    std::size_t index = 0;
    for (const toml::table* table : tables_at("force")) {
      ++index;
      const std::string context = "[[force]] number " + std::to_string(index);
      check_keys(*table, "[[force]]", context);
      AppliedForce force;
      force.pos = pos(table->source());
      const auto body = string_at(*table, "body", context, true);
      check_body(body->first, body->second, context, false);
      const auto point = string_at(*table, "point", context, true);
      check_point(body->first, point->first, point->second, context);
      const toml::node* value = table->get("value");
      if (value == nullptr) fail(table->source(), context + ": the key 'value' is required, e.g. [\"0\", \"-F0\"]");
      force.body = body->first;
      force.point = point->first;
      force.value = vector_of(*value, "'value'", context);
      m_.forces.push_back(std::move(force));
    }
    index = 0;
    for (const toml::table* table : tables_at("torque")) {
      ++index;
      const std::string context = "[[torque]] number " + std::to_string(index);
      check_keys(*table, "[[torque]]", context);
      AppliedTorque torque;
      torque.pos = pos(table->source());
      const auto body = string_at(*table, "body", context, true);
      check_body(body->first, body->second, context, false);
      torque.body = body->first;
      torque.value = required_quantity(*table, "value", context).quantity;
      m_.torques.push_back(std::move(torque));
    }
  }

  void read_initial() {
    const toml::table* table = table_at(root_, "initial", "the top level");
    m_.initial_pos = pos(table != nullptr ? table->source() : root_.source());
    if (table == nullptr) return;
    std::vector<std::string> entries{"independent"};
    for (const Body& body : m_.bodies) entries.push_back(body.name);
    for (const Joint& joint : m_.joints)
      if (joint.type == JointType::slider) entries.push_back(joint.name);
    for (const auto& [key, node] : in_file_order(*table)) {
      const std::string name(key->str());
      if (name == "independent") {
        read_independent(*node);
        continue;
      }
      const Body* body = m_.find_body(name);
      const Joint* joint = m_.find_joint(name);
      const bool slider = joint != nullptr && joint->type == JointType::slider;
      if (body == nullptr && !slider) {
        const std::string pin_note =
            joint != nullptr ? " (" + q(name) + " is a pin: the angle of the body it carries is the coordinate)" : "";
        fail(key->source(), "[initial]: " + q(name) + " is not a body or slider joint" + pin_note +
                                did_you_mean(name, entries) + "; valid: " + join_names(entries));
      }
      const std::string context = "[initial] " + q(name);
      const toml::table* values = node->as_table();
      if (values == nullptr)
        fail(node->source(), context + " must be a table such as { " +
                                 (body != nullptr ? "theta = 0.1, theta_dot = 0" : "s = 0.1, s_dot = 0") + " }, got " +
                                 type_phrase(*node));
      std::vector<std::string> allowed;
      if (body != nullptr) allowed = keys_of("[initial.BODY]");
      if (slider)
        for (const std::string& k : keys_of("[initial.SLIDER]")) allowed.push_back(k);
      check_keys(*values, allowed, context);
      for (const auto& [value_key, value] : in_file_order(*values)) {
        const std::string full = name + "." + std::string(value_key->str());
        std::optional<double> number;
        if (const auto* i = value->as_integer()) number = static_cast<double>(i->get());
        if (const auto* f = value->as_floating_point()) number = f->get();
        if (!number) fail(value->source(), "[initial] " + full + " must be a number, got " + type_phrase(*value));
        if (!std::isfinite(*number))
          fail(value->source(), "[initial] " + full + " = " + format_roundtrip(*number) + " is not a finite number");
        m_.initial.push_back({full, *number, pos(value->source())});
      }
    }
  }

  void read_independent(const toml::node& node) {
    m_.independent_pos = pos(node.source());
    const toml::array* array = node.as_array();
    if (array == nullptr)
      fail(node.source(),
           "[initial]: 'independent' must be a list of coordinates such as [\"2.theta\"], got " + type_phrase(node));
    for (const toml::node& element : *array) {
      const auto* text = element.as_string();
      if (text == nullptr)
        fail(element.source(), "[initial]: every entry of 'independent' must be a string, got " + type_phrase(element));
      m_.independent.push_back(text->get());
    }
  }

  const toml::table& root_;
  std::string file_;
  Mechanism m_;
};

}  // namespace

std::span<const MechanismKey> mechanism_keys() { return kKeys; }

Mechanism read_mechanism(std::string_view toml_text, const std::string& source_name) {
  const toml::table root = parse_toml_text(toml_text, source_name, "mechanism");
  Mechanism mechanism = MechanismReader(root, source_name).read();
  mechanism.name = std::filesystem::path(source_name).stem().string();
  mechanism.source = source_name;
  if (mechanism.title.empty()) mechanism.title = mechanism.name;
  validate_initial(mechanism);
  return mechanism;
}

}  // namespace linkage
