#include "evaluate/tree_dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/joint_types.hpp"
#include "symbolic/joints.hpp"

namespace linkage::eval {

namespace {

using GiNaC::ex;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

enum class NodeKind { floating, revolute, prismatic };  // model/joint_types.hpp: JointMotion

/// One body of the tree, in the order the tree reached it (parents first).
struct Node {
  int body = -1;
  int parent = -1;  // node index, -1 for the ground or none
  NodeKind kind = NodeKind::floating;
  bool rotates = true;
  int dof = 0;
  std::array<int, 3> coordinate{-1, -1, -1};  // generalized indices of the dof
  double mass = 0, inertia = 0;
  Vec2 parent_point = Vec2::Zero();  // in the parent's frame (the world for the ground)
  Vec2 child_point = Vec2::Zero();   // in the body's frame
  Vec2 axis = Vec2::Zero();          // slider: unit, parent's frame (the world for the ground)
  double sign = 1;                   // slider: +1 when the body is bodies[1] of its joint
};

/// A symmetric 3 x 3 matrix by its upper triangle.
struct Sym3 {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
};

/// Per node, the numbers of one evaluation, about the node's own point O (see the header).
struct Work {
  Vec2 centre = Vec2::Zero(), point = Vec2::Zero();  // the centre of mass and O, world
  Vec2 t = Vec2::Zero();  // (-d_y, d_x), d = O - O_parent: motion to O is (w, v + w t), force to O_parent (n + t.F, F)
  double angle = 0, cos_angle = 1, sin_angle = 0;  // each angle's cosine and sine once
  Vec3 s = Vec3::Zero();                           // one-dof joints' motion subspace
  Vec3 v = Vec3::Zero(), c = Vec3::Zero(), a = Vec3::Zero();
  Sym3 IA;
  Vec3 pA = Vec3::Zero(), U = Vec3::Zero(), u = Vec3::Zero();
  double Dinv = 0;
  // Pins: q''_relative = h - W . a_parent.
  Vec3 W = Vec3::Zero();
  double h = 0;
};

/// A floating root's solve: the rotating base's I^A, the point mass's translation block.
struct RootFactor {
  Eigen::LDLT<Mat3> full;
  Eigen::Matrix2d translation_inverse = Eigen::Matrix2d::Zero();
};

/// R(angle) v, with cos and sin of the angle given.
Vec2 rotate(double c, double s, const Vec2& v) { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }

/// X^T Ia X into `parent`: Ia = [A b^T; b K] about O moved to O_parent, X = [1 0; t 1].
void add_shifted(Sym3& parent, const Sym3& ia, const Vec2& t) {
  const double kt0 = ia.a11 * t[0] + ia.a12 * t[1], kt1 = ia.a12 * t[0] + ia.a22 * t[1];
  parent.a00 += ia.a00 + 2 * (ia.a01 * t[0] + ia.a02 * t[1]) + t[0] * kt0 + t[1] * kt1;
  parent.a01 += ia.a01 + kt0;
  parent.a02 += ia.a02 + kt1;
  parent.a11 += ia.a11;
  parent.a12 += ia.a12;
  parent.a22 += ia.a22;
}

/// X^T f into `parent`.
void add_shifted(Vec3& parent, const Vec3& f, const Vec2& t) {
  parent[0] += f[0] + t[0] * f[1] + t[1] * f[2];
  parent[1] += f[1];
  parent[2] += f[2];
}

Vec3 times(const Sym3& m, const Vec3& x) {
  return {m.a00 * x[0] + m.a01 * x[1] + m.a02 * x[2], m.a01 * x[0] + m.a11 * x[1] + m.a12 * x[2],
          m.a02 * x[0] + m.a12 * x[1] + m.a22 * x[2]};
}

Mat3 full(const Sym3& m) {
  Mat3 out;
  out << m.a00, m.a01, m.a02, m.a01, m.a11, m.a12, m.a02, m.a12, m.a22;
  return out;
}

}  // namespace

struct TreeDynamics::Impl {
  std::vector<Node> nodes;
  std::size_t coordinates = 0;
  std::vector<double> parameters;
  bool loads_constant = false;
  Program loads;  // per body Fx, Fy, moment about its centre; inputs: parameters, x y theta per body, rates, t
  Program loops;  // J (m x n, row major), then phi0 (m); inputs: parameters, q, q', t
  int loop_rows = 0;
  // Allocated once: per node, in the tree's order.
  mutable std::vector<Work> work;
  mutable std::vector<RootFactor> roots;
  mutable std::vector<double> angle_force;
  mutable std::vector<double> load_inputs, load_outputs, loop_inputs, loop_outputs, scratch;
  mutable Eigen::MatrixXd J, MinvJt, schur;
  mutable Eigen::VectorXd tau, column, phi0, lambda;
  mutable Eigen::LDLT<Eigen::MatrixXd> factor;

