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

/// Plain vectors for the recursion: GCC builds small Eigen vectors through the stack, and
/// a vector load of two scalars just stored there stalls (store forwarding fails).
struct P2 {
  double x = 0, y = 0;
};
/// A planar spatial vector: motion (omega, vx, vy) or force (n, Fx, Fy).
struct S3 {
  double n = 0, x = 0, y = 0;
};

P2 plain(const Vec2& v) { return {v.x(), v.y()}; }

/// R(angle) v, with cos and sin of the angle given.
P2 rotate(double c, double s, const P2& v) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

enum class NodeKind { floating, revolute, prismatic, fixed, rolling };  // model/joint_types.hpp: JointMotion

/// One body of the tree, in the order the tree reached it (parents first); a pin-slot's
/// two dof are two nodes, the first a massless one of no body (body -1).
struct Node {
  int body = -1;
  int parent = -1;  // node index, -1 for the ground or none
  NodeKind kind = NodeKind::floating;
  bool rotates = true;
  std::array<int, 3> coordinate{-1, -1, -1};  // generalized indices of the dof
  double mass = 0, inertia = 0;
  P2 parent_point;  // in the parent's frame (the world for the ground)
  P2 child_point;   // in the body's frame
  P2 axis;          // slider: unit, parent's frame (the world for the ground); rolling: the line's, its body's frame
  double sign = 1;  // slider: +1 when the body is bodies[1] of its joint; rolling: +1 for the disc, -1 the line's body
  double radius = 0;                            // rolling: the rolling radius
  double held = 0, cos_held = 1, sin_held = 0;  // weld: the angle it holds, child less parent
  bool side_children = false;                   // a child that is not the next node: it adds its I^A and p^A in work[]
};

/// A symmetric 3 x 3 matrix by its upper triangle.
struct Sym3 {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
};

/// Per node, the numbers of one evaluation, spatial ones about the node's own point O.
struct Work {
  P2 centre, point;  // the centre of mass and O, world
  P2 t;              // (-d_y, d_x), d = O - O_parent: motion to O is (w, v + w t), force to O_parent (n + t.F, F)
  double angle = 0, cos_angle = 1, sin_angle = 0;  // each angle's cosine and sine once
  S3 s;                                            // one-dof joints' motion subspace (relative)
  S3 v, c, a;
  Sym3 IA;
  S3 pA, U, u;  // U = I^A s; u: the dof's force less S^T p^A (a floating root's: tau, in x, y, theta)
  double Dinv = 0;
  S3 W;  // pins: q''_absolute = h - W . a_parent (W.n = bt D^-1: the parent's turn cancels)
  double h = 0;
};

/// A floating root's solve: the rotating base's I^A, the point mass's translation block.
struct RootFactor {
  Eigen::LDLT<Mat3> full;
  Eigen::Matrix2d translation_inverse = Eigen::Matrix2d::Zero();
};

/// X^T Ia X into `parent`: Ia = [A b^T; b K] about O moved to O_parent, X = [1 0; t 1].
void add_shifted(Sym3& parent, const Sym3& ia, const P2& t) {
  const double kt0 = ia.a11 * t.x + ia.a12 * t.y, kt1 = ia.a12 * t.x + ia.a22 * t.y;
  parent.a00 += ia.a00 + 2 * (ia.a01 * t.x + ia.a02 * t.y) + t.x * kt0 + t.y * kt1;
  parent.a01 += ia.a01 + kt0;
  parent.a02 += ia.a02 + kt1;
  parent.a11 += ia.a11;
  parent.a12 += ia.a12;
  parent.a22 += ia.a22;
}

/// X^T f into `parent`.
void add_shifted(S3& parent, const S3& f, const P2& t) {
  parent.n += f.n + t.x * f.x + t.y * f.y;
  parent.x += f.x;
  parent.y += f.y;
}

S3 times(const Sym3& m, const S3& v) {
  return {m.a00 * v.n + m.a01 * v.x + m.a02 * v.y, m.a01 * v.n + m.a11 * v.x + m.a12 * v.y,
          m.a02 * v.n + m.a12 * v.x + m.a22 * v.y};
}

