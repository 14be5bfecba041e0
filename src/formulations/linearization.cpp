#include "formulations/linearization.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "formulations/case_system.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using GiNaC::ex;

constexpr int kMaxNewtonSteps = 100;

/// The rows and constraints in the generalized coordinates with every length written out
/// (a spring's stiffness acts through its length), at t = 0.
struct StaticForm {
  std::vector<ex> F;    // n rows: A_q'' q'' + A_lambda lambda - B
  std::vector<ex> phi;  // the loop-closing joints' and the drivers' position rows
  std::vector<std::vector<ex>> mass;
  std::vector<GiNaC::symbol> q, rates, accelerations, lambda;
};

StaticForm static_form(const sym::System& system) {
  const CaseSystem lagrange = lagrange_case(system);
  const auto& coordinates = system.coordinates();
  const std::size_t n = coordinates.size();
  GiNaC::exmap at_zero{{system.time(), 0}};
  const auto written_out = [&](const ex& e) {
    return e.subs(system.lengths(), GiNaC::subs_options::no_pattern)
        .subs(system.to_generalized(), GiNaC::subs_options::no_pattern)
        .subs(at_zero, GiNaC::subs_options::no_pattern);
  };
  StaticForm out;
  for (const sym::GeneralizedCoordinate& g : coordinates) {
    out.q.push_back(g.symbols.q);
    out.rates.push_back(g.symbols.q_dot);
    out.accelerations.push_back(g.symbols.q_ddot);
  }
  for (std::size_t k = n; k < lagrange.unknowns.size(); ++k) out.lambda.push_back(lagrange.unknowns[k]);
  for (std::size_t i = 0; i < n; ++i) {
    ex row = -lagrange.B[i];
    std::vector<ex> mass_row;
    for (std::size_t j = 0; j < lagrange.unknowns.size(); ++j) {
      row += lagrange.A[i][j] * lagrange.unknowns[j];
      if (j < n) mass_row.push_back(written_out(lagrange.A[i][j]));
    }
    out.F.push_back(written_out(row));
    out.mass.push_back(std::move(mass_row));
  }
  for (int j : system.tree().loop_joints)
    for (const ex& c : system.joints()[static_cast<std::size_t>(j)].constraints) out.phi.push_back(written_out(c));
  const Mechanism& m = system.mechanism();
  for (const sym::DriverSystem& d : system.drivers()) {
    const Driver& driver = m.drivers[static_cast<std::size_t>(d.index)];
    const ex moving = d.constraint.subs(system.to_generalized(), GiNaC::subs_options::no_pattern)
                          .subs(system.constants())
                          .subs(system.constants())
                          .diff(system.time());
    if (!GiNaC::normal(moving).is_zero())
      throw Error::input(where(driver.motion.pos) + "driver " + driver.name + "'s motion '" + driver.motion.text +
                         "' moves with t; small vibrations are about a fixed equilibrium: give a constant motion "
                         "(the joint locked) or leave the driver out");
    out.phi.push_back(written_out(d.constraint));
  }
  if (out.phi.size() != out.lambda.size())
    throw std::logic_error("linearize: " + std::to_string(out.phi.size()) + " constraint rows for " +
                           std::to_string(out.lambda.size()) + " multipliers");
  return out;
}

/// Values of the constants and parameters, to which the state's are added.
GiNaC::exmap base_values(const sym::System& system) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, value] : system.constants()) values[symbol] = value;
  return values;
}

Eigen::MatrixXd evaluated(const std::vector<std::vector<ex>>& rows, const GiNaC::exmap& values) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()),
                      static_cast<Eigen::Index>(rows.empty() ? 0 : rows.front().size()));
  for (Eigen::Index i = 0; i < out.rows(); ++i)
    for (Eigen::Index j = 0; j < out.cols(); ++j)
      out(i, j) = sym::evaluate(rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], values);
  return out;
}

std::vector<std::vector<ex>> jacobian(const std::vector<ex>& rows, const std::vector<GiNaC::symbol>& by) {
  std::vector<std::vector<ex>> out;
  for (const ex& r : rows) {
    std::vector<ex> row;
    for (const GiNaC::symbol& s : by) row.push_back(r.diff(s));
    out.push_back(std::move(row));
  }
  return out;
}

/// The state's values: q, lambda, rates and accelerations zero.
void set_state(const StaticForm& form, const Eigen::VectorXd& x, GiNaC::exmap& values) {
  const std::size_t n = form.q.size();
  for (std::size_t i = 0; i < n; ++i) {
    values[form.q[i]] = x[static_cast<Eigen::Index>(i)];
    values[form.rates[i]] = 0;
    values[form.accelerations[i]] = 0;
  }
  for (std::size_t k = 0; k < form.lambda.size(); ++k) values[form.lambda[k]] = x[static_cast<Eigen::Index>(n + k)];
}