  /// Positions, velocities and each body's inertia and velocity-product force root to
  /// leaves from y = (q, q'), the loads' inputs filled.
  void kinematics(const Eigen::VectorXd& y) const;
  /// The loaded pass: articulated inertias and biases leaves to root (kept for the
  /// unloaded passes), accelerations root to leaves.
  void articulate(Eigen::VectorXd& out) const;
  /// q'' = M^-1 tau (generalized forces on the absolute coordinates), on the articulated
  /// inertias of the last loaded pass: no velocity terms and no loads.
  void unloaded(const Eigen::VectorXd& tau_absolute, Eigen::VectorXd& out) const;
  /// Root to leaves: each node's q'' from its parent's acceleration, into out.
  void accelerate(bool loaded, Eigen::VectorXd& out) const;
};

std::vector<Program*> TreeDynamics::programs() { return {&impl_->loads, &impl_->loops}; }

bool TreeDynamics::applies(const sym::System& system) {
  const SpanningTree& tree = system.tree();
  for (std::size_t b = 0; b < tree.bodies.size(); ++b)
    if (!tree.bodies[b].floating && !system.bodies()[b].rotates) return false;
  return true;
}

TreeDynamics::TreeDynamics(const sym::System& system) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const Mechanism& mechanism = system.mechanism();
  const SpanningTree& tree = system.tree();
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, value] : system.constants()) values[symbol] = value;
  auto number = [&](const ex& e) { return sym::evaluate(e, values); };
  auto local = [&](int body, const std::string& point) {
    const sym::Vec2 p =
        body < 0 ? system.point_position(-1, point) : system.bodies()[static_cast<std::size_t>(body)].points.at(point);
    return Vec2(number(p.x), number(p.y));
  };

  std::vector<int> node_of(tree.bodies.size(), -1);
  for (int b : tree.order) {
    const TreeBody& t = tree.bodies[static_cast<std::size_t>(b)];
    const sym::BodySystem& body = system.bodies()[static_cast<std::size_t>(b)];
    Node n;
    n.body = b;
    n.rotates = body.rotates;
    n.mass = number(body.mass);
    n.inertia = body.rotates ? number(body.inertia_formula) : 0.0;
    n.parent = t.parent >= 0 ? node_of[static_cast<std::size_t>(t.parent)] : -1;
    if (t.floating) {
      n.kind = NodeKind::floating;
    } else {
      const Joint& joint = mechanism.joints[static_cast<std::size_t>(t.joint)];
      const bool child_is_b = mechanism.body_index(joint.bodies[1]) == b;
      const int parent_body = t.parent;
      n.parent_point = local(parent_body, joint.points[child_is_b ? 0 : 1]);
      n.child_point = local(b, joint.points[child_is_b ? 1 : 0]);
      switch (joint_type_info(joint.type).motion) {
        case JointMotion::revolute:
          n.kind = NodeKind::revolute;
          break;
        case JointMotion::prismatic: {
          const sym::Vec2 axis = sym::joint_axis(system, joint);
          n.kind = NodeKind::prismatic;
          n.axis = Vec2(number(axis.x), number(axis.y)).normalized();
          n.sign = child_is_b ? 1.0 : -1.0;
          break;
        }
      }
    }
    node_of[static_cast<std::size_t>(b)] = static_cast<int>(m.nodes.size());
    m.nodes.push_back(n);
  }
  for (std::size_t i = 0; i < system.coordinates().size(); ++i) {
    const Coordinate& c = system.coordinates()[i].coordinate;
    Node& n = m.nodes[static_cast<std::size_t>(node_of[static_cast<std::size_t>(c.body)])];
    const int slot = c.kind == CoordinateKind::x    ? 0
                     : c.kind == CoordinateKind::y  ? 1
                     : n.kind == NodeKind::floating ? 2
                                                    : 0;
    n.coordinate[static_cast<std::size_t>(slot)] = static_cast<int>(i);
    n.dof = std::max(n.dof, slot + 1);
  }
  m.coordinates = system.coordinates().size();

  // The loads, in every body's maximal coordinates.
  std::vector<GiNaC::symbol> inputs;
  for (const sym::SymbolInfo& info : system.table().all())
    if (info.role == sym::Role::parameter) {
      inputs.push_back(info.symbol);
      m.parameters.push_back(sym::to_double(system.parameter_values().at(info.symbol)));
    }
  const std::size_t parameter_count = inputs.size();
  for (const sym::BodySystem& b : system.bodies()) {
    inputs.push_back(b.x.q);
    inputs.push_back(b.y.q);
    inputs.push_back(b.theta.q);  // a point mass's never appears: its slot stays 0
  }
  for (const sym::BodySystem& b : system.bodies()) {
    inputs.push_back(b.x.q_dot);
    inputs.push_back(b.y.q_dot);
    inputs.push_back(b.theta.q_dot);
  }
  inputs.push_back(system.time());
  auto prepare = [&](const ex& e) {
    return GiNaC::expand(e.subs(system.lengths(), GiNaC::subs_options::no_pattern)
                             .subs(system.constants(), GiNaC::subs_options::no_pattern)
                             .subs(system.constants(), GiNaC::subs_options::no_pattern));
  };
  std::vector<ex> per_body(3 * system.bodies().size(), ex(0));
  for (const sym::Load& load : system.loads()) {
    if (load.body < 0) continue;
    const auto b = static_cast<std::size_t>(load.body);
    per_body[3 * b] += load.force.x;
    per_body[3 * b + 1] += load.force.y;
    // About the body's centre: r_b cancels symbolically, so the moment carries no
    // round-off of the body's distance from the origin.
    const sym::BodySystem& body = system.bodies()[b];
    per_body[3 * b + 2] +=
        (load.point.x - body.x.q) * load.force.y - (load.point.y - body.y.q) * load.force.x + load.moment;
  }
  for (ex& e : per_body) e = prepare(e);
  // Gravity alone is the same force at every state: evaluated once, not per call.
  m.loads_constant = true;
  for (const ex& e : per_body)
    m.loads_constant = m.loads_constant && GiNaC::is_a<GiNaC::numeric>(e.subs(system.parameter_values()));
  m.loads = compile(per_body, inputs);
  m.load_inputs.assign(inputs.size(), 0.0);
  for (std::size_t i = 0; i < parameter_count; ++i) m.load_inputs[i] = m.parameters[i];
  m.load_outputs.resize(per_body.size());
  if (m.loads_constant) {
    std::vector<double> scratch(m.loads.scratch_size());
    m.loads.run(m.load_inputs.data(), m.load_outputs.data(), scratch.data());
  }

  // The loops' acceleration rows Phi'' = J q'' + phi0, in the generalized coordinates.
  std::vector<GiNaC::symbol> loop_inputs(inputs.begin(), inputs.begin() + static_cast<std::ptrdiff_t>(parameter_count));
  std::vector<GiNaC::symbol> accelerations;
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) loop_inputs.push_back(g.symbols.q);
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    loop_inputs.push_back(g.symbols.q_dot);
    accelerations.push_back(g.symbols.q_ddot);
  }
  loop_inputs.push_back(system.time());
  std::vector<ex> jacobian, bias;
  GiNaC::exmap no_acceleration;
  for (const GiNaC::symbol& a : accelerations) no_acceleration[a] = 0;
  for (int j : tree.loop_joints)
    for (const ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints) {
      const ex rows = GiNaC::expand(system
                                        .time_derivative(system.time_derivative(
                                            phi.subs(system.to_generalized(), GiNaC::subs_options::no_pattern)))
                                        .subs(system.constants(), GiNaC::subs_options::no_pattern));
      for (const GiNaC::symbol& a : accelerations) jacobian.push_back(prepare(rows.coeff(a, 1)));
      bias.push_back(prepare(rows.subs(no_acceleration, GiNaC::subs_options::no_pattern)));
      ++m.loop_rows;
    }
  jacobian.insert(jacobian.end(), bias.begin(), bias.end());
  m.loops = compile(jacobian, loop_inputs);
  m.loop_inputs.assign(loop_inputs.size(), 0.0);
  for (std::size_t i = 0; i < parameter_count; ++i) m.loop_inputs[i] = m.parameters[i];
  m.loop_outputs.resize(jacobian.size());
  m.scratch.resize(std::max(m.loads.scratch_size(), m.loops.scratch_size()));
  m.work.resize(m.nodes.size());
  m.roots.resize(m.nodes.size());
  m.angle_force.resize(m.nodes.size());
  const auto n = static_cast<Eigen::Index>(m.coordinates);
  m.J.resize(m.loop_rows, n);
  m.MinvJt.resize(n, m.loop_rows);
  m.phi0.resize(m.loop_rows);
  m.schur.resize(m.loop_rows, m.loop_rows);
  m.tau.resize(n);
  m.column.resize(n);
}

