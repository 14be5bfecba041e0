#include "report/mechanism_parts.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/number_format.hpp"
#include "formulations/case_system.hpp"
#include "model/body_phrase.hpp"
#include "model/joint_types.hpp"
#include "report/expression_print.hpp"
#include "symbolic/state_values.hpp"

namespace linkage {

std::string body_label(const Mechanism& mechanism, int body) {
  if (body < 0) return "the ground";
  return body_phrase(mechanism.bodies[static_cast<std::size_t>(body)]);
}

std::string body_label(const Mechanism& mechanism, const std::string& name) {
  for (std::size_t i = 0; i < mechanism.bodies.size(); ++i)
    if (mechanism.bodies[i].name == name) return body_label(mechanism, static_cast<int>(i));
  return body_label(mechanism, -1);
}

std::string load_place(const sym::System& system, std::size_t body, const sym::Load& load) {
  const sym::BodySystem& b = system.bodies()[body];
  const sym::Vec2 offset = load.point - sym::Vec2{b.x.q, b.y.q};
  if (GiNaC::expand(offset.x).is_zero() && GiNaC::expand(offset.y).is_zero()) return "the centre of mass";
  for (const auto& [name, local] : b.points) {
    const sym::Vec2 d = offset - sym::rotate(b.rotates ? GiNaC::ex(b.theta.q) : GiNaC::ex(0), local);
    if (GiNaC::expand(d.x).is_zero() && GiNaC::expand(d.y).is_zero()) return name;
  }
  return "";
}

std::vector<PinInertia> pin_inertias(const sym::System& system) {
  std::vector<PinInertia> out;
  const Mechanism& m = system.mechanism();
  for (const sym::BodySystem& b : system.bodies()) {
    if (!b.rotates) continue;
    const sym::SymbolInfo* inertia = system.table().find(GiNaC::ex_to<GiNaC::symbol>(b.inertia));
    for (const Joint& joint : m.joints) {
      switch (joint_type_info(joint.type).motion) {  // the inertia about a revolute joint's point
        case JointMotion::revolute:
          break;
        case JointMotion::prismatic:
        case JointMotion::fixed:
        case JointMotion::rolling:  // it turns about its contact point, not a point of the body
        case JointMotion::slotted:  // its pin slides along the slot
        case JointMotion::loop:     // it carries no body
          continue;
      }
      for (std::size_t end = 0; end < 2; ++end) {
        if (joint.bodies[end] != b.name) continue;
        const std::string& point = joint.points[end];
        const sym::Vec2& r = b.points.at(point);
        const GiNaC::ex r2 = GiNaC::expand(r.x * r.x + r.y * r.y);
        if (r2.is_zero()) continue;
        std::string latex = inertia->latex;
        if (latex.ends_with("^{C}")) latex.resize(latex.size() - 4);
        PinInertia p{concat({inertia->unicode, "^", point}), concat({inertia->ascii, "^", point}),
                     concat({latex, "^{", point, "}"}), b.inertia + b.mass * r2};
        const bool seen = std::any_of(out.begin(), out.end(), [&](const PinInertia& q) {
          return q.ascii == p.ascii && (q.formula - p.formula).expand().is_zero();
        });
        if (!seen) out.push_back(std::move(p));
      }
    }
  }
  return out;
}

std::string given_note(const Mechanism& mechanism) {
  std::string given;
  const auto add = [&](const std::string& name, double value, const SourcePos& pos) {
    if (pos.line != 0 || pos.file.empty()) return;  // from the file itself
    if (!given.empty()) given += ", ";
    given += concat({name, " = ", format_roundtrip(value), " (", pos.file, ")"});
  };
  for (const Parameter& p : mechanism.parameters) add(p.name, p.value, p.pos);
  for (const InitialValue& v : mechanism.initial) add(v.key, v.value, v.pos);
  const std::string source = mechanism.source.starts_with("built-in ")
                                 ? concat({"the shipped ", std::string_view(mechanism.source).substr(9)})
                                 : mechanism.source;
  if (given.empty()) return concat({"All values as in ", source, "."});
  return concat({"Given: ", given, "; the rest as in ", source, "."});
}

GiNaC::ex with_lengths(const sym::System& system, const GiNaC::ex& e) {
  GiNaC::exmap roots, squares;
  for (const auto& [symbol, length] : system.lengths()) {
    roots[length] = symbol;
    squares[length.op(0)] = GiNaC::pow(symbol, 2);  // the square under the root, as a damper's power has it
  }
  return e.subs(roots).subs(squares);  // the roots first, so they do not become sqrt(l^2)
}

bool touches_ground(const Mechanism& mechanism) {
  for (const Joint& j : mechanism.joints)
    if (j.bodies[0] == kGround || j.bodies[1] == kGround) return true;
  for (const Spring& s : mechanism.springs)
    if (s.between[0].body == kGround || s.between[1].body == kGround) return true;
  return !mechanism.forces.empty() || !mechanism.torques.empty();
}

EquationSides acceleration_form(const sym::System& system, const GiNaC::ex& phi, Style style) {
  std::vector<const sym::SymbolInfo*> accelerations;
  std::vector<GiNaC::symbol> symbols;
  for (const sym::SymbolInfo& info : system.table().all())
    if (info.role == sym::Role::acceleration && !info.key.ends_with(".s_ddot")) {
      accelerations.push_back(&info);
      symbols.push_back(info.symbol);
    }
  const GiNaC::ex second = system.time_derivative(system.time_derivative(phi));
  const CaseSystem row = linear_system(CaseId::maximal, {second}, symbols);
  return equation_sides(row.A[0], row.B[0], accelerations, system.table(), style);
}

WrittenValues written_state_values(const sym::System& system) {
  WrittenValues out;
  const std::vector<sym::StateValue> values = sym::state_values(system);
  for (const sym::StateValue& v : values) out.values.push_back({v.what, v.quantity->text});
  // A name used as a token of some value's text: not followed by a name's character.
  const auto used = [&](const std::string& name) {
    return std::any_of(values.begin(), values.end(), [&](const sym::StateValue& v) {
      const std::string& text = v.quantity->text;
      for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        const std::size_t end = at + name.size();
        const bool starts = at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) ||
                                         text[at - 1] == '_' || text[at - 1] == '.');
        const bool ends = end == text.size() || !(std::isalnum(static_cast<unsigned char>(text[end])) ||
                                                  text[end] == '_' || text[end] == '.');
        if (starts && ends) return true;
      }
      return false;
    });
  };
  // A joint's names (a slider's s, s_dot): no maximal coordinate, even where one equals it.
  const auto of_a_joint = [&](const std::string& name) {
    const std::string owner = name.substr(0, name.find('.'));
    const auto& joints = system.mechanism().joints;
    return std::any_of(joints.begin(), joints.end(), [&](const Joint& j) { return j.name == owner; });
  };
  for (const auto& [name, expression] : system.state_names())
    if (of_a_joint(name) && used(name)) out.rewritten.emplace_back(name, expression);
  return out;
}

}  // namespace linkage