double dot(const S3& a, const S3& b) { return a.n * b.n + a.x * b.x + a.y * b.y; }

void add(Sym3& m, const Sym3& d) {
  m.a00 += d.a00;
  m.a01 += d.a01;
  m.a02 += d.a02;
  m.a11 += d.a11;
  m.a12 += d.a12;
  m.a22 += d.a22;
}

Mat3 full(const Sym3& m) {
  Mat3 out;
  out << m.a00, m.a01, m.a02, m.a01, m.a11, m.a12, m.a02, m.a12, m.a22;
  return out;
}

}  // namespace

struct TreeDynamics::Impl {
  std::vector<Node> nodes;
  std::size_t bodies = 0;  // the mechanism's: nodes has one more per pin-slot in the tree
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
  /// The loads on the node's body as a spatial force about O, r = centre - O.
  [[nodiscard]] S3 load_about(const Node& node, const P2& r) const {
    if (node.body < 0) return {};
    const double* f = &load_outputs[3 * static_cast<std::size_t>(node.body)];
    return {f[2] + r.x * f[1] - r.y * f[0], f[0], f[1]};
  }
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

  std::vector<int> node_of(tree.bodies.size(), -1), massless_of(tree.bodies.size(), -1);
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
      n.parent_point = plain(local(parent_body, joint.points[child_is_b ? 0 : 1]));
      n.child_point = plain(local(b, joint.points[child_is_b ? 1 : 0]));
      switch (joint_type_info(joint.type).motion) {
        case JointMotion::revolute:
          n.kind = NodeKind::revolute;
          break;
        case JointMotion::rolling: {  // a one-dof joint turning about the contact point
          const sym::Vec2 axis = sym::joint_axis(system, joint);
          n.kind = NodeKind::rolling;
          n.axis = plain(Vec2(number(axis.x), number(axis.y)).normalized());
          n.sign = child_is_b ? 1.0 : -1.0;
          n.radius = number(sym::joint_radius(system, joint));
          break;
        }
        case JointMotion::slotted: {
          // Two nodes: a massless one of no body takes the first dof, the body the second.
          // Carrying the pin's body: a slider on the slot to the pin, then a pin there.
          // Carrying the slot's: a pin at the pin, then a slider along the turned slot.
          const sym::Vec2 axis = sym::joint_axis(system, joint);
          Node massless;
          massless.parent = n.parent;
          massless.parent_point = n.parent_point;
          massless.kind = child_is_b ? NodeKind::prismatic : NodeKind::revolute;
          massless.axis = plain(Vec2(number(axis.x), number(axis.y)).normalized());
          n.parent = static_cast<int>(m.nodes.size());
          n.parent_point = {};
          n.kind = child_is_b ? NodeKind::revolute : NodeKind::prismatic;
          n.axis = massless.axis;
          n.sign = -1;  // the slot's point A is the pin less s u
          massless_of[static_cast<std::size_t>(b)] = n.parent;
          m.nodes.push_back(massless);
          break;
        }
        case JointMotion::loop:
          throw std::logic_error("TreeDynamics: a loop-only joint in the tree");
        case JointMotion::prismatic: {
          const sym::Vec2 axis = sym::joint_axis(system, joint);
          n.kind = NodeKind::prismatic;
          n.axis = plain(Vec2(number(axis.x), number(axis.y)).normalized());
          n.sign = child_is_b ? 1.0 : -1.0;
          break;
        }
        case JointMotion::fixed: {  // part of its parent's rigid body: no dof of its own
          const double held = (child_is_b ? 1.0 : -1.0) * number(sym::joint_angle(system, joint));
          n.kind = NodeKind::fixed;
          n.held = held;
          n.cos_held = std::cos(held);
          n.sin_held = std::sin(held);
          break;
        }
      }
    }
    node_of[static_cast<std::size_t>(b)] = static_cast<int>(m.nodes.size());
    m.nodes.push_back(n);
  }
  for (std::size_t i = 0; i < system.coordinates().size(); ++i) {
    const Coordinate& c = system.coordinates()[i].coordinate;
    int at = node_of[static_cast<std::size_t>(c.body)];
    // A pin-slot's travel is the slider node's, its angle the pin node's.
    if (const int massless = massless_of[static_cast<std::size_t>(c.body)]; massless >= 0)
      if ((c.kind == CoordinateKind::s) == (m.nodes[static_cast<std::size_t>(massless)].kind == NodeKind::prismatic))
        at = massless;
    Node& n = m.nodes[static_cast<std::size_t>(at)];
    const int slot = c.kind == CoordinateKind::x    ? 0
                     : c.kind == CoordinateKind::y  ? 1
                     : n.kind == NodeKind::floating ? 2
                                                    : 0;
    n.coordinate[static_cast<std::size_t>(slot)] = static_cast<int>(i);
  }
  m.coordinates = system.coordinates().size();
  m.bodies = system.bodies().size();

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
  m.loops.read_state_from(parameter_count, 2 * system.coordinates().size());  // q and q' read from y itself
  m.loop_inputs.assign(loop_inputs.size(), 0.0);
  for (std::size_t i = 0; i < parameter_count; ++i) m.loop_inputs[i] = m.parameters[i];
  m.loop_outputs.resize(jacobian.size());
  m.scratch.resize(std::max(m.loads.scratch_size(), m.loops.scratch_size()));
  for (std::size_t k = 0; k < m.nodes.size(); ++k)
    if (const int p = m.nodes[k].parent; p >= 0 && static_cast<std::size_t>(p) + 1 != k)
      m.nodes[static_cast<std::size_t>(p)].side_children = true;
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
  const std::size_t first = parameters.size();
  // Each angle's cosine and sine first, in a loop of their own: the calls clobber every
  // register, and the recursion below then runs without them.
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    switch (node.kind) {
      case NodeKind::floating:
        w.angle = node.rotates ? q[node.coordinate[2]] : 0.0;
        break;
      case NodeKind::revolute:
      case NodeKind::rolling:
        w.angle = q[node.coordinate[0]];
        break;
      case NodeKind::prismatic:
      case NodeKind::fixed:
        continue;  // from its parent's, set below
    }
    w.cos_angle = std::cos(w.angle);
    w.sin_angle = std::sin(w.angle);
  }
  // A chain's parent is the node before: its position and velocity, on the dependent
  // chain, are taken from the registers, not read back; its angle's cosine and sine were
  // stored before (the loop above, or a slider's or weld's turn a node earlier) and are
  // read back, which keeps three registers free for the rest.
  struct Parent {
    P2 centre, point;
    S3 v;
  } previous;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    const bool has_parent = node.parent >= 0;
    Parent parent;
    double parent_angle = 0, pc = 1, ps = 0;  // the ground's
    if (has_parent) {
      const Work& p = work[static_cast<std::size_t>(node.parent)];
      if (static_cast<std::size_t>(node.parent) + 1 == k)
        parent = previous;
      else
        parent = {p.centre, p.point, p.v};
      parent_angle = p.angle;
      pc = p.cos_angle;
      ps = p.sin_angle;
    }
    const S3 pv = parent.v;
    const P2 pp = parent.point;
    // The joint's point on the parent, world.
    P2 joint = node.parent_point;
    if (has_parent) {
      const P2 r = rotate(pc, ps, node.parent_point);
      joint = {parent.centre.x + r.x, parent.centre.y + r.y};
    }
    // What follows a node's kind, called at the end of each case rather than after the
    // switch: GCC then keeps each case's results in registers, where merging the cases
    // put them on the stack (a store and a reload on the chain of positions).
    const auto finish = [&](const P2& point, const P2& centre, P2 t, const S3& v, const S3& c)
        __attribute__((always_inline)) {
      if (!has_parent) t = {};  // the ground does not move: nothing to pass on
      w.centre = centre;
      w.point = point;
      w.t = t;
      w.v = v;
      w.c = c;
      // The body's own I^A and p^A are formed in articulate(); here only what its other
      // children add in is zeroed.
      if (node.side_children) {
        w.IA = {};
        w.pA = {};
      }
      previous = {centre, point, v};
      if (loads_constant || node.body < 0) return;
      const P2 r{centre.x - point.x, centre.y - point.y};
      const double omega = v.n;
      const P2 vc{v.x - omega * r.y, v.y + omega * r.x};
      const auto b = static_cast<std::size_t>(node.body);
      load_inputs[first + 3 * b] = centre.x;
      load_inputs[first + 3 * b + 1] = centre.y;
      load_inputs[first + 3 * b + 2] = w.angle;
      load_inputs[first + 3 * bodies + 3 * b] = vc.x;
      load_inputs[first + 3 * bodies + 3 * b + 1] = vc.y;
      load_inputs[first + 3 * bodies + 3 * b + 2] = omega;
    };
    P2 point, centre, t;
    S3 v, c;
    switch (node.kind) {
      case NodeKind::floating: {
        centre = {q[node.coordinate[0]], q[node.coordinate[1]]};
        point = centre;
        const double omega = node.rotates ? q_dot[node.coordinate[2]] : 0.0;
        const double vx = q_dot[node.coordinate[0]], vy = q_dot[node.coordinate[1]];
        v = {omega, vx, vy};
        // About the point where the centre is now: S' q' = (0, w y', -w x').
        c = {0, omega * vy, -omega * vx};
        finish(point, centre, t, v, c);
        break;
      }
      case NodeKind::revolute: {
        const P2 r = rotate(w.cos_angle, w.sin_angle, node.child_point);
        point = joint;
        centre = {joint.x - r.x, joint.y - r.y};
        const double omega = q_dot[node.coordinate[0]];
        // The joint's velocity, and S' q' = v_p x (1, 0, 0) q'_relative.
        t = {pp.y - joint.y, joint.x - pp.x};
        const double vx = pv.x + pv.n * t.x, vy = pv.y + pv.n * t.y, relative = omega - pv.n;
        v = {omega, vx, vy};
        c = {0, relative * vy, -relative * vx};
        w.s = {1, 0, 0};
        finish(point, centre, t, v, c);
        break;
      }
      case NodeKind::prismatic: {
        const P2 u = rotate(pc, ps, node.axis), r = rotate(pc, ps, node.child_point);
        w.angle = parent_angle;
        w.cos_angle = pc;
        w.sin_angle = ps;
        const double along = node.sign * q[node.coordinate[0]], rate = q_dot[node.coordinate[0]];
        point = {joint.x + along * u.x, joint.y + along * u.y};
        centre = {point.x - r.x, point.y - r.y};
        const S3 s{0, node.sign * u.x, node.sign * u.y};
        w.s = s;
        t = {pp.y - point.y, point.x - pp.x};
        v = {pv.n, pv.x + pv.n * t.x + s.x * rate, pv.y + pv.n * t.y + s.y * rate};
        c = {0, -pv.n * s.y * rate, pv.n * s.x * rate};
        finish(point, centre, t, v, c);
        break;
      }
      case NodeKind::fixed: {
        // Its parent's motion carried to the joint, turned by the angle it holds.
        w.angle = parent_angle + node.held;
        w.cos_angle = pc * node.cos_held - ps * node.sin_held;
        w.sin_angle = ps * node.cos_held + pc * node.sin_held;
        const P2 r = rotate(w.cos_angle, w.sin_angle, node.child_point);
        point = joint;
        centre = {joint.x - r.x, joint.y - r.y};
        t = {pp.y - joint.y, joint.x - pp.x};
        v = {pv.n, pv.x + pv.n * t.x, pv.y + pv.n * t.y};
        w.s = {};
        finish(point, centre, t, v, c);
        break;
      }
      case NodeKind::rolling: {
        // The relative motion is a turn about the contact point K: S = (1, k x (O - K))
        // about the node's point O, and S' q' = (0, -k x K') q'_relative with K' the
        // contact point's own velocity, K = C - R n, n = k x u turning with the line.
        const double omega = q_dot[node.coordinate[0]], relative = omega - pv.n, radius = node.radius;
        const bool disc = node.sign > 0;
        const double line_cos = disc ? pc : w.cos_angle, line_sin = disc ? ps : w.sin_angle;
        const P2 u = rotate(line_cos, line_sin, node.axis), normal{-u.y, u.x};
        const double turned = disc ? w.angle - parent_angle : parent_angle - w.angle;  // th_disc - th_line
        P2 away;                                                                       // O - K
        if (disc) {  // O = C = O_line + R n - R turned u, on the line's parent
          point = {joint.x + radius * (normal.x - turned * u.x), joint.y + radius * (normal.y - turned * u.y)};
          away = {radius * normal.x, radius * normal.y};
        } else {  // O = the line's point, C - R n + R turned u, under the parent's disc
          point = {joint.x + radius * (turned * u.x - normal.x), joint.y + radius * (turned * u.y - normal.y)};
          away = {radius * turned * u.x, radius * turned * u.y};
        }
        const P2 r = rotate(w.cos_angle, w.sin_angle, node.child_point);
        centre = {point.x - r.x, point.y - r.y};
        const S3 s{1, -away.y, away.x};
        w.s = s;
        t = {pp.y - point.y, point.x - pp.x};
        v = {omega, pv.x + pv.n * t.x + s.x * relative, pv.y + pv.n * t.y + s.y * relative};
        // The disc's centre's velocity, and the line's rate.
        const P2 centre_rate = disc ? P2{v.x, v.y} : P2{pv.x + pv.n * (pp.y - joint.y), pv.y + pv.n * (joint.x - pp.x)};
        const double line_rate = disc ? pv.n : omega;
        const P2 contact_rate{centre_rate.x + radius * line_rate * u.x, centre_rate.y + radius * line_rate * u.y};
        c = {0, relative * contact_rate.y, -relative * contact_rate.x};
        finish(point, centre, t, v, c);
        break;
      }
    }
  }
}