TreeDynamics::~TreeDynamics() = default;
TreeDynamics::TreeDynamics(TreeDynamics&&) noexcept = default;
TreeDynamics& TreeDynamics::operator=(TreeDynamics&&) noexcept = default;

void TreeDynamics::Impl::kinematics(const Eigen::VectorXd& y) const {
  const auto n = static_cast<Eigen::Index>(coordinates);
  const double* q = y.data();
  const double* q_dot = q + n;
  const std::size_t bodies = nodes.size(), first = parameters.size();
  for (std::size_t k = 0; k < bodies; ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    const Work* p = node.parent >= 0 ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    // The joint's point on the parent, world.
    const Vec2 joint =
        p != nullptr ? Vec2(p->centre + rotate(p->cos_angle, p->sin_angle, node.parent_point)) : node.parent_point;
    switch (node.kind) {
      case NodeKind::floating: {
        w.centre = {q[node.coordinate[0]], q[node.coordinate[1]]};
        w.point = w.centre;
        w.angle = node.rotates ? q[node.coordinate[2]] : 0.0;
        w.cos_angle = std::cos(w.angle);
        w.sin_angle = std::sin(w.angle);
        const double omega = node.rotates ? q_dot[node.coordinate[2]] : 0.0;
        const double vx = q_dot[node.coordinate[0]], vy = q_dot[node.coordinate[1]];
        w.t.setZero();
        w.v = {omega, vx, vy};
        // About the point where the centre is now: S' q' = (0, w y', -w x').
        w.c = {0, omega * vy, -omega * vx};
        break;
      }
      case NodeKind::revolute: {
        w.angle = q[node.coordinate[0]];
        w.cos_angle = std::cos(w.angle);
        w.sin_angle = std::sin(w.angle);
        w.point = joint;
        w.centre = joint - rotate(w.cos_angle, w.sin_angle, node.child_point);
        const double omega = q_dot[node.coordinate[0]];
        if (p != nullptr) {
          const Vec2 d = joint - p->point;
          w.t = {-d.y(), d.x()};
          // The joint's velocity, and S' q' = v_p x (1, 0, 0) q'_relative.
          const Vec2 vj(p->v[1] + p->v[0] * w.t[0], p->v[2] + p->v[0] * w.t[1]);
          const double relative = omega - p->v[0];
          w.v = {omega, vj.x(), vj.y()};
          w.c = {0, relative * vj.y(), -relative * vj.x()};
        } else {
          w.t.setZero();
          w.v = {omega, 0, 0};
          w.c.setZero();
        }
        w.s = {1, 0, 0};
        break;
      }
      case NodeKind::prismatic: {
        const double pc = p != nullptr ? p->cos_angle : 1.0, ps = p != nullptr ? p->sin_angle : 0.0;
        const Vec2 u = rotate(pc, ps, node.axis);
        w.angle = p != nullptr ? p->angle : 0.0;
        w.cos_angle = pc;
        w.sin_angle = ps;
        w.point = joint + node.sign * q[node.coordinate[0]] * u;
        w.centre = w.point - rotate(pc, ps, node.child_point);
        w.s = {0, node.sign * u.x(), node.sign * u.y()};
        const double rate = q_dot[node.coordinate[0]];
        if (p != nullptr) {
          const Vec2 d = w.point - p->point;
          w.t = {-d.y(), d.x()};
          const double omega = p->v[0];
          w.v = {omega, p->v[1] + omega * w.t[0] + w.s[1] * rate, p->v[2] + omega * w.t[1] + w.s[2] * rate};
          w.c = {0, -omega * w.s[2] * rate, omega * w.s[1] * rate};
        } else {
          w.t.setZero();
          w.v = w.s * rate;
          w.c.setZero();
        }
        break;
      }
    }
    // The body's inertia about O, and v x* (I v) written through the centre's velocity
    // v_c: the momentum changes at m (omega x v_c), its moment about O at r x that.
    const Vec2 r = w.centre - w.point;
    const double m = node.mass, omega = w.v[0];
    w.IA = {node.inertia + m * r.squaredNorm(), -m * r.y(), m * r.x(), m, 0, m};
    const Vec2 vc(w.v[1] - omega * r.y(), w.v[2] + omega * r.x());
    const Vec2 turn(-m * omega * vc.y(), m * omega * vc.x());
    w.pA = {r.x() * turn.y() - r.y() * turn.x(), turn.x(), turn.y()};
    if (loads_constant) continue;
    const auto b = static_cast<std::size_t>(node.body);
    load_inputs[first + 3 * b] = w.centre.x();
    load_inputs[first + 3 * b + 1] = w.centre.y();
    load_inputs[first + 3 * b + 2] = w.angle;
    load_inputs[first + 3 * bodies + 3 * b] = vc.x();
    load_inputs[first + 3 * bodies + 3 * b + 1] = vc.y();
    load_inputs[first + 3 * bodies + 3 * b + 2] = omega;
  }
}

