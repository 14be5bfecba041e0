// Case 1, maximal coordinates. Unknowns: x_b'', y_b'', theta_b'' of every body, then every
// joint's force. Rows: Newton-Euler of every body,
//   m_b x_b'' - sum F_x = 0,   m_b y_b'' - sum F_y = 0,   I_b theta_b'' - sum M = 0,
// then every joint's constraint at the acceleration level, Phi'' = 0:
//   Phi_q q'' = -(Phi_q q')_q q'   (the second time derivative, q'' terms on the left);
// then every driver's, C'' = 0, its torque or force the last unknowns.
#include "formulations/case_system.hpp"

namespace linkage {

CaseSystem maximal_case(const sym::System& system) {
  std::vector<GiNaC::symbol> unknowns;
  for (const sym::BodySystem& b : system.bodies()) {
    unknowns.push_back(b.x.q_ddot);
    unknowns.push_back(b.y.q_ddot);
    if (b.rotates) unknowns.push_back(b.theta.q_ddot);
  }
  for (const sym::JointSystem& j : system.joints())
    for (const GiNaC::symbol& u : j.unknowns) unknowns.push_back(u);
  for (const sym::DriverSystem& d : system.drivers()) unknowns.push_back(d.unknown);

  std::vector<GiNaC::ex> rows;
  for (const sym::NewtonEulerRows& ne : system.newton_euler())
    for (const GiNaC::ex& r : ne.rows) rows.push_back(r);
  for (const sym::JointSystem& j : system.joints())
    for (const GiNaC::ex& phi : j.constraints) rows.push_back(system.time_derivative(system.time_derivative(phi)));
  for (const sym::DriverSystem& d : system.drivers())
    rows.push_back(system.time_derivative(system.time_derivative(d.constraint)));

  CaseSystem out = linear_system(CaseId::maximal, rows, unknowns);
  out.maximal = true;
  // With no joint there is no constraint: ordinary equations, and no force to keep.
  out.title = system.mechanism().joints.empty()
                  ? count_word(rows.size()) + " equations in maximal coordinates, no joints"
                  : count_word(rows.size()) + " DAEs in maximal coordinates with the " + force_phrase(system);
  return out;
}

}  // namespace linkage
