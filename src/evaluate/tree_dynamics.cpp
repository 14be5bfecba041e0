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

/// Per node, the numbers of one pass.
struct Work {
  Vec2 centre = Vec2::Zero();
  double angle = 0, cos_angle = 1, sin_angle = 0;                       // each angle's cosine and sine once
  Eigen::Matrix<double, 3, 3> S = Eigen::Matrix<double, 3, 3>::Zero();  // first dof columns used
  Vec3 v = Vec3::Zero(), c = Vec3::Zero(), a = Vec3::Zero();
  Mat3 I0 = Mat3::Zero();                         // the body's own spatial inertia
  Vec3 bias = Vec3::Zero(), load = Vec3::Zero();  // v x* I v, and the loads, as spatial forces
  Mat3 IA = Mat3::Zero();
  Vec3 pA = Vec3::Zero();
  Eigen::Matrix<double, 3, 3> U = Eigen::Matrix<double, 3, 3>::Zero();
  Mat3 Dinv = Mat3::Zero();
  Vec3 u = Vec3::Zero();
  Vec3 q_dot = Vec3::Zero(), q_ddot = Vec3::Zero();  // relative, first dof entries
  double omega = 0, alpha = 0;                       // absolute angular velocity and acceleration
};

/// R(angle) v, with cos and sin of the angle given.
Vec2 rotate(double c, double s, const Vec2& v) { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }

/// v x* u for planar motion vectors.
Vec3 cross_motion(const Vec3& v, const Vec3& u) { return {0, -v[0] * u[2] + v[2] * u[0], v[0] * u[1] - v[1] * u[0]}; }

Mat3 spatial_inertia(double m, double I, const Vec2& c) {
  Mat3 out;
  out << I + m * c.squaredNorm(), -m * c.y(), m * c.x(), -m * c.y(), m, 0, m * c.x(), 0, m;
  return out;
}

}  // namespace