void TreeDynamics::Impl::articulate(Eigen::VectorXd& out) const {
  // In a chain a node's parent is the node before it, the next one done: what it gets is
  // carried in registers, not through memory (each step waits on the one before).
  Sym3 carry_IA;
  Vec3 carry_pA = Vec3::Zero();
  bool carried = false;
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const Node& node = nodes[k];
    Work& w = work[k];
    if (carried) {
      w.IA.a00 += carry_IA.a00;
      w.IA.a01 += carry_IA.a01;
      w.IA.a02 += carry_IA.a02;
      w.IA.a11 += carry_IA.a11;
      w.IA.a12 += carry_IA.a12;
      w.IA.a22 += carry_IA.a22;
      w.pA += carry_pA;
    }
    const bool to_next = node.parent >= 0 && static_cast<std::size_t>(node.parent) + 1 == k;
    Work* p = node.parent >= 0 && !to_next ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    Sym3& P = to_next ? carry_IA : p != nullptr ? p->IA : carry_IA;
    Vec3& pP = to_next ? carry_pA : p != nullptr ? p->pA : carry_pA;
    if (to_next) {
      carry_IA = Sym3{};
      carry_pA.setZero();
    }
    carried = to_next;
    const bool has_parent = node.parent >= 0;
    const Sym3& A = w.IA;
    switch (node.kind) {
      case NodeKind::revolute: {
        // S = (1, 0, 0) about the joint: U is I^A's first column (a00, b), D = a00, and
        // I^A - U D^-1 U^T keeps K = A22 - b b^T / a00 alone. Each product that needs
        // no D^-1 is formed while the division runs.
        w.Dinv = 1 / A.a00;
        w.U = {A.a00, A.a01, A.a02};
        w.u[0] = -w.pA[0];
        const double bt = A.a01 * w.t[0] + A.a02 * w.t[1], bc = A.a01 * w.c[1] + A.a02 * w.c[2];
        w.h = w.Dinv * (w.u[0] - bc);
        w.W = {1 + bt * w.Dinv, A.a01 * w.Dinv, A.a02 * w.Dinv};
        if (!has_parent) break;
        const double at0 = A.a11 * w.t[0] + A.a12 * w.t[1], at1 = A.a12 * w.t[0] + A.a22 * w.t[1];
        const double ac0 = A.a11 * w.c[1] + A.a12 * w.c[2], ac1 = A.a12 * w.c[1] + A.a22 * w.c[2];
        const double f1 = w.pA[1] + ac0 + A.a01 * w.h, f2 = w.pA[2] + ac1 + A.a02 * w.h;
        P.a00 += (w.t[0] * at0 + w.t[1] * at1) - bt * bt * w.Dinv;
        P.a01 += at0 - A.a01 * bt * w.Dinv;
        P.a02 += at1 - A.a02 * bt * w.Dinv;
        P.a11 += A.a11 - A.a01 * A.a01 * w.Dinv;
        P.a12 += A.a12 - A.a01 * A.a02 * w.Dinv;
        P.a22 += A.a22 - A.a02 * A.a02 * w.Dinv;
        pP[0] += w.t[0] * f1 + w.t[1] * f2;
        pP[1] += f1;
        pP[2] += f2;
        break;
      }
      case NodeKind::prismatic: {
        w.U = times(A, w.s);
        w.Dinv = 1 / w.s.dot(w.U);
        w.u[0] = -w.s.dot(w.pA);
        if (!has_parent) break;
        const Vec3 g = w.U * w.Dinv;
        const Sym3 Ia{A.a00 - g[0] * w.U[0], A.a01 - g[0] * w.U[1], A.a02 - g[0] * w.U[2],
                      A.a11 - g[1] * w.U[1], A.a12 - g[1] * w.U[2], A.a22 - g[2] * w.U[2]};
        add_shifted(P, Ia, w.t);
        add_shifted(pP, Vec3(w.pA + times(Ia, w.c) + g * w.u[0]), w.t);
        break;
      }
      case NodeKind::floating:
        // A root: its I^A a + p^A = S^-T tau solved in accelerate().
        w.u.setZero();
        if (node.rotates)
          roots[k].full.compute(full(A));
        else
          roots[k].translation_inverse = (Eigen::Matrix2d() << A.a11, A.a12, A.a12, A.a22).finished().inverse();
        break;
    }
  }
  accelerate(true, out);
}

