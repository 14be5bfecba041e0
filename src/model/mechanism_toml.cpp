#include "model/mechanism_toml.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "model/inputs_toml.hpp"
#include "model/joint_types.hpp"
#include "toml/toml_table.hpp"

namespace linkage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
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
    {"top level", "joint", "list of tables", "none",
     "pins, sliders, welds, rolling joints, pin-slots and gears between two bodies or a body and the ground"},
    {"top level", "driver", "list of tables", "none", "motors: the prescribed motion of a pin or slider joint"},
    {"top level", "spring", "list of tables", "none", "linear spring-dampers between two points"},
    {"top level", "force", "list of tables", "none", "applied forces at points, world frame"},
    {"top level", "torque", "list of tables", "none", "applied torques on bodies"},
    {"top level", "initial", "table", "(required)", "the generalized coordinates and rates at t = 0"},
    {"top level", "aliases", "table of strings", "none",
     "other names for keys of the worked solution's JSON, printed by an interface built on the file"},
    {"top level", "picture", "table", "none", "how `linkage render` draws the mechanism by default"},
    {"[picture]", "title", "string", "the title", "the picture's title line"},
    {"[picture]", "trail", "list of strings", "none",
     "points whose path the picture draws, \"BODY.POINT\" (\"1.P\"), as --trail gives them"},
    {"[picture]", "ensemble", "string", "the first coordinate",
     "the coordinate of [initial] an ensemble's runs start apart in (\"1.theta\")"},
    {"top level", "table", "table", "none", "the table an interface built on the file writes by default"},
    {"[table]", "columns", "list of strings", "every column",
     "the columns, in order, by the names `linkage simulate --mechanism FILE --columns all` prints (\"1.x\", "
     "\"energy\")"},
    {"[ground]", "points", "table of [x, y]", "none", "named points of the fixed frame, world coordinates, m"},
    {"[[body]]", "name", "string", "(required)", "the body's name: letters, digits, '_' or '-' (e.g. \"1\")"},
    {"[[body]]", "shape", "string", "(required)", "rectangle, rod, disc, ring or point"},
    {"[[body]]", "mass", kQuantity, "(required)", "mass, kg, > 0"},
    {"[[body]]", "length", kQuantity, "(required by rectangle and rod)", "length along the body x axis, m, > 0"},
    {"[[body]]", "width", kQuantity, "(required by rectangle)", "width across the body x axis, m, > 0"},
    {"[[body]]", "radius", kQuantity, "(required by disc)", "radius, m, > 0"},
    {"[[body]]", "inertia", kQuantity, "the shape's formula",
     "moment of inertia about the centre of mass, kg m^2, > 0"},
    {"[[body]]", "points", "table of [x, y]", "none",
     "named points in the body frame (origin at the centre of mass, x along the length), m"},
    {"[[joint]]", "name", "string", "(required)", "the joint's name: letters, digits, '_' or '-'"},
    {"[[joint]]", "type", "string", "(required)", "pin, slider, weld, rolling, pin-slot or gear"},
    {"[[joint]]", "bodies", "list of two strings", "(required)", "two different bodies, or a body and \"ground\""},
    {"[[joint]]", "points", "list of two strings", "(required; none for a gear)",
     "a named point of each body, in the order of bodies"},
    {"[[joint]]", "stiffness", kQuantity, "none", "pin only: torsional spring stiffness, N m/rad, >= 0"},
    {"[[joint]]", "damping", kQuantity, "none", "pin only: torsional damping, N m s/rad, >= 0"},
    {"[[joint]]", "rest_angle", kQuantity, "0", "pin only: relative angle at which the torsional spring is slack, rad"},
    {"[[joint]]", "axis", kVector, "(required by slider, rolling and pin-slot)",
     "slider: the sliding direction; rolling: the line's direction (the disc on its side turned +90 degrees); "
     "pin-slot: the slot's direction; in the frame of bodies[0], any length but not zero"},
    {"[[joint]]", "radius", kQuantity, "the rolling body's disc radius", "rolling only: the rolling radius, m, > 0"},
    {"[[joint]]", "angle", kQuantity, "0",
     "weld only: the relative angle th_b - th_a it holds, rad; neither body may be a point mass"},
    {"[[joint]]", "carrier", "string", "\"ground\"",
     "gear only: the body (or \"ground\") both gears are pinned to, each by a pin joint"},
    {"[[joint]]", "radii", "list of two numbers or expressions", "(required by gear)",
     "gear only: the pitch radii of bodies[0] and bodies[1], m, > 0"},
    {"[[joint]]", "internal", "boolean", "false",
     "gear only: an internal mesh (a ring gear): r1 (th1 - thc) - r2 (th2 - thc) is held, not r1 (th1 - thc) + r2 "
     "(th2 - thc)"},
    {"[[driver]]", "name", "string", "(required)",
     "the driver's name, naming its column NAME.torque (pin) or NAME.force (slider): letters, digits, '_' or '-'"},
    {"[[driver]]", "joint", "string", "(required)", "the pin or slider joint it drives"},
    {"[[driver]]", "motion", kQuantity, "(required)",
     "pin: the relative angle th_b - th_a of the joint's bodies, rad; slider: the joint's travel s, m; in t, the "
     "parameters and definitions"},
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

