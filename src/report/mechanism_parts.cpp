#include "report/mechanism_parts.hpp"

#include <array>
#include <cctype>

#include "formulations/case_system.hpp"
#include "report/expression_print.hpp"

namespace linkage {

std::string body_label(const Mechanism& mechanism, int body) {
  if (body < 0) return "the ground";
  const Body& b = mechanism.bodies[static_cast<std::size_t>(body)];
  bool numeric = !b.name.empty();
  for (char c : b.name) numeric = numeric && std::isdigit(static_cast<unsigned char>(c)) != 0;
  static constexpr std::array<const char*, 4> kNoun{"block", "rod", "disc", "mass"};
  return numeric ? std::string(kNoun[static_cast<std::size_t>(b.shape)]) + " " + b.name : b.name;
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

}  // namespace linkage