void TreeDynamics::Impl::unloaded(const Eigen::VectorXd& tau_absolute, Eigen::VectorXd& out) const {
  // Generalized forces on the relative coordinates: an absolute angle's force reaches
  // every coordinate it depends on, so a pin's relative angle collects its subtree's.
  std::fill(angle_force.begin(), angle_force.end(), 0.0);
  for (Work& w : work) w.pA.setZero();
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const Node& node = nodes[k];
    Work& w = work[k];
    Work* p = node.parent >= 0 ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    switch (node.kind) {
      case NodeKind::floating:
        if (node.rotates) angle_force[k] += tau_absolute[node.coordinate[2]];
        w.u = {tau_absolute[node.coordinate[0]], tau_absolute[node.coordinate[1]], angle_force[k]};
        continue;  // a root
      case NodeKind::revolute:
        angle_force[k] += tau_absolute[node.coordinate[0]];
        w.u[0] = angle_force[k] - w.pA[0];
        w.h = w.Dinv * w.u[0];
        break;
      case NodeKind::prismatic:
        w.u[0] = tau_absolute[node.coordinate[0]] - w.s.dot(w.pA);
        break;
    }
    if (p == nullptr) continue;
    angle_force[static_cast<std::size_t>(node.parent)] += angle_force[k];
    add_shifted(p->pA, Vec3(w.pA + w.U * (w.Dinv * w.u[0])), w.t);
  }
  accelerate(false, out);
}