namespace {

/// The leaves-to-root step of a node with D > 1 degrees of freedom (a floating base),
/// in fixed-size matrices.
template <int D>
void backward(Work& w, Work* p, const Vec3& c) {
  const Eigen::Matrix<double, 3, D> S = w.S.leftCols<D>();
  const Eigen::Matrix<double, 3, D> U = w.IA * S;
  w.U.leftCols<D>() = U;
  const Eigen::Matrix<double, D, D> Dinv = (S.transpose() * U).inverse();
  w.Dinv.topLeftCorner<D, D>() = Dinv;
  w.u.head<D>() -= S.transpose() * w.pA;
  if (p == nullptr) return;
  const Mat3 Ia = w.IA - U * Dinv * U.transpose();
  p->IA += Ia;
  p->pA += w.pA + Ia * c + U * (Dinv * w.u.head<D>());
}

/// The root-to-leaves step of such a node.
template <int D>
void forward(Work& w, const Vec3& a_in) {
  const Eigen::Matrix<double, D, D> Dinv = w.Dinv.topLeftCorner<D, D>();
  w.q_ddot.head<D>() = Dinv * (w.u.head<D>() - w.U.leftCols<D>().transpose() * a_in);
  w.a = a_in + w.S.leftCols<D>() * w.q_ddot.head<D>();
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
  mutable std::vector<Work> work;
  mutable Vec2 origin = Vec2::Zero();  // of the spatial quantities, world
  mutable std::vector<double> angle_force;
  mutable std::vector<double> load_inputs, load_outputs, loop_inputs, loop_outputs, scratch;
  mutable Eigen::MatrixXd J, MinvJt;
  mutable Eigen::VectorXd q_ddot0, tau, column;

  /// Positions and velocities root to leaves from y = (q, q').
  void kinematics(const Eigen::VectorXd& y) const;
  /// Articulated inertias and biases leaves to root, accelerations root to leaves; with
  /// `loaded` false: no velocity terms and no loads (q'' = M^-1 tau).
  void recursion(bool loaded, const Eigen::VectorXd& tau_absolute, Eigen::VectorXd& out) const;
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
  m.angle_force.resize(m.nodes.size());
  const auto n = static_cast<Eigen::Index>(m.coordinates);
  m.J.resize(m.loop_rows, n);
  m.MinvJt.resize(n, m.loop_rows);
  m.q_ddot0.resize(n);
  m.tau.resize(n);
  m.column.resize(n);
}

TreeDynamics::~TreeDynamics() = default;
TreeDynamics::TreeDynamics(TreeDynamics&&) noexcept = default;
TreeDynamics& TreeDynamics::operator=(TreeDynamics&&) noexcept = default;

void TreeDynamics::Impl::kinematics(const Eigen::VectorXd& y) const {
  const auto n = static_cast<Eigen::Index>(coordinates);
  auto q = [&](int i) { return y[i]; };
  auto q_dot = [&](int i) { return y[n + i]; };
  // Spatial quantities about a point near the mechanism, not the world origin: about a
  // far origin I + m |c|^2 would swamp I and cost digits.
  origin = nodes.front().kind == NodeKind::floating
               ? Vec2(q(nodes.front().coordinate[0]), q(nodes.front().coordinate[1]))
               : Vec2::Zero();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    const Work* p = node.parent >= 0 ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    const double parent_angle = p != nullptr ? p->angle : 0.0;
    const double pc = p != nullptr ? p->cos_angle : 1.0, ps = p != nullptr ? p->sin_angle : 0.0;
    const double parent_omega = p != nullptr ? p->omega : 0.0;
    const Vec3 parent_v = p != nullptr ? p->v : Vec3::Zero();
    const Vec2 parent_point = p != nullptr ? Vec2(p->centre + rotate(pc, ps, node.parent_point)) : node.parent_point;
    switch (node.kind) {
      case NodeKind::floating: {
        w.S.setZero();
        w.c.setZero();
        w.centre = {q(node.coordinate[0]), q(node.coordinate[1])};
        w.angle = node.rotates ? q(node.coordinate[2]) : 0.0;
        w.cos_angle = std::cos(w.angle);
        w.sin_angle = std::sin(w.angle);
        w.q_dot[0] = q_dot(node.coordinate[0]);
        w.q_dot[1] = q_dot(node.coordinate[1]);
        w.q_dot[2] = node.rotates ? q_dot(node.coordinate[2]) : 0.0;
        w.S(1, 0) = 1;
        w.S(2, 1) = 1;
        if (node.rotates) {
          const Vec2 r = w.centre - origin;
          w.S.col(2) << 1, r.y(), -r.x();
          w.c << 0, w.q_dot[2] * w.q_dot[1], -w.q_dot[2] * w.q_dot[0];
        }
        w.v = w.S.leftCols(node.dof) * w.q_dot.head(node.dof);
        w.omega = w.q_dot[2];
        break;
      }
      case NodeKind::revolute: {
        w.angle = q(node.coordinate[0]);
        w.omega = q_dot(node.coordinate[0]);
        w.q_dot[0] = w.omega - parent_omega;
        w.cos_angle = std::cos(w.angle);
        w.sin_angle = std::sin(w.angle);
        w.centre = parent_point - rotate(w.cos_angle, w.sin_angle, node.child_point);
        const Vec2 r = parent_point - origin;
        w.S.col(0) << 1, r.y(), -r.x();
        w.v = parent_v + w.S.col(0) * w.q_dot[0];
        w.c = cross_motion(parent_v, w.S.col(0)) * w.q_dot[0];
        break;
      }
      case NodeKind::prismatic: {
        const Vec2 u = rotate(pc, ps, node.axis);
        w.angle = parent_angle;
        w.cos_angle = pc;
        w.sin_angle = ps;
        w.omega = parent_omega;
        w.q_dot[0] = q_dot(node.coordinate[0]);
        w.centre = parent_point + node.sign * q(node.coordinate[0]) * u - rotate(pc, ps, node.child_point);
        w.S.col(0) << 0, node.sign * u.x(), node.sign * u.y();
        w.v = parent_v + w.S.col(0) * w.q_dot[0];
        w.c = cross_motion(parent_v, w.S.col(0)) * w.q_dot[0];
        break;
      }
    }
  }
}

