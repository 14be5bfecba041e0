#include "integrate/kinematic_path.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"

namespace linkage {

namespace {

// Gauss-Legendre points per quadrature interval: exact for the power's Taylor polynomial
// of degree 15, so halving an output interval shrinks the error 2^16-fold.
constexpr int kGaussPoints = 8;
// Halvings of an interval before the quadrature takes what it has.
constexpr int kQuadratureDepth = 10;
// The largest Newton correction of a continuation step, relative to the coordinates' scale.
constexpr double kLargestCorrection = 1e-3;
// A continuation step shorter than this fraction of the time reached is not taken: the
// mechanism cannot go on there.
constexpr double kShortestStep = 1e-10;
// J's smallest over largest singular value below sqrt(eps): at a fold of C(q, t) = 0 a
// residual of round-off moves q by its square root, so q is no longer fixed to the
// digits the columns promise; the mechanism is at a toggle or limit position.
const double kSingularSpread = std::sqrt(std::numeric_limits<double>::epsilon());
// Two links are in line when the sine of the angle between their lines is below this.
constexpr double kInLine = 1e-2;

/// links_in_line() at the pose of (t, y).
std::string links_in_line_at(const sym::System& system, const eval::MechanismDynamics& dynamics, double t,
                             const Eigen::VectorXd& y) {
  eval::MechanismSample s;
  dynamics.sample(t, y, s);
  return links_in_line(system, s.pose);
}

}  // namespace

KinematicPath::KinematicPath(const sym::System& system, const eval::MechanismDynamics& dynamics, Eigen::VectorXd& y)
    : system_(&system), dynamics_(&dynamics) {
  // Golub-Welsch: the nodes are the eigenvalues of Legendre's Jacobi matrix, the weights
  // 2 v_0^2 of its unit eigenvectors.
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(kGaussPoints, kGaussPoints);
  for (int k = 1; k < kGaussPoints; ++k) jacobi(k - 1, k) = jacobi(k, k - 1) = k / std::sqrt(4.0 * k * k - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> legendre(jacobi);
  for (int k = 0; k < kGaussPoints; ++k) {
    nodes_.push_back(legendre.eigenvalues()[k]);
    weights_.push_back(2 * legendre.eigenvectors()(0, k) * legendre.eigenvectors()(0, k));
  }
  if (!dynamics.close_positions(0, y)) stop(0, "cannot close at the start");
  dynamics.solve_rates(0, y);
  if (dynamics.jacobian_spread(0, y) < kSingularSpread)
    stop(0, "is at a toggle or limit position at the start (" + in_line(0, y) + ")");
  sign_ = dynamics.jacobian_sign(0, y);
  y[y.size() - 1] = 0;
  dy_ = derivative(0, y);
}

Eigen::VectorXd KinematicPath::derivative(double t, const Eigen::VectorXd& y) const {
  Eigen::VectorXd dydt;
  if (!dynamics_->derivative(t, y, dydt))
    stop(t, "reached a dead point (the case's matrix is singular: the driver cannot move it)");
  return dydt;
}

bool KinematicPath::solve_at(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& a0, double t,
                             Eigen::VectorXd& y) {
  const auto n = static_cast<Eigen::Index>(dynamics_->coordinates());
  const double h = t - t0;
  y = y0;
  y.head(n) += h * y0.segment(n, n) + 0.5 * h * h * a0.segment(n, n);
  const Eigen::VectorXd predicted = y.head(n);
  ++solves_;
  if (!dynamics_->close_positions(t, y)) return false;
  // On the branch the predictor errs by O(h^3) against a motion of O(h): a correction of a
  // quarter of the motion is another branch (halving h shrinks a true step's ratio 4-fold).
  // Nor more than a thousandth of the coordinates' scale, far below the distance between two
  // assemblies of the same links, so a long step cannot land on the other one.
  const double scale = 1 + y.head(n).cwiseAbs().maxCoeff();
  const double motion = (predicted - y0.head(n)).cwiseAbs().maxCoeff();
  const double correction = (y.head(n) - predicted).cwiseAbs().maxCoeff();
  if (correction > std::min(0.25 * motion, kLargestCorrection * scale) + 1e-12 * scale) return false;
  dynamics_->solve_rates(t, y);
  return true;
}

bool KinematicPath::solve_between(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb, double t,
                                  Eigen::VectorXd& y) {
  // Predicted by the cubic through q and q' at both ends of an accepted step: within it the
  // branch is the one they are on, so a correction of a quarter of the step's motion is not.
  const auto n = static_cast<Eigen::Index>(dynamics_->coordinates());
  const double h = b - a, s = (t - a) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s), h01 = s * s * (3 - 2 * s),
               h11 = s * s * (s - 1);
  y = ya;
  y.head(n) = h00 * ya.head(n) + h10 * h * ya.segment(n, n) + h01 * yb.head(n) + h11 * h * yb.segment(n, n);
  const Eigen::VectorXd predicted = y.head(n);
  ++solves_;
  if (!dynamics_->close_positions(t, y)) return false;
  const double motion = (yb.head(n) - ya.head(n)).cwiseAbs().maxCoeff();
  const double correction = (y.head(n) - predicted).cwiseAbs().maxCoeff();
  if (correction > 0.25 * motion + 1e-12 * (1 + y.head(n).cwiseAbs().maxCoeff())) return false;
  dynamics_->solve_rates(t, y);
  return true;
}

std::optional<double> KinematicPath::gauss(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb) {
  const auto last = ya.size() - 1;
  double sum = 0;
  Eigen::VectorXd y;
  for (int k = 0; k < kGaussPoints; ++k) {
    const double t = a + (b - a) * (1 + nodes_[static_cast<std::size_t>(k)]) / 2;
    if (!solve_between(a, ya, b, yb, t, y)) return std::nullopt;
    sum += weights_[static_cast<std::size_t>(k)] * derivative(t, y)[last];
  }
  return sum * (b - a) / 2;
}

std::optional<double> KinematicPath::work(double a, const Eigen::VectorXd& ya, double b, const Eigen::VectorXd& yb,
                                          std::optional<double> whole, int depth) {
  if (!whole) whole = gauss(a, ya, b, yb);
  const double m = (a + b) / 2;
  Eigen::VectorXd ym;
  if (!whole || !solve_between(a, ya, b, yb, m, ym)) return std::nullopt;
  const std::optional<double> left = gauss(a, ya, m, ym), right = gauss(m, ym, b, yb);
  if (!left || !right) return std::nullopt;
  const double halves = *left + *right;
  if (depth >= kQuadratureDepth ||
      std::fabs(*whole - halves) <= 4 * std::numeric_limits<double>::epsilon() * energy_scale_)
    return halves;
  const std::optional<double> first = work(a, ya, m, ym, left, depth + 1),
                              second = work(m, ym, b, yb, right, depth + 1);
  if (!first || !second) return std::nullopt;
  return *first + *second;
}

void KinematicPath::advance(double t, Eigen::VectorXd& y) {
  if (h_ == 0) h_ = t;  // the first output interval sets the first step
  Eigen::VectorXd next;
  // Times a few roundings apart (0.1 + 0.1 + ... against 0.4) are the same time: the state
  // moves by round-off, and a continuation step that short cannot be judged.
  const double sliver = 64 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(t));
  if (t_ < t && t - t_ <= sliver) {
    y[y.size() - 1] += dy_[dy_.size() - 1] * (t - t_);
    t_ = t;
  }
  while (t_ < t) {
    throw_if_interrupted();
    double h = std::min(h_, t - t_);
    if (t - (t_ + h) <= sliver) h = t - t_;  // never leave a sliver before t
    const double to = h == t - t_ ? t : t_ + h;
    std::optional<double> done;  // the work over the step, when it is taken
    if (solve_at(t_, y, dy_, to, next)) {
      if (dynamics_->jacobian_spread(to, next) < kSingularSpread)
        stop(to, "reached a toggle or limit position (" + in_line(to, next) + ": the driver cannot move it on)");
      if (dynamics_->jacobian_sign(to, next) != sign_) crossed(t_, y, to, next);
      done = work(t_, y, to, next, std::nullopt, 0);
    }
    if (!done) {
      ++rejected_;
      h_ = h / 2;
      if (h_ < kShortestStep * std::max(1.0, t_)) stop(t_, past_the_limit(*system_, *dynamics_, t_, y) + ")");
      continue;
    }
    next[next.size() - 1] = y[y.size() - 1] + *done;
    ++accepted_;
    y = next;
    sign_ = dynamics_->jacobian_sign(to, next);
    dy_ = derivative(to, next);
    t_ = to;
    h_ = std::max(h_, 2 * h);
  }
}