std::vector<std::string_view> keys_of(std::string_view table) {
  std::vector<std::string_view> out;
  for (const MechanismKey& key : kKeys)
    if (key.table == table) out.push_back(key.name);
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

// The names an expression's text mentions (numbers, exponents included, skipped).
std::vector<std::string> names_in(std::string_view text) {
  std::vector<std::string> names;
  std::size_t i = 0;
  auto word = [&](std::size_t j) {
    return j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) != 0 || text[j] == '_');
  };
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c) != 0 || c == '.') {
      while (i < text.size() && (word(i) || text[i] == '.' ||
                                 ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E'))))
        ++i;
    } else if (std::isalpha(c) != 0 || c == '_') {
      const std::size_t start = i;
      while (word(i)) ++i;
      names.emplace_back(text.substr(start, i - start));
    } else {
      ++i;
    }
  }
  return names;
}

// A quantity as read, with its number when the file gave a plain number.
struct ReadQuantity {
  Quantity quantity;
  std::optional<double> number;
};

class MechanismReader {
 public:
  MechanismReader(const toml::table& root, std::string file)
      : file_(std::move(file)), root_(root, file_, "the top level", {}, keys_of("top level")) {}

  Mechanism read() {
    root_.reject_unknown_keys();
    read_header();
    read_parameters();
    read_definitions();
    read_ground();
    read_bodies();
    read_joints();
    read_drivers();
    read_springs();
    read_loads();
    read_initial();
    read_aliases();
    read_picture();
    read_table();
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

  // A reader of `table`, named `context` in messages, that allows `keys`.
  TableReader reader(const toml::table& table, std::string context, std::vector<std::string_view> keys = {}) const {
    return {table, file_, std::move(context), {}, std::move(keys)};
  }
  // The same for a table of the format (kKeys), refusing any key it does not list.
  TableReader checked(const toml::table& table, std::string context, std::string_view format_table) const {
    TableReader r = reader(table, std::move(context), keys_of(format_table));
    r.reject_unknown_keys();
    return r;
  }

  std::optional<std::pair<std::string, SourcePos>> string_at(const TableReader& r, std::string_view key,
                                                             bool required) const {
    if (required) r.require(key);
    auto text = r.string(key);
    if (!text) return std::nullopt;
    return std::make_pair(std::move(*text), pos(r.node(key)->source()));
  }

  // The index of the required string `key` among `names` (a shape, a joint type).
  template <std::size_t N>
  static std::size_t choose(const TableReader& r, std::string_view key, const std::array<const char*, N>& names) {
    r.require(key);
    const std::vector<std::string_view> valid(names.begin(), names.end());
    const std::string value = *r.choice(key, valid);
    return static_cast<std::size_t>(std::find(valid.begin(), valid.end(), value) - valid.begin());
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

  std::optional<ReadQuantity> quantity_at(const TableReader& r, std::string_view key) const {
    const toml::node* node = r.node(key);
    if (node == nullptr) return std::nullopt;
    return quantity_of(*node, q(key), r.context());
  }

  ReadQuantity required_quantity(const TableReader& r, std::string_view key) const {
    r.require(key);
    return *quantity_at(r, key);
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

  std::array<std::pair<std::string, SourcePos>, 2> two_strings(const TableReader& r, std::string_view key,
                                                               std::string_view example) const {
    r.require(key, example);
    const toml::node& node = *r.node(key);
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 2)
      r.fail(key,
             q(key) + " must be a list of two strings, e.g. " + std::string(example) + ", got " +
                 (array == nullptr ? type_phrase(node) : "an array of " + std::to_string(array->size()) + " entries"));
    const std::vector<std::string> text = *r.strings(key);  // every entry a string
    return {{{text[0], pos(array->get(0)->source())}, {text[1], pos(array->get(1)->source())}}};
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

  // A part's name, unique among its kind (`lines` remembers where each was given).
  std::string unique_name(const TableReader& numbered, const std::string& kind, bool reserve,
                          std::map<std::string, long>& lines) const {
    const auto name = string_at(numbered, "name", true);
    check_part_name(name->first, name->second, kind, reserve);
    if (const auto seen = lines.find(name->first); seen != lines.end())
      fail(name->second, kind + " name " + q(name->first) + " is used twice (first at line " +
                             std::to_string(seen->second) + "); names must be unique");
    lines[name->first] = name->second.line;
    return name->first;
  }

  // --- the sections -----------------------------------------------------------------

  void read_header() {
    if (auto title = string_at(root_, "title", false)) {
      if (title->first.find_first_of("\r\n") != std::string::npos)
        fail(title->second, "the title must be one line; put the rest in 'description'");
      m_.title = title->first;
    }
    if (auto description = root_.string("description")) {
      // One paragraph: line breaks and runs of spaces read as one space.
      for (char c : *description) {
        const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
        if (space && (m_.description.empty() || m_.description.back() == ' ')) continue;
        m_.description += space ? ' ' : c;
      }
      if (!m_.description.empty() && m_.description.back() == ' ') m_.description.pop_back();
    }
    if (auto gravity = quantity_at(root_, "gravity")) {
      if (gravity->number && *gravity->number < 0)
        fail(gravity->quantity.pos, "gravity = " + gravity->quantity.text +
                                        " m/s^2 is out of range; valid: a magnitude >= 0 (it acts along -y), or an "
                                        "expression");
      m_.gravity = gravity->quantity;
    }
  }

  void read_parameters() {
    const toml::table* table = root_.subtable("parameters");
    if (table == nullptr) return;
    for (const auto& [key, node] : reader(*table, "[parameters]").entries()) {
      const std::string name(key->str());
      check_symbol_name(name, pos(key->source()), "parameter");
      const std::string context = "parameter " + q(name);
      // A number, or { value = 0.3, unit = "m", meaning = "block length" } for the reports.
      const toml::node* number = node;
      std::string unit, meaning;
      if (const auto* described = node->as_table()) {
        const TableReader r = reader(*described, context, {"value", "unit", "meaning"});
        r.reject_unknown_keys();
        r.require("value");
        number = r.node("value");
        unit = r.string("unit").value_or("");
        meaning = r.string("meaning").value_or("");
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
      if (!in_magnitude_range(*value))
        fail(number->source(),
             context + " = " + format_roundtrip(*value) + " is out of range; valid: " + kMagnitudeRange);
      m_.parameters.push_back({name, *value, pos(number->source()), unit, meaning});
    }
  }

  void read_definitions() {
    const toml::table* table = root_.subtable("definitions");
    if (table == nullptr) return;
    for (const auto& [key, node] : reader(*table, "[definitions]").entries()) {
      const std::string name(key->str());
      const SourcePos at = pos(key->source());
      check_symbol_name(name, at, "definition");
      for (const Parameter& p : m_.parameters)
        if (p.name == name)
          fail(at, "definition " + q(name) + " has the name of the parameter at line " + std::to_string(p.pos.line) +
                       "; names must be unique");
      m_.definitions.push_back({name, quantity_of(*node, q(name), "definition " + q(name)).quantity, at});
    }
    order_definitions();
  }

  // A TOML table has no order: each definition goes after the ones it uses (file order
  // otherwise), and a cycle is refused naming it.
  void order_definitions() {
    std::vector<Definition>& all = m_.definitions;
    auto uses = [&](const Definition& d) {
      std::vector<std::size_t> out;
      for (const std::string& word : names_in(d.value.text))
        for (std::size_t k = 0; k < all.size(); ++k)
          if (all[k].name == word) out.push_back(k);
      return out;
    };
    std::vector<int> state(all.size(), 0);  // 0 not yet, 1 on the path, 2 placed
    std::vector<std::size_t> order, path;
    const std::function<void(std::size_t)> place = [&](std::size_t k) {
      if (state[k] == 2) return;
      if (state[k] == 1) {
        std::string cycle;
        const auto from = std::find(path.begin(), path.end(), k);
        for (auto i = from; i != path.end(); ++i) cycle += all[*i].name + " -> ";
        fail(all[k].value.pos, "definition " + q(all[k].name) + " depends on itself: " + cycle + all[k].name +
                                   "; valid: definitions that end in parameters and numbers");
      }
      state[k] = 1;
      path.push_back(k);
      for (const std::size_t used : uses(all[k])) place(used);
      path.pop_back();
      state[k] = 2;
      order.push_back(k);
    };
    for (std::size_t k = 0; k < all.size(); ++k) place(k);
    std::vector<Definition> sorted;
    for (const std::size_t k : order) sorted.push_back(std::move(all[k]));
    all = std::move(sorted);
  }

  std::vector<NamedPoint> read_points(const TableReader& owner) const {
    const toml::table* table = owner.subtable("points");
    if (table == nullptr) return {};
    std::vector<NamedPoint> points;
    for (const auto& [key, node] : reader(*table, owner.context()).entries()) {
      const std::string name(key->str());
      const SourcePos at = pos(key->source());
      check_part_name(name, at, owner.context() + ": point", false);
      points.push_back({name, vector_of(*node, "point " + q(name), owner.context()), at});
    }
    return points;
  }

  void read_ground() {
    const toml::table* table = root_.subtable("ground");
    if (table == nullptr) return;
    m_.ground_points = read_points(checked(*table, "[ground]", "[ground]"));
  }

  void read_bodies() {
    std::map<std::string, long> lines;
    std::size_t index = 0;
    for (const toml::table* table : root_.tables("body", "[[body]]")) {
      Body body;
      body.pos = pos(table->source());
      body.name =
          unique_name(checked(*table, "[[body]] number " + std::to_string(++index), "[[body]]"), "body", true, lines);
      const TableReader r = reader(*table, "body " + q(body.name));
      body.shape = static_cast<Shape>(choose(r, "shape", kShapeNames));
      const ReadQuantity mass = required_quantity(r, "mass");
      require_bound(mass, "mass", r.context(), true, "kg");
      body.mass = mass.quantity;
      read_sizes(r, body);
      if (auto inertia = quantity_at(r, "inertia")) {
        require_bound(*inertia, "inertia", r.context(), true, "kg m^2");
        body.inertia = inertia->quantity;
      }
      body.points = read_points(r);
      m_.bodies.push_back(std::move(body));
    }
    if (m_.bodies.empty())
      fail(root_.table().source(), "no [[body]]: a mechanism needs at least one body; see mechanisms/README.md");
  }

  // The sizes the shape takes, each required; any other size is a mistake.
  void read_sizes(const TableReader& r, Body& body) const {
    struct Size {
      std::string_view key;
      std::optional<Quantity> Body::*member;
    };
    static constexpr std::array<Size, 3> kSizes{
        {{"length", &Body::length}, {"width", &Body::width}, {"radius", &Body::radius}}};
    std::vector<std::string> takes;
    if (body.shape == Shape::rectangle) takes = {"length", "width"};
    if (body.shape == Shape::rod) takes = {"length"};
    if (body.shape == Shape::disc || body.shape == Shape::ring) takes = {"radius"};
    const std::string shape = kShapeNames[static_cast<std::size_t>(body.shape)];
    for (const Size& size : kSizes) {
      const bool used = std::find(takes.begin(), takes.end(), size.key) != takes.end();
      if (!used && r.has(size.key))
        r.fail(size.key, "a " + shape + " has no " + q(size.key) + "; a " + shape + " takes " +
                             (takes.empty() ? std::string("no sizes") : join_names(takes)));
      if (!used) continue;
      if (!r.has(size.key))
        r.fail(size.key, "a " + shape + " needs " + q(size.key) + "; a " + shape + " takes " + join_names(takes));
      const ReadQuantity read = *quantity_at(r, size.key);
      require_bound(read, size.key, r.context(), true, "m");
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
    for (const toml::table* table : root_.tables("joint", "[[joint]]")) {
      Joint joint;
      joint.pos = pos(table->source());
      joint.name = unique_name(checked(*table, "[[joint]] number " + std::to_string(++index), "[[joint]]"), "joint",
                               true, lines);
      const TableReader r = reader(*table, "joint " + q(joint.name));
      joint.type = static_cast<JointType>(choose(r, "type", kJointTypeNames));
      const auto bodies = two_strings(r, "bodies", "[\"ground\", \"1\"]");
      for (const auto& [body, at] : bodies) check_body(body, at, r.context(), true);
      if (bodies[0].first == bodies[1].first)
        fail(bodies[1].second, r.context() + " joins " + q(bodies[0].first) +
                                   " to itself; give two different bodies (or a body and \"ground\")");
      for (std::size_t i = 0; i < 2; ++i) joint.bodies[i] = bodies[i].first;
      read_joint_options(r, joint);  // before the points: a key of another type is named first
      if (joint_type_info(joint.type).mesh) {
        if (r.has("points"))
          r.fail("points", std::string("a ") + joint_type_name(joint.type) +
                               " takes no 'points': its points are where its bodies are pinned to its carrier");
      } else {
        const auto points = two_strings(r, "points", "[\"O\", \"A\"]");
        for (std::size_t i = 0; i < 2; ++i) {
          joint.points[i] = points[i].first;
          check_point(bodies[i].first, points[i].first, points[i].second, r.context());
        }
      }
      m_.joints.push_back(std::move(joint));
    }
    for (Joint& joint : m_.joints)
      if (joint_type_info(joint.type).mesh) find_carrier_pins(joint);
  }

  // A mesh's keys: its carrier (a body or the ground, not one of its gears), two radii and
  // whether it is internal.
  void read_mesh(const TableReader& r, Joint& joint, const std::string& takes) const {
    if (!joint_type_info(joint.type).mesh) {
      for (const std::string_view key : {"carrier", "radii", "internal"})
        if (r.has(key)) r.fail(key, q(key) + " is for " + joint_types_with(&JointTypeInfo::mesh) + " only; " + takes);
      return;
    }
    if (const auto carrier = string_at(r, "carrier", false)) {
      check_body(carrier->first, carrier->second, r.context() + " (carrier)", true);
      if (carrier->first == joint.bodies[0] || carrier->first == joint.bodies[1])
        fail(carrier->second, r.context() + ": 'carrier' " + q(carrier->first) +
                                  " is one of its gears; valid: the body (or \"ground\") both gears are pinned to");
      joint.carrier = carrier->first;
      joint.carrier_pos = carrier->second;
    } else {
      joint.carrier_pos = joint.pos;
    }
    r.require("radii", "[\"r1\", \"r2\"]");
    const toml::node& node = *r.node("radii");
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 2)
      r.fail("radii",
             "'radii' must be [r1, r2], the pitch radii of " + q(joint.bodies[0]) + " and " + q(joint.bodies[1]) +
                 " (numbers or expressions, m), got " +
                 (array == nullptr ? type_phrase(node) : "an array of " + std::to_string(array->size()) + " entries"));
    std::array<Quantity, 2> radii;
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string what = "radii[" + std::to_string(i) + "]";
      const ReadQuantity read = quantity_of(*array->get(i), q(what), r.context());
      require_bound(read, what, r.context(), true, "m");
      radii[i] = read.quantity;
    }
    joint.radii = radii;
    if (r.has("internal")) joint.internal = *r.boolean("internal");
  }

  // Each gear's pin joint to the carrier: its point on the gear is the gear's centre, the
  // mesh's point on that body.
  void find_carrier_pins(Joint& joint) const {
    for (std::size_t i = 0; i < 2; ++i) {
      const Joint* pin = nullptr;
      for (const Joint& other : m_.joints) {
        if (joint_type_info(other.type).motion != JointMotion::revolute) continue;
        for (std::size_t side = 0; side < 2 && pin == nullptr; ++side)
          if (other.bodies[side] == joint.bodies[i] && other.bodies[1 - side] == joint.carrier) {
            pin = &other;
            joint.points[i] = other.points[side];
          }
      }
      if (pin == nullptr)
        fail(joint.pos, "joint " + q(joint.name) + ": gear " + q(joint.bodies[i]) + " is not pinned to its carrier " +
                            q(joint.carrier) + "; valid: a pin joint between " + q(joint.bodies[i]) + " and " +
                            q(joint.carrier) + " (each gear turns on a pin of the carrier)");
    }
  }

  void read_joint_options(const TableReader& r, Joint& joint) const {
    const JointTypeInfo& info = joint_type_info(joint.type);
    const std::string takes = std::string("a ") + joint_type_name(joint.type) + " takes: " + info.options;
    for (const std::string_view key : {"stiffness", "damping", "rest_angle"}) {
      if (!r.has(key)) continue;
      if (!info.torsional_spring)
        r.fail(key, q(key) + " is for " + joint_types_with(&JointTypeInfo::torsional_spring) +
                        " only (a torsional spring-damper); " + takes);
      const auto read = quantity_at(r, key);
      if (key == "stiffness") {
        require_bound(*read, key, r.context(), false, "N m/rad");
        joint.stiffness = read->quantity;
      } else if (key == "damping") {
        require_bound(*read, key, r.context(), false, "N m s/rad");
        joint.damping = read->quantity;
      } else {
        joint.rest_angle = read->quantity;
      }
    }
    if (r.has("angle")) {
      if (!info.angle) r.fail("angle", "'angle' is for " + joint_types_with(&JointTypeInfo::angle) + " only; " + takes);
      joint.angle = quantity_at(r, "angle")->quantity;
    }
    read_radius(r, joint, takes);
    if (!info.axis && r.has("axis"))
      r.fail("axis", "'axis' is for " + joint_types_with(&JointTypeInfo::axis) + " only; " + takes);
    read_mesh(r, joint, takes);
    if (!info.axis) return;
    if (!r.has("axis"))
      r.fail("axis", std::string("a ") + joint_type_name(joint.type) +
                         " needs 'axis', its direction [x, y] in the frame of " + q(joint.bodies[0]));
    joint.axis = vector_of(*r.node("axis"), "'axis'", r.context());
    const auto is_zero = [](const Quantity& c) {
      const auto* end = c.text.data() + c.text.size();
      double v = 1;
      const auto [ptr, ec] = std::from_chars(c.text.data(), end, v);
      return ec == std::errc() && ptr == end && v == 0;
    };
    if (is_zero(joint.axis->x) && is_zero(joint.axis->y))
      fail(joint.axis->x.pos,
           r.context() + ": 'axis' = [0, 0] has no direction; valid: a nonzero vector such as [1, 0]");
  }

  // A rolling joint's radius: given, or its rolling body's (bodies[1]) disc radius.
  void read_radius(const TableReader& r, Joint& joint, const std::string& takes) const {
    if (!joint_type_info(joint.type).radius) {
      if (r.has("radius"))
        r.fail("radius", "'radius' is for " + joint_types_with(&JointTypeInfo::radius) + " only; " + takes);
      return;
    }
    if (const auto read = quantity_at(r, "radius")) {
      require_bound(*read, "radius", r.context(), true, "m");
      joint.radius = read->quantity;
      return;
    }
    const Body* rolling = m_.find_body(joint.bodies[1]);
    if (rolling != nullptr && (rolling->shape == Shape::disc || rolling->shape == Shape::ring) && rolling->radius) {
      joint.radius = rolling->radius;
      return;
    }
    fail(joint.pos,
         r.context() + ": the rolling body " + q(joint.bodies[1]) +
             " is not a disc or a ring and the joint gives no 'radius'; valid: a 'radius' > 0 (m), or a disc "
             "or a ring as bodies[1]");
  }

  // [[driver]]: a joint whose type's row is drivable, at most one driver each, a name no
  // body or joint has (they share the columns' namespace), a motion free of the state.
  void read_drivers() {
    std::map<std::string, long> lines;
    std::size_t index = 0;
    for (const toml::table* table : root_.tables("driver", "[[driver]]")) {
      Driver driver;
      driver.pos = pos(table->source());
      const TableReader numbered = checked(*table, "[[driver]] number " + std::to_string(++index), "[[driver]]");
      driver.name = unique_name(numbered, "driver", true, lines);
      const SourcePos name_at = string_at(numbered, "name", true)->second;
      const auto clash = [&](const std::string& kind, const SourcePos& first) {
        fail(name_at, "driver name " + q(driver.name) + " is the name of the " + kind + " at line " +
                          std::to_string(first.line) + "; a driver's name must differ from every body and joint name");
      };
      if (const Body* body = m_.find_body(driver.name)) clash("body", body->pos);
      if (const Joint* joint = m_.find_joint(driver.name)) clash("joint", joint->pos);
      const TableReader r = reader(*table, "driver " + q(driver.name));
      const auto joint_name = string_at(r, "joint", true);
      const Joint* joint = m_.find_joint(joint_name->first);
      std::vector<std::string> drivable;
      for (const Joint& j : m_.joints)
        if (linkage::drivable(j.type)) drivable.push_back(j.name);
      if (joint == nullptr)
        fail(joint_name->second, r.context() + ": " + q(joint_name->first) + " is not a joint" +
                                     did_you_mean(joint_name->first, drivable) +
                                     "; valid: " + join_names(drivable, "none (the file has no pin or slider joint)"));
      if (!linkage::drivable(joint->type))
        fail(joint_name->second, r.context() + ": joint " + q(joint->name) + " is a " + joint_type_name(joint->type) +
                                     ", which cannot be driven; valid: a joint of type " + drivable_joint_types());
      for (const Driver& other : m_.drivers)
        if (other.joint == joint->name)
          fail(joint_name->second, r.context() + ": joint " + q(joint->name) + " is already driven by " +
                                       q(other.name) + " (line " + std::to_string(other.pos.line) +
                                       "); a joint takes one driver");
      driver.joint = joint->name;
      driver.motion = required_quantity(r, "motion").quantity;
      reject_state_in_motion(driver, r.context());
      m_.drivers.push_back(std::move(driver));
    }
  }

  // "crank.theta", "S.s_dot": a BODY.NAME or JOINT.NAME in a motion, which must be a
  // function of t alone (the expression reader would only say "unknown name").
  void reject_state_in_motion(const Driver& driver, const std::string& context) const {
    const std::string& text = driver.motion.text;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const auto word = [&](std::size_t j) { return j < text.size() && (alnum(text[j]) || text[j] == '_'); };
      if (!word(i) || (i > 0 && (word(i - 1) || text[i - 1] == '.'))) continue;
      std::size_t end = i;
      while (word(end)) ++end;
      if (end + 1 >= text.size() || text[end] != '.' || !(alpha(text[end + 1]) || text[end + 1] == '_')) continue;
      const std::string owner = text.substr(i, end - i);
      if (m_.find_body(owner) == nullptr && m_.find_joint(owner) == nullptr) continue;
      std::size_t stop = end + 1;
      while (word(stop)) ++stop;
      fail(driver.motion.pos, context + ": the motion \"" + text + "\" uses the state " + q(text.substr(i, stop - i)) +
                                  "; valid: an expression in t, the parameters and definitions (a prescribed "
                                  "motion cannot depend on the state)");
    }
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
    for (const toml::table* table : root_.tables("spring", "[[spring]]")) {
      Spring spring;
      spring.pos = pos(table->source());
      spring.name = unique_name(checked(*table, "[[spring]] number " + std::to_string(++index), "[[spring]]"), "spring",
                                false, lines);
      const TableReader r = reader(*table, "spring " + q(spring.name));
      const auto between = two_strings(r, "between", "[\"ground.O\", \"1.P\"]");
      for (std::size_t i = 0; i < 2; ++i) spring.between[i] = point_ref(between[i], r.context());
      if (between[0].first == between[1].first)
        fail(between[1].second,
             r.context() + " joins " + q(between[0].first) + " to itself; give two different points");
      const ReadQuantity stiffness = required_quantity(r, "stiffness");
      require_bound(stiffness, "stiffness", r.context(), false, "N/m");
      spring.stiffness = stiffness.quantity;
      const ReadQuantity rest = required_quantity(r, "rest_length");
      require_bound(rest, "rest_length", r.context(), false, "m");
      spring.rest_length = rest.quantity;
      spring.damping = {"0", spring.pos};
      if (auto damping = quantity_at(r, "damping")) {
        require_bound(*damping, "damping", r.context(), false, "N s/m");
        spring.damping = damping->quantity;
      }
      m_.springs.push_back(std::move(spring));
    }
  }

  void read_loads() {
    std::size_t index = 0;
    for (const toml::table* table : root_.tables("force", "[[force]]")) {
      const TableReader r = checked(*table, "[[force]] number " + std::to_string(++index), "[[force]]");
      AppliedForce force;
      force.pos = pos(table->source());
      const auto body = string_at(r, "body", true);
      check_body(body->first, body->second, r.context(), false);
      const auto point = string_at(r, "point", true);
      check_point(body->first, point->first, point->second, r.context());
      r.require("value", "[\"0\", \"-F0\"]");
      force.body = body->first;
      force.point = point->first;
      force.value = vector_of(*r.node("value"), "'value'", r.context());
      m_.forces.push_back(std::move(force));
    }
    index = 0;
    for (const toml::table* table : root_.tables("torque", "[[torque]]")) {
      const TableReader r = checked(*table, "[[torque]] number " + std::to_string(++index), "[[torque]]");
      AppliedTorque torque;
      torque.pos = pos(table->source());
      const auto body = string_at(r, "body", true);
      check_body(body->first, body->second, r.context(), false);
      torque.body = body->first;
      torque.value = required_quantity(r, "value").quantity;
      m_.torques.push_back(std::move(torque));
    }
  }

  void read_initial() {
    const toml::table* table = root_.subtable("initial");
    m_.initial_pos = pos(table != nullptr ? table->source() : root_.table().source());
    if (table == nullptr) return;
    const TableReader initial = reader(*table, "[initial]");
    std::vector<std::string> entries{"independent"};
    for (const Body& body : m_.bodies) entries.push_back(body.name);
    for (const Joint& joint : m_.joints)
      if (has_own_coordinate(joint_type_info(joint.type).motion)) entries.push_back(joint.name);
    for (const auto& [key, node] : initial.entries()) {
      const std::string name(key->str());
      if (name == "independent") {
        read_independent(initial);
        continue;
      }
      const Body* body = m_.find_body(name);
      const Joint* joint = m_.find_joint(name);
      const bool slider = joint != nullptr && has_own_coordinate(joint_type_info(joint->type).motion);
      if (body == nullptr && !slider) {
        const std::string pin_note = joint != nullptr ? " (" + q(name) + " is a " + joint_type_name(joint->type) +
                                                            ": the angle of the body it carries is the coordinate)"
                                                      : "";
        fail(key->source(), "[initial]: " + q(name) + " is not a body or slider joint" + pin_note +
                                did_you_mean(name, entries) + "; valid: " + join_names(entries));
      }
      const std::string context = "[initial] " + q(name);
      const toml::table* values = node->as_table();
      if (values == nullptr)
        fail(node->source(), context + " must be a table such as { " +
                                 (body != nullptr ? "theta = 0.1, theta_dot = 0" : "s = 0.1, s_dot = 0") + " }, got " +
                                 type_phrase(*node));
      std::vector<std::string_view> allowed;
      if (body != nullptr) allowed = keys_of("[initial.BODY]");
      if (slider)
        for (std::string_view k : keys_of("[initial.SLIDER]")) allowed.push_back(k);
      const TableReader r = reader(*values, context, allowed);
      r.reject_unknown_keys();
      for (const auto& [value_key, value] : r.entries()) {
        const std::string coordinate(value_key->str());
        const double number = *r.number(coordinate, -kInf, kInf, "");
        if (!in_magnitude_range(number))
          fail(value->source(), context + ": " + coordinate + " = " + format_roundtrip(number) +
                                    " is out of range; valid: " + kMagnitudeRange);
        m_.initial.push_back({name + "." + coordinate, number, pos(value->source())});
      }
    }
  }

  void read_independent(const TableReader& initial) {
    const toml::node& node = *initial.node("independent");
    m_.independent_pos = pos(node.source());
    if (!node.is_array())
      initial.fail("independent",
                   "'independent' must be a list of coordinates such as [\"2.theta\"], got " + type_phrase(node));
    m_.independent = *initial.strings("independent");  // every entry a string
  }

  // "1.x_ddot" = "x1_ddot": each a name of its own (the JSON key it replaces is checked
  // when the JSON is made, where the keys are known).
  void read_aliases() {
    const toml::table* table = root_.subtable("aliases");
    if (table == nullptr) return;
    std::map<std::string, long> lines;
    for (const auto& [key, node] : reader(*table, "[aliases]").entries()) {
      const std::string context = "[aliases]: " + q(key->str());
      const auto* name = node->as_string();
      if (name == nullptr)
        fail(node->source(), context + " must be a string such as \"x1_ddot\", got " + type_phrase(*node));
      const SourcePos at = pos(node->source());
      if (!is_symbol_name(name->get()))
        fail(at,
             context + ": " + q(name->get()) + " is not a valid alias; valid: a letter, then letters, digits or '_'");
      if (const auto seen = lines.find(name->get()); seen != lines.end())
        fail(at, context + ": the alias " + q(name->get()) + " is used twice (first at line " +
                     std::to_string(seen->second) + "); aliases must be unique");
      lines[name->get()] = at.line;
      m_.aliases.push_back({std::string(key->str()), name->get(), pos(key->source())});
    }
  }

  // [picture]: a one-line title and trail points that name a body's (or the ground's) point.
  void read_picture() {
    const toml::table* table = root_.subtable("picture");
    if (table == nullptr) return;
    const TableReader r = checked(*table, "[picture]", "[picture]");
    if (auto title = string_at(r, "title", false)) {
      if (title->first.find_first_of("\r\n") != std::string::npos)
        fail(title->second, "[picture]: the title must be one line");
      m_.picture.title = title->first;
    }
    if (auto ensemble = string_at(r, "ensemble", false)) {
      std::vector<std::string> coordinates;
      for (const InitialValue& v : m_.initial)
        if (!v.key.ends_with("_dot")) coordinates.push_back(v.key);
      if (std::find(coordinates.begin(), coordinates.end(), ensemble->first) == coordinates.end())
        fail(ensemble->second, "[picture]: ensemble " + q(ensemble->first) + " is not a coordinate of [initial]" +
                                   did_you_mean(ensemble->first, coordinates) + "; valid: " + join_names(coordinates));
      m_.picture.ensemble = ensemble->first;
    }
    const toml::node* trail = r.node("trail");
    if (trail == nullptr) return;
    if (!trail->is_array())
      r.fail("trail", "'trail' must be a list of points such as [\"1.P\"], got " + type_phrase(*trail));
    const std::vector<std::string> points = *r.strings("trail");  // every entry a string
    for (std::size_t i = 0; i < points.size(); ++i) {
      const SourcePos at = pos(trail->as_array()->get(i)->source());
      const std::string& point = points[i];
      const auto dot = point.find('.');
      const std::string body = point.substr(0, dot), name = dot == std::string::npos ? "" : point.substr(dot + 1);
      const std::vector<NamedPoint>* named = nullptr;
      if (body == kGround) named = &m_.ground_points;
      for (const Body& b : m_.bodies)
        if (b.name == body) named = &b.points;
      std::vector<std::string> valid;
      for (const Body& b : m_.bodies)
        for (const NamedPoint& p : b.points) valid.push_back(b.name + "." + p.name);
      for (const NamedPoint& p : m_.ground_points) valid.push_back(std::string(kGround) + "." + p.name);
      const bool found = named != nullptr &&
                         std::any_of(named->begin(), named->end(), [&](const NamedPoint& p) { return p.name == name; });
      if (!found)
        fail(at, "[picture]: trail " + q(point) + " is not a named point" + did_you_mean(point, valid) +
                     "; valid: " + join_names(valid, "none (the file names no points)"));
      m_.picture.trails.push_back(point);
    }
  }

  // [table]: the default columns of an interface built on the file; that they are columns
  // is checked with the derived system (report's work_out_mechanism).
  void read_table() {
    const toml::table* table = root_.subtable("table");
    if (table == nullptr) return;
    const TableReader r = checked(*table, "[table]", "[table]");
    const toml::node* columns = r.node("columns");
    if (columns == nullptr) return;
    if (!columns->is_array())
      r.fail("columns",
             "'columns' must be a list of column names such as [\"t\", \"1.x\"], got " + type_phrase(*columns));
    if (columns->as_array()->empty()) r.fail("columns", "'columns' is empty; list at least one column");
    const std::vector<std::string> names = *r.strings("columns");  // every entry a string
    for (std::size_t i = 0; i < names.size(); ++i) {
      const SourcePos at = pos(columns->as_array()->get(i)->source());
      for (const TableColumn& c : m_.table)
        if (c.name == names[i])
          fail(at, "[table]: column " + q(names[i]) + " is listed twice (first at line " + std::to_string(c.pos.line) +
                       ", column " + std::to_string(c.pos.column) + ")");
      m_.table.push_back({names[i], at});
    }
  }

  std::string file_;
  TableReader root_;
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
