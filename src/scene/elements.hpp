#pragma once
// The parts of a picture a user can show or hide (`linkage render --show/--hide`).
// The set decides what the scene builds and what the simulation must compute: no pin
// force arrows means no pin force solves; no trail means no trail points.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace linkage {

enum class Element : std::uint8_t {
  blocks,        // the two blocks, true size, semi-transparent so their overlap shows
  pin,           // the pin P
  pin_force,     // the pin force on block 1 at P and its opposite on block 2
  gravity,       // m g at each centre of mass
  velocity,      // velocity of each centre of mass
  trail,         // the fading path of P
  com,           // both centres of mass and the system's
  grid,          // a metric grid
  axes,          // coordinate ticks in metres along two frame edges
  hud,           // time, case, integrator, energy and constraint errors
  legend,        // what each colour is, arrow scales, the grid spacing
  labels,        // "1", "2" on the blocks and names on the arrows
  title,         // the title line
  equations,     // the case's equations as `linkage solve` prints them, in a band under the motion
  spring_force,  // a mechanism's spring (and damper) force on each body at its end
  loads,         // a mechanism's applied forces and torques
  acceleration,  // acceleration of each centre of mass and traced point (a mechanism's)
  motor,         // a [[driver]] drawn as a motor at its joint, with its torque or force
};

struct ElementInfo {
  Element element;
  std::string_view name;  // CLI spelling, e.g. "pin-force"
  bool shown_by_default;
};

inline constexpr std::array<ElementInfo, 18> kElements{{
    {Element::blocks, "blocks", true},
    {Element::pin, "pin", true},
    {Element::pin_force, "pin-force", true},
    {Element::gravity, "gravity", true},
    {Element::velocity, "velocity", false},
    {Element::trail, "trail", true},
    {Element::com, "com", true},
    {Element::grid, "grid", true},
    {Element::axes, "axes", false},
    {Element::hud, "hud", true},
    {Element::legend, "legend", true},
    {Element::labels, "labels", true},
    {Element::title, "title", true},
    {Element::equations, "equations", false},
    {Element::spring_force, "spring-force", true},
    {Element::loads, "loads", true},
    {Element::acceleration, "acceleration", false},
    {Element::motor, "motor", true},
}};

/// Other spellings a mechanism's picture reads more naturally with.
inline constexpr std::array<std::pair<std::string_view, Element>, 3> kElementAliases{{
    {"bodies", Element::blocks},
    {"joints", Element::pin},
    {"joint-force", Element::pin_force},
}};

/// A set of elements (a bit per element).
class ElementSet {
 public:
  /// The defaults: everything a lecture needs (velocity arrows and axes off).
  [[nodiscard]] static ElementSet defaults();
  [[nodiscard]] static ElementSet none() { return ElementSet{}; }
  [[nodiscard]] static ElementSet all();

  [[nodiscard]] bool has(Element e) const { return (bits_ & bit(e)) != 0; }
  void show(Element e) { bits_ |= bit(e); }
  void hide(Element e) { bits_ &= ~bit(e); }
  bool operator==(const ElementSet&) const = default;

 private:
  static std::uint32_t bit(Element e) { return 1u << static_cast<unsigned>(e); }
  std::uint32_t bits_ = 0;
};

/// The element named `name` (CLI spelling); throws Error::input naming `origin` and
/// every valid name otherwise.
[[nodiscard]] Element parse_element(std::string_view name, const std::string& origin);
[[nodiscard]] std::string_view name(Element e);
/// "blocks, pin, pin-force, ..." for help and error messages.
[[nodiscard]] std::string element_name_list();

/// Applies names (each entry may itself be a comma-separated list) to `set`: first
/// every shown name, then every hidden one, so the order of the flags does not matter.
/// Throws Error::input naming --show or --hide for an unknown name.
void apply_show_hide(ElementSet& set, const std::vector<std::string>& show, const std::vector<std::string>& hide);

}  // namespace linkage