void KinematicPath::crossed(double a, Eigen::VectorXd ya, double b, Eigen::VectorXd yb) {
  // det J changed sign within the step: bisect on the path between its ends for where.
  const int sign_a = dynamics_->jacobian_sign(a, ya);
  Eigen::VectorXd ym;
  while (b - a > kShortestStep * std::max(1.0, b)) {
    const double m = (a + b) / 2;
    if (!solve_between(a, ya, b, yb, m, ym)) break;
    if (dynamics_->jacobian_sign(m, ym) == sign_a) {
      a = m;
      ya = ym;
    } else {
      b = m;
      yb = ym;
    }
  }
  const bool at_a = dynamics_->jacobian_spread(a, ya) < dynamics_->jacobian_spread(b, yb);
  stop(at_a ? a : b, "passes a change point (" + in_line(at_a ? a : b, at_a ? ya : yb) +
                         ": J is singular and the mechanism may go on in either assembly, which the driver "
                         "cannot decide)");
}

std::string KinematicPath::in_line(double t, const Eigen::VectorXd& y) const {
  return links_in_line_at(*system_, *dynamics_, t, y);
}

void KinematicPath::stop(double t, const std::string& what) const {
  throw Error::input(driven_stop_message(*system_, t, what) +
                     " (kinematic analysis: the drivers take every degree of freedom)");
}