void TreeDynamics::Impl::accelerate(bool loaded, Eigen::VectorXd& out) const {
  Vec3 previous = Vec3::Zero();  // the acceleration of node k - 1, in registers
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    Vec3 ap = Vec3::Zero();
    if (node.parent >= 0)
      ap = static_cast<std::size_t>(node.parent) + 1 == k ? previous : work[static_cast<std::size_t>(node.parent)].a;
    const Vec3 c = loaded ? w.c : Vec3::Zero();
    const Vec3 a_in(ap[0], ap[1] + ap[0] * w.t[0] + c[1], ap[2] + ap[0] * w.t[1] + c[2]);
    switch (node.kind) {
      case NodeKind::floating:
        if (node.rotates) {
          // S = 1 about the centre's point: f = (n, Fx, Fy) from tau = (Fx, Fy, n).
          w.a = roots[k].full.solve(Vec3(w.u[2], w.u[0], w.u[1]) - w.pA);
          out[node.coordinate[2]] = w.a[0];
        } else {
          const Eigen::Vector2d qdd =
              roots[k].translation_inverse * Eigen::Vector2d(w.u[0] - w.pA[1], w.u[1] - w.pA[2]);
          w.a = {0, qdd.x(), qdd.y()};
        }
        out[node.coordinate[0]] = w.a[1] - a_in[1];
        out[node.coordinate[1]] = w.a[2] - a_in[2];
        break;
      case NodeKind::revolute: {
        // q''_relative = D^-1 (u - U^T a_in), its parts without the parent's a in h.
        const double relative = w.h - (w.W[0] * ap[0] + w.W[1] * ap[1] + w.W[2] * ap[2]);
        w.a = {ap[0] + relative, a_in[1], a_in[2]};
        out[node.coordinate[0]] = w.a[0];  // the absolute angle's
        break;
      }
      case NodeKind::prismatic: {
        const double qdd = w.Dinv * (w.u[0] - w.U.dot(a_in));
        w.a = a_in + w.s * qdd;
        out[node.coordinate[0]] = qdd;
        break;
      }
    }
    previous = w.a;
  }
}