void TreeDynamics::Impl::articulate(Eigen::VectorXd& out) const {
  // In a chain a node's parent is the node before it, the next one done: what it gets is
  // carried in registers, not through memory (each step waits on the one before).
  Sym3 carry_IA;
  S3 carry_pA;
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const Node& node = nodes[k];
    Work& w = work[k];
    // The body's inertia about O, and v x* (I v) - f written through the centre's
    // velocity v_c: the momentum changes at m (omega x v_c), its moment about O at r x
    // that. Formed here, not in kinematics(): this pass waits on each link's division
    // and has room for them.
    const P2 r{w.centre.x - w.point.x, w.centre.y - w.point.y};
    const double m = node.mass, omega = w.v.n;
    const P2 vc{w.v.x - omega * r.y, w.v.y + omega * r.x};
    const P2 turn{-m * omega * vc.y, m * omega * vc.x};
    const S3 f = load_about(node, r);
    Sym3 A{node.inertia + m * (r.x * r.x + r.y * r.y), -m * r.y, m * r.x, m, 0, m};
    S3 pA{(r.x * turn.y - r.y * turn.x) - f.n, turn.x - f.x, turn.y - f.y};
    if (node.side_children) {
      add(A, w.IA);
      pA = {pA.n + w.pA.n, pA.x + w.pA.x, pA.y + w.pA.y};
    }
    add(A, carry_IA);
    pA = {pA.n + carry_pA.n, pA.x + carry_pA.x, pA.y + carry_pA.y};
    const P2 t = w.t;
    const S3 c = w.c;
    const bool to_next = node.parent >= 0 && static_cast<std::size_t>(node.parent) + 1 == k;
    Sym3 to_IA;  // what the parent gets
    S3 to_pA;
    // Called at the end of each case, not after the switch: merging the cases had GCC
    // carry p^A through the stack, a store and a reload on a chain's dependent path.
    const auto pass_on = [&]() __attribute__((always_inline)) {
      carry_IA = {};
      carry_pA = {};
      if (to_next) {
        carry_IA = to_IA;
        carry_pA = to_pA;
      } else if (node.parent >= 0) {
        Work& p = work[static_cast<std::size_t>(node.parent)];
        add(p.IA, to_IA);
        add_shifted(p.pA, to_pA, P2{});
      }
    };
    switch (node.kind) {
      case NodeKind::revolute: {
        // S = (1, 0, 0) about the joint: U is I^A's first column (a00, b), D = a00, and
        // I^A - U D^-1 U^T keeps K = A22 - b b^T / a00 alone. Each product that needs
        // no D^-1 is formed while the division runs.
        const double Dinv = 1 / A.a00, u = -pA.n;
        const double bt = A.a01 * t.x + A.a02 * t.y, bc = A.a01 * c.x + A.a02 * c.y;
        const double h = Dinv * (u - bc);
        w.Dinv = Dinv;
        w.U = {A.a00, A.a01, A.a02};
        w.u.n = u;
        w.h = h;
        w.W = {bt * Dinv, A.a01 * Dinv, A.a02 * Dinv};
        const double at0 = A.a11 * t.x + A.a12 * t.y, at1 = A.a12 * t.x + A.a22 * t.y;
        const double ac0 = A.a11 * c.x + A.a12 * c.y, ac1 = A.a12 * c.x + A.a22 * c.y;
        const double f1 = pA.x + ac0 + A.a01 * h, f2 = pA.y + ac1 + A.a02 * h;
        to_IA = {(t.x * at0 + t.y * at1) - bt * bt * Dinv,
                 at0 - A.a01 * bt * Dinv,
                 at1 - A.a02 * bt * Dinv,
                 A.a11 - A.a01 * A.a01 * Dinv,
                 A.a12 - A.a01 * A.a02 * Dinv,
                 A.a22 - A.a02 * A.a02 * Dinv};
        to_pA = {t.x * f1 + t.y * f2, f1, f2};
        pass_on();
        break;
      }
      case NodeKind::prismatic:
      case NodeKind::rolling: {
        const S3 s = w.s, U = times(A, s);
        const double Dinv = 1 / dot(s, U), u = -dot(s, pA);
        w.U = U;
        w.Dinv = Dinv;
        w.u.n = u;
        const S3 g{U.n * Dinv, U.x * Dinv, U.y * Dinv};
        const Sym3 Ia{A.a00 - g.n * U.n, A.a01 - g.n * U.x, A.a02 - g.n * U.y,
                      A.a11 - g.x * U.x, A.a12 - g.x * U.y, A.a22 - g.y * U.y};
        const S3 Iac = times(Ia, c);
        add_shifted(to_IA, Ia, t);
        add_shifted(to_pA, S3{pA.n + Iac.n + g.n * u, pA.x + Iac.x + g.x * u, pA.y + Iac.y + g.y * u}, t);
        pass_on();
        break;
      }
      case NodeKind::fixed:
        // Its inertia and loads are its parent's, moved to the parent's point.
        w.U = {};
        w.Dinv = 0;
        w.u = {};
        add_shifted(to_IA, A, t);
        add_shifted(to_pA, pA, t);
        pass_on();
        break;
      case NodeKind::floating:
        // A root: its I^A a + p^A = S^-T tau solved in accelerate().
        w.u = {};
        w.pA = pA;
        if (node.rotates)
          roots[k].full.compute(full(A));
        else
          roots[k].translation_inverse = (Eigen::Matrix2d() << A.a11, A.a12, A.a12, A.a22).finished().inverse();
        pass_on();
        break;
    }
  }
  accelerate(true, out);
}