std::string links_in_line(const sym::System& system, const std::vector<double>& pose) {
  const Mechanism& mechanism = system.mechanism();
  GiNaC::exmap at = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants()) at[symbol] = expression;
  const std::size_t bodies = system.bodies().size();
  for (std::size_t b = 0; b < bodies && 3 * b + 2 < pose.size(); ++b) {
    const sym::BodySystem& body = system.bodies()[b];
    at[body.x.q] = pose[3 * b];
    at[body.y.q] = pose[3 * b + 1];
    if (body.rotates) at[body.theta.q] = pose[3 * b + 2];
  }
  // Slot 0 the ground, slot b + 1 body b: its joints, then its line's unit direction.
  const auto slot = [&](const std::string& name) { return static_cast<std::size_t>(mechanism.body_index(name) + 1); };
  std::vector<std::vector<std::pair<std::size_t, int>>> joints(bodies + 1);  // (joint, side)
  for (std::size_t j = 0; j < mechanism.joints.size(); ++j)
    for (int side = 0; side < 2; ++side)
      joints[slot(mechanism.joints[j].bodies[static_cast<std::size_t>(side)])].emplace_back(j, side);
  std::vector<std::optional<Eigen::Vector2d>> line(bodies + 1);
  for (std::size_t b = 0; b <= bodies; ++b) {
    if (joints[b].size() != 2) continue;  // binary links only: two joints give one line
    std::vector<Eigen::Vector2d> pins;
    std::optional<Eigen::Vector2d> axis;
    for (const auto& [j, side] : joints[b]) {
      const Joint& joint = mechanism.joints[j];
      switch (joint_type_info(joint.type).motion) {
        case JointMotion::revolute:
        case JointMotion::fixed:  // a point the link is joined at
        case JointMotion::rolling: {
          const sym::Vec2 p =
              system.point_position(static_cast<int>(b) - 1, joint.points[static_cast<std::size_t>(side)]);
          pins.emplace_back(sym::evaluate(p.x, at), sym::evaluate(p.y, at));
          break;
        }
        case JointMotion::loop:  // no point or axis the link is joined along
          break;
        case JointMotion::prismatic: {
          // The axis, in the frame of bodies[0], turned into the world.
          const sym::Vec2 a = sym::rotate(
              slot(joint.bodies[0]) == 0 ? GiNaC::ex(0) : GiNaC::ex(system.bodies()[slot(joint.bodies[0]) - 1].theta.q),
              {system.quantity(joint.axis->x, false), system.quantity(joint.axis->y, false)});
          axis = Eigen::Vector2d(sym::evaluate(a.x, at), sym::evaluate(a.y, at));
          break;
        }
        case JointMotion::slotted: {  // the slot's body lies along it; the pin's is joined at a point
          if (side == 0) {
            const sym::Vec2 a =
                sym::rotate(slot(joint.bodies[0]) == 0 ? GiNaC::ex(0)
                                                       : GiNaC::ex(system.bodies()[slot(joint.bodies[0]) - 1].theta.q),
                            {system.quantity(joint.axis->x, false), system.quantity(joint.axis->y, false)});
            axis = Eigen::Vector2d(sym::evaluate(a.x, at), sym::evaluate(a.y, at));
          } else {
            const sym::Vec2 p = system.point_position(static_cast<int>(b) - 1, joint.points[1]);
            pins.emplace_back(sym::evaluate(p.x, at), sym::evaluate(p.y, at));
          }
          break;
        }
      }
    }
    const Eigen::Vector2d d = axis               ? *axis
                              : pins.size() == 2 ? Eigen::Vector2d(pins[1] - pins[0])
                                                 : Eigen::Vector2d::Zero();
    if (d.norm() > 0 && d.allFinite()) line[b] = d.normalized();
  }
  // Bodies joined by a pin whose lines are parallel, grouped; else the pair nearest to it.
  std::vector<std::size_t> group(bodies + 1);
  for (std::size_t b = 0; b <= bodies; ++b) group[b] = b;
  const auto root = [&](std::size_t b) {
    while (group[b] != b) b = group[b];
    return b;
  };
  double nearest = std::numeric_limits<double>::infinity();
  std::array<std::size_t, 2> nearest_pair{};
  for (const Joint& joint : mechanism.joints) {
    // A slider's bodies share its axis always, a weld's keep their angle.
    if (joint_type_info(joint.type).motion != JointMotion::revolute) continue;
    const std::size_t a = slot(joint.bodies[0]), b = slot(joint.bodies[1]);
    if (!line[a] || !line[b]) continue;
    const double sine = std::fabs(line[a]->x() * line[b]->y() - line[a]->y() * line[b]->x());
    if (sine < kInLine) group[root(a)] = root(b);
    if (sine < nearest) {
      nearest = sine;
      nearest_pair = {a, b};
    }
  }
  const auto name = [&](std::size_t b) { return b == 0 ? std::string(kGround) : mechanism.bodies[b - 1].name; };
  const auto listed = [](const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
      text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
    return text + " in line";
  };
  std::string text;
  for (std::size_t r = 0; r <= bodies; ++r) {
    std::vector<std::string> names;
    for (std::size_t b = 0; b <= bodies; ++b)
      if (root(b) == r && line[b]) names.push_back(name(b));
    if (names.size() >= 2) text += (text.empty() ? "" : "; ") + listed(names);
  }
  if (text.empty() && std::isfinite(nearest)) text = listed({name(nearest_pair[0]), name(nearest_pair[1])});
  return text.empty() ? "its links in line" : text;
}