/// The residual [F; Phi] at x = (q, lambda).
Eigen::VectorXd residual(const StaticForm& form, const Eigen::VectorXd& x, GiNaC::exmap& values) {
  set_state(form, x, values);
  Eigen::VectorXd r(static_cast<Eigen::Index>(form.F.size() + form.phi.size()));
  Eigen::Index k = 0;
  for (const ex& e : form.F) r[k++] = sym::evaluate(e, values);
  for (const ex& e : form.phi) r[k++] = sym::evaluate(e, values);
  return r;
}

double largest(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff(); }

/// Picks the independent coordinates: the dependent ones are m columns of J, taken first
/// among the coordinates the file does not name `independent` (in order), so the file's
/// choice is kept where the constraints allow it.
std::vector<std::size_t> dependent_columns(const Eigen::MatrixXd& J, const std::vector<std::string>& names,
                                           const std::vector<std::string>& preferred) {
  const auto m = J.rows();
  std::vector<std::size_t> order;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t j = 0; j < names.size(); ++j) {
      const bool kept = std::find(preferred.begin(), preferred.end(), names[j]) != preferred.end();
      if (kept == (pass == 1)) order.push_back(j);
    }
  const double scale = std::max(J.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  std::vector<std::size_t> chosen;
  for (const std::size_t j : order) {
    if (static_cast<Eigen::Index>(chosen.size()) == m) break;
    Eigen::MatrixXd columns(m, static_cast<Eigen::Index>(chosen.size() + 1));
    for (std::size_t c = 0; c < chosen.size(); ++c)
      columns.col(static_cast<Eigen::Index>(c)) = J.col(static_cast<Eigen::Index>(chosen[c]));
    columns.col(static_cast<Eigen::Index>(chosen.size())) = J.col(static_cast<Eigen::Index>(j));
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(columns);
    qr.setThreshold(1e-10 * scale / std::max(1.0, columns.cwiseAbs().maxCoeff()));
    if (qr.rank() == columns.cols()) chosen.push_back(j);
  }
  return chosen;
}

}  // namespace

std::size_t mode_count(const sym::System& system) {
  std::size_t rows = system.drivers().size();
  for (int j : system.tree().loop_joints) rows += system.joints()[static_cast<std::size_t>(j)].constraints.size();
  const std::size_t n = system.coordinates().size();
  return rows >= n ? 0 : n - rows;
}