void TreeDynamics::Impl::unloaded(const Eigen::VectorXd& tau_absolute, Eigen::VectorXd& out) const {
  // Generalized forces on the relative coordinates: an absolute angle's force reaches
  // every coordinate it depends on, so a pin's relative angle collects its subtree's.
  std::fill(angle_force.begin(), angle_force.end(), 0.0);
  for (Work& w : work) w.pA = {};
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const Node& node = nodes[k];
    Work& w = work[k];
    switch (node.kind) {
      case NodeKind::floating:
        if (node.rotates) angle_force[k] += tau_absolute[node.coordinate[2]];
        w.u = {tau_absolute[node.coordinate[0]], tau_absolute[node.coordinate[1]], angle_force[k]};
        continue;  // a root
      case NodeKind::revolute:
        angle_force[k] += tau_absolute[node.coordinate[0]];
        w.u.n = angle_force[k] - w.pA.n;
        w.h = w.Dinv * w.u.n;
        break;
      case NodeKind::prismatic:
        w.u.n = tau_absolute[node.coordinate[0]] - dot(w.s, w.pA);
        break;
      case NodeKind::rolling:  // an absolute angle, as a pin's
        angle_force[k] += tau_absolute[node.coordinate[0]];
        w.u.n = angle_force[k] - dot(w.s, w.pA);
        break;
      case NodeKind::fixed:  // no coordinate: its subtree's forces pass to its parent whole
        break;
    }
    if (node.parent < 0) continue;
    angle_force[static_cast<std::size_t>(node.parent)] += angle_force[k];
    const double g = w.Dinv * w.u.n;
    add_shifted(work[static_cast<std::size_t>(node.parent)].pA,
                S3{w.pA.n + w.U.n * g, w.pA.x + w.U.x * g, w.pA.y + w.U.y * g}, w.t);
  }
  accelerate(false, out);
}