void TreeDynamics::Impl::recursion(bool loaded, const Eigen::VectorXd& tau_absolute, Eigen::VectorXd& out) const {
  // Generalized forces on the relative coordinates: an absolute angle's force reaches
  // every coordinate it depends on, so a pin's relative angle collects its subtree's.
  // The motion itself has none (the loads act on the bodies).
  if (loaded) {
    for (Work& w : work) w.u.setZero();
  } else {
    std::fill(angle_force.begin(), angle_force.end(), 0.0);
    for (std::size_t k = nodes.size(); k-- > 0;) {
      const Node& node = nodes[k];
      Work& w = work[k];
      double own = 0;
      switch (node.kind) {
        case NodeKind::floating:
          if (node.rotates) own = tau_absolute[node.coordinate[2]];
          break;
        case NodeKind::revolute:
          own = tau_absolute[node.coordinate[0]];
          break;
        case NodeKind::prismatic:
          break;
      }
      angle_force[k] += own;
      if (node.parent >= 0 && node.kind != NodeKind::floating)
        angle_force[static_cast<std::size_t>(node.parent)] += angle_force[k];
      w.u.setZero();
      switch (node.kind) {
        case NodeKind::floating:
          w.u[0] = tau_absolute[node.coordinate[0]];
          w.u[1] = tau_absolute[node.coordinate[1]];
          w.u[2] = angle_force[k];
          break;
        case NodeKind::revolute:
          w.u[0] = angle_force[k];
          break;
        case NodeKind::prismatic:
          w.u[0] = tau_absolute[node.coordinate[0]];
          break;
      }
    }
  }
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    Work& w = work[k];
    w.IA = w.I0;
    if (loaded)
      w.pA = w.bias - w.load;
    else
      w.pA.setZero();
  }
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const Node& node = nodes[k];
    Work& w = work[k];
    const Vec3 c = loaded ? w.c : Vec3::Zero();
    Work* p = node.parent >= 0 ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    if (node.dof == 1) {  // pins and sliders: scalars, no matrix to invert
      const Vec3 s = w.S.col(0);
      w.U.col(0) = w.IA * s;
      const double D = s.dot(w.U.col(0));
      w.Dinv(0, 0) = 1 / D;
      w.u[0] -= s.dot(w.pA);
      if (p == nullptr) continue;
      const Vec3 U = w.U.col(0);
      const Mat3 Ia = w.IA - (U / D) * U.transpose();
      p->IA += Ia;
      p->pA += w.pA + Ia * c + U * (w.u[0] / D);
      continue;
    }
    if (node.dof == 3) {
      // A rotating floating base is a root: I^A a + p^A = f, with S^T f = tau; no D to
      // form, one symmetric 3 x 3 solve (its forward step below).
      const Vec2 r = w.centre - origin;
      const Vec3 f(w.u[2] - r.y() * w.u[0] + r.x() * w.u[1], w.u[0], w.u[1]);
      w.a = w.IA.ldlt().solve(f - w.pA);
    } else {
      backward<2>(w, p, c);
    }
  }
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& node = nodes[k];
    Work& w = work[k];
    const int d = node.dof;
    const Work* p = node.parent >= 0 ? &work[static_cast<std::size_t>(node.parent)] : nullptr;
    const Vec3 a_in = (p != nullptr ? p->a : Vec3::Zero()) + (loaded ? w.c : Vec3::Zero());
    if (d == 1) {
      w.q_ddot[0] = w.Dinv(0, 0) * (w.u[0] - w.U.col(0).dot(a_in));
      w.a = a_in + w.S.col(0) * w.q_ddot[0];
    } else if (d == 3) {
      // q'' = S^-1 (a - c): S q'' = (theta'', x'' + r_y theta'', y'' - r_x theta'').
      const Vec2 r = w.centre - origin;
      const Vec3 e = w.a - a_in;
      w.q_ddot << e[1] - r.y() * e[0], e[2] + r.x() * e[0], e[0];
    } else {
      forward<2>(w, a_in);
    }
    const double parent_alpha = p != nullptr ? p->alpha : 0.0;
    switch (node.kind) {
      case NodeKind::floating:
        out[node.coordinate[0]] = w.q_ddot[0];
        out[node.coordinate[1]] = w.q_ddot[1];
        w.alpha = node.rotates ? w.q_ddot[2] : 0.0;
        if (node.rotates) out[node.coordinate[2]] = w.alpha;
        break;
      case NodeKind::revolute:
        w.alpha = parent_alpha + w.q_ddot[0];
        out[node.coordinate[0]] = w.alpha;
        break;
      case NodeKind::prismatic:
        w.alpha = parent_alpha;
        out[node.coordinate[0]] = w.q_ddot[0];
        break;
    }
  }
}