bool TreeDynamics::accelerations(double t, const Eigen::VectorXd& y, Eigen::VectorXd& q_ddot) const {
  Impl& m = *impl_;
  const auto n = static_cast<Eigen::Index>(m.coordinates);
  q_ddot.resize(n);
  m.kinematics(y);
  const std::size_t bodies = m.work.size(), first = m.parameters.size();
  if (!m.loads_constant) {
    m.load_inputs[first + 6 * bodies] = t;
    m.loads.run(m.load_inputs.data(), m.load_outputs.data(), m.scratch.data());
  }
  // The loads as spatial forces about each body's point: p^A = v x* I v - f.
  for (std::size_t k = 0; k < bodies; ++k) {
    Work& w = m.work[k];
    const Vec2 r = w.centre - w.point;
    const double* f = &m.load_outputs[3 * static_cast<std::size_t>(m.nodes[k].body)];
    w.pA -= Vec3(f[2] + r.x() * f[1] - r.y() * f[0], f[0], f[1]);
  }
  m.articulate(q_ddot);
  if (m.loop_rows == 0) return true;

  for (Eigen::Index i = 0; i < 2 * n; ++i) m.loop_inputs[first + static_cast<std::size_t>(i)] = y[i];
  m.loop_inputs[first + static_cast<std::size_t>(2 * n)] = t;
  m.loops.run(m.loop_inputs.data(), m.loop_outputs.data(), m.scratch.data());
  std::size_t k = 0;
  for (Eigen::Index r = 0; r < m.loop_rows; ++r)
    for (Eigen::Index c = 0; c < n; ++c) m.J(r, c) = m.loop_outputs[k++];
  for (Eigen::Index r = 0; r < m.loop_rows; ++r) m.phi0[r] = m.loop_outputs[k++];
  for (Eigen::Index r = 0; r < m.loop_rows; ++r) {
    m.tau = m.J.row(r).transpose();
    m.unloaded(m.tau, m.column);
    m.MinvJt.col(r) = m.column;
  }
  m.schur.noalias() = m.J * m.MinvJt;
  m.factor.compute(m.schur);
  if (m.factor.info() != Eigen::Success || !(m.factor.rcond() > 1e3 * std::numeric_limits<double>::epsilon()))
    return false;
  m.phi0 += m.J * q_ddot;
  m.lambda = m.factor.solve(-m.phi0);
  q_ddot.noalias() += m.MinvJt * m.lambda;
  return q_ddot.allFinite();
}

}  // namespace linkage::eval
