// Case 2, the spanning tree's generalized coordinates q with every joint force kept.
// Each body's Newton-Euler rows with its x, y, theta and their derivatives written in q:
//   x_b = X_b(q),  x_b' = X_b,q q',  x_b'' = X_b,q q'' + (X_b,q q')_q q'.
// Rows, in order: the row of each generalized coordinate (x -> the body's x row, y -> its
// y row, theta -> its moment row, s -> its row along the slider axis); then the rest,
// body by body, a translation row per unit mass (x_b'' + sum F / m_b: the homework's
// (5.2), (6.2)); then each loop-closing joint's constraint at the acceleration level,
// then each driver's (kept like a loop's, its torque or force an unknown).
#include <stdexcept>

#include "core/interrupt.hpp"
#include "formulations/case_system.hpp"
#include "model/joint_types.hpp"
#include "symbolic/joints.hpp"

namespace linkage {

namespace {

struct BodyRows {
  std::vector<GiNaC::ex> rows;  // x, y, theta; or along, across, theta for a slider's child
  std::vector<int> own;         // the coordinate index each row belongs to, -1 for none
};

}  // namespace

GeneralizedRows generalized_rows(const sym::System& system) {
  const auto& bodies = system.bodies();
  const auto& coordinates = system.coordinates();
  const SpanningTree& tree = system.tree();
  const GiNaC::exmap& to_q = system.to_generalized();

  GeneralizedRows out;
  for (const sym::GeneralizedCoordinate& g : coordinates) out.unknowns.push_back(g.symbols.q_ddot);
  for (const sym::JointSystem& j : system.joints())
    for (const GiNaC::symbol& u : j.unknowns) out.unknowns.push_back(u);
  for (const sym::DriverSystem& d : system.drivers()) out.unknowns.push_back(d.unknown);

  std::vector<BodyRows> per_body(bodies.size());
  for (const sym::NewtonEulerRows& ne : system.newton_euler()) {
    throw_if_interrupted();
    const auto b = static_cast<std::size_t>(ne.body);
    BodyRows& rows = per_body[b];
    for (const GiNaC::ex& r : ne.rows)
      rows.rows.push_back(GiNaC::expand(r.subs(to_q, GiNaC::subs_options::no_pattern)));
    rows.own.assign(rows.rows.size(), -1);
    // A prismatic or slotted joint's child: its translation rows along and across the axis.
    const TreeBody& node = tree.bodies[b];
    if (node.floating || node.joint < 0) continue;
    const Joint& joint = system.mechanism().joints[static_cast<std::size_t>(node.joint)];
    switch (joint_type_info(joint.type).motion) {
      case JointMotion::revolute:
      case JointMotion::fixed:
      case JointMotion::rolling:
      case JointMotion::loop:  // never a tree joint
        break;
      case JointMotion::prismatic:
      case JointMotion::slotted: {
        const sym::Vec2 axis = sym::joint_axis(system, joint);
        const GiNaC::ex length = GiNaC::sqrt(axis.x * axis.x + axis.y * axis.y);
        // The axis turns with bodies[0] (a slider's child keeps that angle).
        const int holder = system.mechanism().body_index(joint.bodies[0]);
        const GiNaC::ex angle = holder >= 0 && bodies[static_cast<std::size_t>(holder)].rotates
                                    ? GiNaC::ex(bodies[static_cast<std::size_t>(holder)].theta.q)
                                          .subs(to_q, GiNaC::subs_options::no_pattern)
                                    : GiNaC::ex(0);
        const sym::Vec2 u = sym::rotate(angle, {axis.x / length, axis.y / length});
        const GiNaC::ex rx = rows.rows[0], ry = rows.rows[1];
        rows.rows[0] = GiNaC::expand(u.x * rx + u.y * ry);
        rows.rows[1] = GiNaC::expand(-u.y * rx + u.x * ry);
        break;
      }
    }
  }
  for (std::size_t c = 0; c < coordinates.size(); ++c) {
    const Coordinate& coordinate = coordinates[c].coordinate;
    const int row = coordinate.kind == CoordinateKind::y ? 1 : coordinate.kind == CoordinateKind::theta ? 2 : 0;
    per_body[static_cast<std::size_t>(coordinate.body)].own[static_cast<std::size_t>(row)] = static_cast<int>(c);
  }
  // Own rows in coordinate order.
  for (std::size_t c = 0; c < coordinates.size(); ++c)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (std::size_t r = 0; r < per_body[b].rows.size(); ++r)
        if (per_body[b].own[r] == static_cast<int>(c)) out.rows.push_back(per_body[b].rows[r]);
  // The rest, translation per unit mass.
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (std::size_t r = 0; r < per_body[b].rows.size(); ++r) {
      if (per_body[b].own[r] >= 0) continue;
      const GiNaC::ex row = per_body[b].rows[r];
      out.rows.push_back(r < 2 ? GiNaC::expand(row / bodies[b].mass) : row);
    }
  for (int j : tree.loop_joints)
    for (const GiNaC::ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints)
      out.rows.push_back(GiNaC::expand(
          system.time_derivative(system.time_derivative(phi.subs(to_q, GiNaC::subs_options::no_pattern)))));
  for (const sym::DriverSystem& d : system.drivers())
    out.rows.push_back(GiNaC::expand(
        system.time_derivative(system.time_derivative(d.constraint.subs(to_q, GiNaC::subs_options::no_pattern)))));

  for (const sym::BodySystem& b : bodies) {
    auto recover = [&](const sym::CoordinateSymbols& c) {
      if (const auto it = to_q.find(c.q_ddot); it != to_q.end()) out.recovered.push_back({c.q_ddot, it->second});
    };
    recover(b.x);
    recover(b.y);
    if (b.rotates) recover(b.theta);
  }
  return out;
}

CaseSystem generalized_case(const sym::System& system) {
  GeneralizedRows g = generalized_rows(system);
  CaseSystem out = linear_system(CaseId::generalized, g.rows, g.unknowns);
  out.recovered = std::move(g.recovered);
  out.title = count_word(g.rows.size()) + " equations in generalized coordinates" +
              (system.mechanism().joints.empty() ? ", no joints" : " with the " + force_phrase(system));
  return out;
}

}  // namespace linkage