std::string past_the_limit(const sym::System& system, const eval::MechanismDynamics& dynamics, double t,
                           const Eigen::VectorXd& y) {
  return "cannot close beyond here (a limit position, " + links_in_line_at(system, dynamics, t, y) +
         ": J's smallest over largest singular value " + format_significant(dynamics.jacobian_spread(t, y), 2) +
         " there";
}

std::string driven_stop_message(const sym::System& system, double t, const std::string& what) {
  const Mechanism& mechanism = system.mechanism();
  std::string loops;
  for (int j : system.tree().loop_joints)
    loops += (loops.empty() ? "" : ", ") + mechanism.joints[static_cast<std::size_t>(j)].name;
  std::string drivers;
  GiNaC::exmap at = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants()) at[symbol] = expression;
  at[system.time()] = t;
  for (const sym::DriverSystem& d : system.drivers()) {
    const Driver& driver = mechanism.drivers[static_cast<std::size_t>(d.index)];
    const std::string unit =
        std::string(" ") + joint_type_info(mechanism.joints[static_cast<std::size_t>(d.joint)].type).driven_unit;
    drivers += std::string(drivers.empty() ? "" : ", ") + "driver '" + driver.name + "' at " +
               format_significant(sym::evaluate(system.quantity(driver.motion, true), at), 6) + unit;
  }
  const std::string what_closes = loops.empty() ? std::string("the mechanism") : "the loop through " + loops;
  return "at t = " + format_significant(t, 6) + " s " + drivers + ": " + what_closes + " " + what +
         "; valid: a motion within the mechanism's range";
}

}  // namespace linkage