Linearization linearize(const sym::System& system, const LinearizeOptions& options) {
  const Mechanism& mechanism = system.mechanism();
  const StaticForm form = static_form(system);
  const std::size_t n = form.q.size(), m = form.phi.size();
  const auto N = static_cast<Eigen::Index>(n);
  Linearization out;
  out.at_initial = options.at_initial;
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    out.tree_coordinates.push_back(g.coordinate.key);
    out.tree_units.push_back(g.coordinate.kind == CoordinateKind::theta ? "rad" : "m");
  }
  if (m >= n)
    throw Error::input("modes: " + mechanism.name + " has no degree of freedom (" + std::to_string(n) +
                       " coordinates, " + std::to_string(m) +
                       " loop and driver rows): nothing is free to vibrate; valid: a mechanism with at least one");

  // Newton's method on (q, lambda) from the closed initial state, lambda from zero.
  const GiNaC::exmap start = sym::checked_initial_state(system).state;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n + m));
  for (std::size_t i = 0; i < n; ++i) x[static_cast<Eigen::Index>(i)] = sym::to_double(start.at(form.q[i]));
  GiNaC::exmap values = base_values(system);
  std::vector<GiNaC::symbol> unknowns = form.q;
  unknowns.insert(unknowns.end(), form.lambda.begin(), form.lambda.end());
  std::vector<ex> all = form.F;  // [F; Phi] by (q, lambda)
  all.insert(all.end(), form.phi.begin(), form.phi.end());
  const std::vector<std::vector<ex>> dall = jacobian(all, unknowns);
  const auto forces = [&](const Eigen::VectorXd& r) { return largest(r.head(N)); };
  Eigen::VectorXd r = residual(form, x, values);
  if (!r.allFinite())
    throw Error::input("modes: " + mechanism.name +
                       "'s equations are not finite at [initial]; valid: a state where "
                       "every load and length is finite");
  // lambda holding the initial q as well as it can; the forces' scale: the imbalance
  // there, or the stiffness times a unit move.
  set_state(form, x, values);
  const Eigen::MatrixXd D0 = evaluated(dall, values);
  if (m > 0) {
    x.tail(static_cast<Eigen::Index>(m)) =
        D0.block(0, N, N, static_cast<Eigen::Index>(m)).completeOrthogonalDecomposition().solve(-r.head(N));
    r = residual(form, x, values);
  }
  out.force_scale = forces(r);
  const double scale =
      std::max({out.force_scale, D0.topLeftCorner(N, N).cwiseAbs().maxCoeff(), std::numeric_limits<double>::min()});
  const auto closed = [&] {
    return r.allFinite() && forces(r) <= 1e-10 * scale && largest(r.tail(static_cast<Eigen::Index>(m))) <= 1e-12;
  };
  for (; !options.at_initial && out.newton_steps < kMaxNewtonSteps; ++out.newton_steps) {
    set_state(form, x, values);
    const Eigen::VectorXd dx = evaluated(dall, values).completeOrthogonalDecomposition().solve(-r);
    if (!dx.allFinite()) break;
    // Halved while the residual grows: a step from far off may overshoot.
    double alpha = 1;
    Eigen::VectorXd next = x + dx, rn = residual(form, next, values);
    while (!(largest(rn) <= largest(r)) && alpha > 1.0 / 1024) {
      alpha /= 2;
      next = x + alpha * dx;
      rn = residual(form, next, values);
    }
    x = next;
    r = rn;
    if (closed() && alpha * largest(dx.head(N)) <= 1e-13 * (1 + largest(x.head(N)))) {
      ++out.newton_steps;
      break;
    }
  }
  if (!options.at_initial && !closed())
    throw Error::input("modes: no equilibrium of " + mechanism.name + " found from [initial] (" +
                       std::to_string(out.newton_steps) + " Newton steps; largest generalized force left " +
                       format_significant(forces(r), 3) + " against " + format_significant(scale, 3) +
                       "); valid: [initial] near an equilibrium, or --at-initial to linearize there");
  out.residual = forces(r);
  out.equilibrium = x.head(N);
  out.multipliers = x.tail(static_cast<Eigen::Index>(m));

  // The expansion: M0, C0 = dF/dq', K0 = dF/dq at the point, J0 = dPhi/dq.
  set_state(form, x, values);
  const std::vector<std::vector<ex>> dF_dq = jacobian(form.F, form.q), dF_drate = jacobian(form.F, form.rates);
  out.M_symbolic = form.mass;
  out.K_symbolic = dF_dq;
  out.C_symbolic = dF_drate;
  GiNaC::exmap rates_zero;
  for (const GiNaC::symbol& s : form.rates) rates_zero[s] = 0;
  for (const GiNaC::symbol& s : form.accelerations) rates_zero[s] = 0;
  for (auto* matrix : {&out.K_symbolic, &out.C_symbolic})
    for (auto& row : *matrix)
      for (ex& e : row) e = GiNaC::normal(e.subs(rates_zero, GiNaC::subs_options::no_pattern));
  out.tree_M = evaluated(form.mass, values);
  out.tree_K = evaluated(dF_dq, values);
  out.tree_C = evaluated(dF_drate, values);

  // Reduced to the independent coordinates.
  std::vector<std::size_t> dependent;
  Eigen::MatrixXd J;
  if (m > 0) {
    J = evaluated(jacobian(form.phi, form.q), values);
    dependent = dependent_columns(J, out.tree_coordinates, mechanism.independent);
    if (dependent.size() != m)
      throw Error::input("modes: " + mechanism.name +
                         "'s loop rows are singular at the equilibrium (a change point, links in line): its "
                         "small motions are not determined by the constraints; valid: an equilibrium away from it");
  }
  for (std::size_t j = 0; j < n; ++j)
    if (std::find(dependent.begin(), dependent.end(), j) == dependent.end()) out.independent.push_back(j);
  for (const std::size_t j : out.independent) out.coordinates.push_back(out.tree_coordinates[j]);
  const auto f = static_cast<Eigen::Index>(out.independent.size());
  out.R = Eigen::MatrixXd::Zero(N, f);
  for (Eigen::Index k = 0; k < f; ++k)
    out.R(static_cast<Eigen::Index>(out.independent[static_cast<std::size_t>(k)]), k) = 1;
  if (m > 0) {
    const auto M_rows = static_cast<Eigen::Index>(m);
    Eigen::MatrixXd Jd(M_rows, M_rows), Ji(M_rows, f);
    for (std::size_t c = 0; c < m; ++c)
      Jd.col(static_cast<Eigen::Index>(c)) = J.col(static_cast<Eigen::Index>(dependent[c]));
    for (Eigen::Index k = 0; k < f; ++k)
      Ji.col(k) = J.col(static_cast<Eigen::Index>(out.independent[static_cast<std::size_t>(k)]));
    const Eigen::MatrixXd Rd = -Jd.fullPivLu().solve(Ji);
    for (std::size_t c = 0; c < m; ++c)
      out.R.row(static_cast<Eigen::Index>(dependent[c])) = Rd.row(static_cast<Eigen::Index>(c));
    // The premise of the reduction: the multipliers' columns are -J^T, so R^T removes them.
    const Eigen::MatrixXd A_lambda = evaluated(jacobian(form.F, form.lambda), values);
    const double left = (out.R.transpose() * A_lambda).cwiseAbs().maxCoeff();
    if (!(left <= 1e-9 * std::max(1.0, A_lambda.cwiseAbs().maxCoeff()) * std::max(1.0, out.R.cwiseAbs().maxCoeff())))
      throw std::logic_error("linearize: R^T A_lambda = " + format_significant(left, 3) + ", not zero");
  }
  out.M = out.R.transpose() * out.tree_M * out.R;
  out.C = out.R.transpose() * out.tree_C * out.R;
  out.K = out.R.transpose() * out.tree_K * out.R;
  if (!out.M.allFinite() || !out.C.allFinite() || !out.K.allFinite())
    throw Error::input("modes: " + mechanism.name + "'s linearized matrices are not finite at the equilibrium");
  const Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (out.M + out.M.transpose()));
  if (llt.info() != Eigen::Success)
    throw Error::input("modes: " + mechanism.name +
                       "'s mass matrix is not positive definite at the equilibrium (a body without mass or "
                       "inertia?); valid: every moving body with mass and, when it turns, inertia");
  return out;
}