bool TreeDynamics::accelerations(double t, const Eigen::VectorXd& y, Eigen::VectorXd& q_ddot) const {
  Impl& m = *impl_;
  const auto n = static_cast<Eigen::Index>(m.coordinates);
  q_ddot.resize(n);
  m.kinematics(y);
  // The loads at every body's maximal coordinates and rates.
  const std::size_t bodies = m.work.size(), first = m.parameters.size();
  for (std::size_t k = 0; k < bodies && !m.loads_constant; ++k) {
    const Work& w = m.work[k];
    const auto b = static_cast<std::size_t>(m.nodes[k].body);
    m.load_inputs[first + 3 * b] = w.centre.x();
    m.load_inputs[first + 3 * b + 1] = w.centre.y();
    m.load_inputs[first + 3 * b + 2] = w.angle;
    // The centre's velocity from the spatial velocity about the origin.
    const Vec2 r = w.centre - m.origin;
    m.load_inputs[first + 3 * bodies + 3 * b] = w.v[1] - w.v[0] * r.y();
    m.load_inputs[first + 3 * bodies + 3 * b + 1] = w.v[2] + w.v[0] * r.x();
    m.load_inputs[first + 3 * bodies + 3 * b + 2] = w.omega;
  }
  if (!m.loads_constant) {
    m.load_inputs[first + 6 * bodies] = t;
    m.loads.run(m.load_inputs.data(), m.load_outputs.data(), m.scratch.data());
  }
  // Each body's spatial inertia, velocity-product force and load about the origin, once:
  // the loop-closure passes reuse the inertias.
  for (std::size_t k = 0; k < bodies; ++k) {
    const Node& node = m.nodes[k];
    Work& w = m.work[k];
    const Vec2 r = w.centre - m.origin;
    w.I0 = spatial_inertia(node.mass, node.inertia, r);
    // v x* (I v) written through the centre's velocity v_c: the body's momentum changes
    // at m (omega x v_c), its moment about the origin at r x that, so a body about its
    // own centre (r = 0) gets exactly no moment, as Case 2's rows give it.
    const double omega = w.v[0];
    const Vec2 vc(w.v[1] - omega * r.y(), w.v[2] + omega * r.x());
    const Vec2 turn(-omega * vc.y(), omega * vc.x());
    w.bias = Vec3(node.mass * (r.x() * turn.y() - r.y() * turn.x()), node.mass * turn.x(), node.mass * turn.y());
    const double* f = &m.load_outputs[3 * static_cast<std::size_t>(node.body)];
    w.load = Vec3(f[2] + r.x() * f[1] - r.y() * f[0], f[0], f[1]);
  }
  m.tau.setZero();
  m.recursion(true, m.tau, q_ddot);
  if (m.loop_rows == 0) return true;

  for (Eigen::Index i = 0; i < 2 * n; ++i) m.loop_inputs[first + static_cast<std::size_t>(i)] = y[i];
  m.loop_inputs[first + static_cast<std::size_t>(2 * n)] = t;
  m.loops.run(m.loop_inputs.data(), m.loop_outputs.data(), m.scratch.data());
  std::size_t k = 0;
  for (Eigen::Index r = 0; r < m.loop_rows; ++r)
    for (Eigen::Index c = 0; c < n; ++c) m.J(r, c) = m.loop_outputs[k++];
  Eigen::VectorXd phi0(m.loop_rows);
  for (Eigen::Index r = 0; r < m.loop_rows; ++r) phi0[r] = m.loop_outputs[k++];
  for (Eigen::Index r = 0; r < m.loop_rows; ++r) {
    m.tau = m.J.row(r).transpose();
    m.recursion(false, m.tau, m.column);
    m.MinvJt.col(r) = m.column;
  }
  const Eigen::MatrixXd schur = m.J * m.MinvJt;
  const Eigen::LDLT<Eigen::MatrixXd> factor(schur);
  if (factor.info() != Eigen::Success || !(factor.rcond() > 1e3 * std::numeric_limits<double>::epsilon())) return false;
  const Eigen::VectorXd lambda = factor.solve(-phi0 - m.J * q_ddot);
  q_ddot += m.MinvJt * lambda;
  return q_ddot.allFinite();
}

}  // namespace linkage::eval