void TreeDynamics::Impl::accelerate(bool loaded, Eigen::VectorXd& out) const {
  S3 previous;  // the acceleration of node k - 1, in registers
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    S3 ap;
    if (node.parent >= 0)
      ap = static_cast<std::size_t>(node.parent) + 1 == k ? previous : work[static_cast<std::size_t>(node.parent)].a;
    const S3 c = loaded ? w.c : S3{};
    const P2 t = w.t;
    const S3 a_in{ap.n, ap.x + ap.n * t.x + c.x, ap.y + ap.n * t.y + c.y};
    S3 a;
    switch (node.kind) {
      case NodeKind::floating:
        if (node.rotates) {
          // S = 1 about the centre's point: f = (n, Fx, Fy) from tau = (Fx, Fy, n).
          const Vec3 solved = roots[k].full.solve(Vec3(w.u.y - w.pA.n, w.u.n - w.pA.x, w.u.x - w.pA.y));
          a = {solved[0], solved[1], solved[2]};
          out[node.coordinate[2]] = a.n;
        } else {
          const Eigen::Vector2d qdd = roots[k].translation_inverse * Eigen::Vector2d(w.u.n - w.pA.x, w.u.x - w.pA.y);
          a = {0, qdd.x(), qdd.y()};
        }
        out[node.coordinate[0]] = a.x - a_in.x;
        out[node.coordinate[1]] = a.y - a_in.y;
        break;
      case NodeKind::revolute:
        // q''_relative = D^-1 (u - U^T a_in), its parts without the parent's a in h; the
        // absolute angle's h - W . a_parent. In a chain ap.n is the last link's result and
        // ap.x, ap.y came a link earlier: one product and one difference wait for it.
        a = {(w.h - (w.W.x * ap.x + w.W.y * ap.y)) - w.W.n * ap.n, a_in.x, a_in.y};
        out[node.coordinate[0]] = a.n;  // the absolute angle's
        break;
      case NodeKind::prismatic: {
        const double qdd = w.Dinv * (w.u.n - dot(w.U, a_in));
        a = {a_in.n + w.s.n * qdd, a_in.x + w.s.x * qdd, a_in.y + w.s.y * qdd};
        out[node.coordinate[0]] = qdd;
        break;
      }
      case NodeKind::rolling: {
        const double qdd = w.Dinv * (w.u.n - dot(w.U, a_in));  // relative
        a = {a_in.n + qdd, a_in.x + w.s.x * qdd, a_in.y + w.s.y * qdd};
        out[node.coordinate[0]] = a.n;  // the absolute angle's
        break;
      }
      case NodeKind::fixed:
        a = a_in;
        break;
    }
    w.a = a;
    previous = a;
  }
}

bool TreeDynamics::accelerations(double t, const Eigen::VectorXd& y, Eigen::VectorXd& q_ddot) const {
  Impl& m = *impl_;
  const auto n = static_cast<Eigen::Index>(m.coordinates);
  q_ddot.resize(n);
  m.kinematics(y);
  const std::size_t first = m.parameters.size();
  if (!m.loads_constant) {
    m.load_inputs[first + 6 * m.bodies] = t;
    m.loads.run(m.load_inputs.data(), m.load_outputs.data(), m.scratch.data());
  }
  m.articulate(q_ddot);
  if (m.loop_rows == 0) return true;

  m.loop_inputs[first + static_cast<std::size_t>(2 * n)] = t;
  m.loops.run(m.loop_inputs.data(), y.data(), m.loop_outputs.data(), m.scratch.data());
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