std::string kind_word(Mode::Kind kind) {
  switch (kind) {
    case Mode::Kind::oscillation:
      return "oscillation";
    case Mode::Kind::neutral:
      return "neutral";
    case Mode::Kind::unstable:
      return "unstable";
  }
  return {};
}

ModalAnalysis modal_analysis(const Linearization& linear) {
  ModalAnalysis out;
  const Eigen::MatrixXd M = 0.5 * (linear.M + linear.M.transpose());
  const Eigen::MatrixXd K = 0.5 * (linear.K + linear.K.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> undamped(K, M);
  if (undamped.info() != Eigen::Success) throw Error::input("modes: the eigenvalue problem K v = w^2 M v failed");
  const Eigen::VectorXd& w2 = undamped.eigenvalues();
  const double scale = w2.size() == 0 ? 0.0 : w2.cwiseAbs().maxCoeff();
  out.damped = linear.C.size() > 0 && linear.C.cwiseAbs().maxCoeff() > 0;
  // The damped system's eigenvalue pairs, by increasing natural frequency |s|.
  std::vector<std::complex<double>> pairs;
  if (out.damped) {
    const auto f = M.rows();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * f, 2 * f);
    A.topRightCorner(f, f).setIdentity();
    const Eigen::LDLT<Eigen::MatrixXd> mass(M);
    A.bottomLeftCorner(f, f) = -mass.solve(linear.K);
    A.bottomRightCorner(f, f) = -mass.solve(linear.C);
    const Eigen::EigenSolver<Eigen::MatrixXd> state(A, false);
    for (Eigen::Index k = 0; k < state.eigenvalues().size(); ++k)
      if (state.eigenvalues()[k].imag() > 0) pairs.push_back(state.eigenvalues()[k]);
    std::sort(pairs.begin(), pairs.end(), [](auto a, auto b) { return std::abs(a) < std::abs(b); });
  }
  std::size_t next_pair = 0;
  for (Eigen::Index k = 0; k < w2.size(); ++k) {
    Mode mode;
    const double tolerance = 1e-10 * scale;
    if (w2[k] < -tolerance) {
      mode.kind = Mode::Kind::unstable;
      mode.growth_rate = std::sqrt(-w2[k]);
      out.stable = false;
    } else if (w2[k] <= tolerance) {
      mode.kind = Mode::Kind::neutral;
    } else {
      mode.omega = mode.damped_omega = std::sqrt(w2[k]);
      if (out.damped && next_pair < pairs.size()) {
        const std::complex<double> s = pairs[next_pair++];
        mode.damping_ratio = -s.real() / std::abs(s);
        mode.damped_omega = s.imag();
      }
    }
    Eigen::VectorXd v = undamped.eigenvectors().col(k);
    Eigen::Index at = 0;
    v.cwiseAbs().maxCoeff(&at);
    mode.shape = v / v[at];
    mode.tree_shape = linear.R * mode.shape;
    out.modes.push_back(std::move(mode));
  }
  return out;
}

}  // namespace linkage
