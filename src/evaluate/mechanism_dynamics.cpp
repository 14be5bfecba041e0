#include "evaluate/mechanism_dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/interrupt.hpp"
#include "evaluate/native_builtin.hpp"
#include "evaluate/static_solve.hpp"
#include "evaluate/substitute.hpp"
#include "evaluate/tree_dynamics.hpp"
#include "symbolic/energy.hpp"
#include "symbolic/joints.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/shaking.hpp"

namespace linkage::eval {

namespace {

using GiNaC::ex;

Eigen::Index idx(std::size_t i) { return static_cast<Eigen::Index>(i); }

// A Newton projection that has not met the constraints in this many iterations will not.
constexpr int kProjectionIterations = 12;

// Systems up to this many rows solve with fixed-size matrices once native code runs A and
// B: the compiler unrolls the LU, and nothing is allocated or sized at run time.
constexpr std::size_t kFixedRows = 8;

// y's q and q' into a program's inputs, one value at a time. GCC vectorizes a plain loop
// into 16-byte loads, and a 16-byte load that overlaps a value just stored alone (a
// caller that set one entry of y, as a nudged state in `bench mechanisms` or a column
// written by hand) waits for the store to retire instead of taking it from the store
// buffer: that stall was a fifth of the homework's right-hand side at its initial state.
void copy_state_in(const double* from, double* to, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    double v = from[i];
#if defined(__GNUC__) && defined(__x86_64__)
    asm("" : "+x"(v));  // one value per load: the loop is not paired into vectors
#endif
    to[i] = v;
  }
}

/// The pivots' spread of an LU (see unknowns()).
template <class Lu>
double pivot_spread(const Lu& lu) {
  const auto pivots = lu.matrixLU().diagonal().cwiseAbs();
  return pivots.minCoeff() / pivots.maxCoeff();
}

/// x from the upper triangle of a (row major at `Stride`) and b of N rows. Unrolled into
/// registers and stored once at the end: the loop as written was vectorized into 16-byte
/// loads of two x just stored one at a time, which wait for the stores to retire (store
/// forwarding fails); perf put a quarter of the four-bar's Case 1 on that one load.
template <int N, int Stride>
void back_substitute(const double* a, const double* b, double* x) {
  std::array<double, N> v;
#pragma GCC unroll 8
  for (int k = N - 1; k >= 0; --k) {
    double sum = b[k];
#pragma GCC unroll 8
    for (int j = k + 1; j < N; ++j) sum -= a[k * Stride + j] * v[j];
    v[k] = sum / a[k * Stride + k];
  }
  std::copy(v.begin(), v.end(), x);
}

/// A u = B for A (row major) and B of N rows at `values`; the pivots' spread. The same
/// elimination as Eigen's PartialPivLU (largest pivot of the column, first on ties), with
/// N known to the compiler: Eigen's fixed-size LU still runs its general loops and
/// triangular solves, 60% of the homework's Case 3 right-hand side under perf.
template <int N>
double solve_fixed(const double* values, Eigen::VectorXd& u) {
  std::array<double, N * N> a;
  std::array<double, N> b;
  std::copy(values, values + N * N, a.begin());
  std::copy(values + N * N, values + N * N + N, b.begin());
  double largest = 0, smallest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < N; ++k) {
    int p = k;
    for (int i = k + 1; i < N; ++i)
      if (std::fabs(a[i * N + k]) > std::fabs(a[p * N + k])) p = i;
    if (p != k) {
      for (int j = 0; j < N; ++j) std::swap(a[k * N + j], a[p * N + j]);
      std::swap(b[k], b[p]);
    }
    const double pivot = a[k * N + k];
    if (!(std::fabs(pivot) > 0)) return 0;  // zero or NaN: singular
    largest = std::max(largest, std::fabs(pivot));
    smallest = std::min(smallest, std::fabs(pivot));
    for (int i = k + 1; i < N; ++i) {
      const double l = a[i * N + k] / pivot;
      for (int j = k + 1; j < N; ++j) a[i * N + j] -= l * a[k * N + j];
      b[i] -= l * b[k];
    }
  }
  const double rcond = smallest / largest;
  if (!(rcond > std::numeric_limits<double>::epsilon())) return 0;
  u.resize(N);
  back_substitute<N, N>(a.data(), b.data(), u.data());
  return rcond;
}

/// solve_fixed for N up to kFixedRows; nullopt for a larger system.
template <std::size_t... I>
std::optional<double> solve_small(std::size_t n, const double* values, Eigen::VectorXd& u,
                                  std::index_sequence<I...> /*sizes less one*/) {
  std::optional<double> rcond;
  (void)((n == I + 1 && (rcond = solve_fixed<static_cast<int>(I + 1)>(values, u), true)) || ...);
  return rcond;
}
std::optional<double> solve_small(std::size_t n, const double* values, Eigen::VectorXd& u) {
  return solve_small(n, values, u, std::make_index_sequence<kFixedRows>{});
}

/// P x = r for P symmetric positive definite of N rows, its upper triangle row major at
/// stride kFixedRows; the pivots' spread, 0 for a pivot not positive (P singular, as at a
/// dead point, where rounding leaves a pivot near zero of either sign). Gaussian
/// elimination without pivoting on the upper triangle (LDL^T): half the LU's work.
template <int N>
double solve_symmetric(std::array<double, kFixedRows * kFixedRows>& p, std::array<double, kFixedRows>& r, double* x) {
  constexpr int S = static_cast<int>(kFixedRows);
  double largest = 0, smallest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < N; ++k) {
    const double pivot = p[k * S + k];
    if (!(pivot > 0)) return 0;  // zero, negative or NaN: singular
    largest = std::max(largest, pivot);
    smallest = std::min(smallest, pivot);
    for (int i = k + 1; i < N; ++i) {
      const double l = p[k * S + i] / pivot;
      for (int j = i; j < N; ++j) p[i * S + j] -= l * p[k * S + j];
      r[i] -= l * r[k];
    }
  }
  const double rcond = smallest / largest;
  if (!(rcond > std::numeric_limits<double>::epsilon())) return 0;
  back_substitute<N, S>(p.data(), r.data(), x);
  return rcond;
}

template <std::size_t... I>
double solve_symmetric(std::size_t n, std::array<double, kFixedRows * kFixedRows>& p, std::array<double, kFixedRows>& r,
                       double* x, std::index_sequence<I...> /*sizes less one*/) {
  double rcond = 0;
  (void)((n == I + 1 && (rcond = solve_symmetric<static_cast<int>(I + 1)>(p, r, x), true)) || ...);
  return rcond;
}

/// The joint's own coordinate in maximal coordinates (a slider's s; 0 without one).
ex joint_coordinate(const sym::System& system, int joint) {
  return sym::joint_stages(system.mechanism().joints[static_cast<std::size_t>(joint)].type)
      .coordinate(sym::maximal_ends(system, joint));
}

}  // namespace

std::vector<NamedPoint> named_points(const sym::System& system) {
  std::vector<NamedPoint> out;
  for (std::size_t b = 0; b < system.bodies().size(); ++b)
    for (const auto& [name, position] : system.bodies()[b].points) out.push_back({b, name});
  return out;
}

MechanismDynamics::MechanismDynamics(const sym::System& system, CaseId id, std::optional<CaseSystem> derived)
    : id_(id), system_(&system), derived_(std::move(derived)) {
  if (derived_ && derived_->id != id) throw std::logic_error("a derived case given for another case");
  const bool maximal = id == CaseId::maximal;
  bodies_ = system.bodies().size();
  joints_ = system.joints().size();
  for (const sym::JointSystem& j : system.joints()) joint_rows_.push_back(j.constraints.size());

  // The state's coordinates: every body's own for Case 1, the tree's otherwise.
  std::vector<GiNaC::symbol> q, q_dot;
  if (maximal) {
    for (const sym::BodySystem& b : system.bodies()) {
      q.push_back(b.x.q);
      q_dot.push_back(b.x.q_dot);
      coordinate_names_.push_back(b.name + ".x");
      q.push_back(b.y.q);
      q_dot.push_back(b.y.q_dot);
      coordinate_names_.push_back(b.name + ".y");
      if (!b.rotates) continue;
      q.push_back(b.theta.q);
      q_dot.push_back(b.theta.q_dot);
      coordinate_names_.push_back(b.name + ".theta");
    }
  } else {
    for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
      q.push_back(g.symbols.q);
      q_dot.push_back(g.symbols.q_dot);
      coordinate_names_.push_back(g.coordinate.key);
    }
  }
  n_ = q.size();
  // The state at the file's generalized values: Case 1 places the bodies by them.
  constants_ = system.parameter_values();
  for (const auto& [symbol, value] : system.constants()) constants_[symbol] = value;
  auto in_generalized = [&](const GiNaC::symbol& s) {
    const auto it = system.to_generalized().find(s);
    return maximal && it != system.to_generalized().end() ? it->second : ex(s);
  };
  for (const GiNaC::symbol& s : q) initial_expressions_.push_back(in_generalized(s));
  for (const GiNaC::symbol& s : q_dot) initial_expressions_.push_back(in_generalized(s));
  state_symbols_ = q;
  state_symbols_.insert(state_symbols_.end(), q_dot.begin(), q_dot.end());

  std::vector<GiNaC::symbol> inputs;
  for (const sym::SymbolInfo& info : system.table().all())
    if (info.role == sym::Role::parameter) {
      inputs.push_back(info.symbol);
      parameter_values_.push_back(sym::to_double(system.parameter_values().at(info.symbol)));
    }
  parameters_ = inputs.size();
  inputs.insert(inputs.end(), state_symbols_.begin(), state_symbols_.end());
  inputs.push_back(system.time());

  // Maximal positions and rates in the state's coordinates (none to replace for Case 1).
  if (!maximal)
    for (const auto& [symbol, expression] : system.to_generalized()) {
      const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
      if (info != nullptr && info->role != sym::Role::acceleration) to_state_[symbol] = expression;
    }
  input_symbols_ = inputs;
  auto prepare = [&](const ex& e) { return this->prepare(e); };
  const ex power = prepare(sym::nonconservative_power(system));
  power_zero_ = power.is_zero();  // no damper, no applied load: nothing to evaluate per step
  power_ = compile({power}, inputs);
  // A driven Case 3 solves densely: the drivers' power needs their torques, which the
  // recursion does not yield.
  if (id == CaseId::reduced && system.drivers().empty() && TreeDynamics::applies(system))
    tree_ = std::make_unique<TreeDynamics>(system);

  // The kept constraints: the last rows of the case, in joint order, then the drivers'.
  std::vector<ex> kept;
  auto keep = [&](int j) {
    for (const ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints) {
      kept.push_back(prepare(phi));
      constraint_joint_.push_back(j);
    }
  };
  if (maximal)
    for (std::size_t j = 0; j < joints_; ++j) keep(static_cast<int>(j));
  else
    for (int j : system.tree().loop_joints) keep(j);
  for (const sym::DriverSystem& d : system.drivers()) {
    kept.push_back(prepare(d.constraint));
    constraint_joint_.push_back(d.joint);
  }
  constraint_rows_ = static_cast<int>(kept.size());
  drivers_ = system.drivers().size();
  if (drivers_ > 0) {
    // C' = J q' + C_t: C_t of every kept row, then each driver's J q' (its power over its
    // torque or force). Only with drivers: a scleronomic mechanism's programs stay as built in.
    std::vector<ex> rates;
    for (const ex& phi : kept) rates.push_back(GiNaC::expand(phi.diff(system.time())));
    for (std::size_t d = 0; d < drivers_; ++d) {
      ex jq = 0;
      for (std::size_t i = 0; i < n_; ++i) jq += kept[kept.size() - drivers_ + d].diff(q[i]) * q_dot[i];
      rates.push_back(GiNaC::expand(jq));
    }
    time_rates_ = compile(rates, inputs);
    time_rate_values_.resize(rates.size());
    scratch_.resize(std::max(scratch_.size(), time_rates_.scratch_size()));
  }
  inputs_.assign(inputs.size(), 0.0);
  for (std::size_t i = 0; i < parameters_; ++i) inputs_[i] = parameter_values_[i];
  J_.resize(constraint_rows_, idx(n_));
  M_.resize(idx(n_), idx(n_));
  constraint_values_.resize(static_cast<std::size_t>(constraint_rows_));
  power_values_.resize(1);
  scratch_.resize(power_.scratch_size());
  // A mechanism without kept constraints needs no metric: T is not expanded (for long
  // chains its expansion is the costliest expression of all).
  if (constraint_rows_ == 0) return;
  std::vector<ex> constraint_outputs = kept;
  for (const ex& phi : kept)
    for (const GiNaC::symbol& s : q) constraint_outputs.push_back(GiNaC::expand(phi.diff(s)));
  const ex kinetic = prepare(sym::kinetic_energy(system));
  for (const GiNaC::symbol& a : q_dot)
    for (const GiNaC::symbol& b : q_dot) constraint_outputs.push_back(GiNaC::expand(kinetic.diff(a).diff(b)));
  constraints_ = compile(constraint_outputs, inputs);
  values_.resize(constraints_.output_count());
  scratch_.resize(std::max(scratch_.size(), constraints_.scratch_size()));
}

std::vector<Program*> MechanismDynamics::programs(bool kinematics) {
  compile_case();
  if (kinematics) compile_kinematics();
  std::vector<Program*> out;
  for (Program* p : {&power_, &constraints_, &rhs_, &solve_, &outputs_, &kinematics_, &time_rates_})
    if (p->output_count() > 0) out.push_back(p);
  if (tree_)
    for (Program* p : tree_->programs())
      if (p->output_count() > 0) out.push_back(p);
  return out;
}

NativeAttachment MechanismDynamics::attach_native(bool kinematics, bool may_compile) {
  return eval::attach_native(programs(kinematics), may_compile);
}

NativeAttachment MechanismDynamics::attach_native_derivative(bool may_compile) {
  if (!tree_) return attach_native(false, may_compile);
  std::vector<Program*> programs;
  // A small tree solves A u = B, not by the recursion (derivative()).
  if (n_ + static_cast<std::size_t>(constraint_rows_) <= kFixedRows) compile_case();
  for (Program* p : {&power_, &time_rates_, &rhs_, &solve_})
    if (p->output_count() > 0) programs.push_back(p);
  for (Program* p : tree_->programs())
    if (p->output_count() > 0) programs.push_back(p);
  return eval::attach_native(programs, may_compile);
}

bool MechanismDynamics::attach_builtin(bool kinematics) {
  builtin_ = eval::attach_builtin(programs(kinematics));
  return builtin_;
}

void MechanismDynamics::find_structure(const std::vector<GiNaC::ex>& rhs) const {
  // Symbolically, from the expanded rows: A = [M G; J 0] with M symmetric, G = s J^T.
  schur_ = false;
  if (rows_ <= kFixedRows || rows_ == n_) return;
  const auto at = [&](std::size_t i, std::size_t j) -> const ex& { return rhs[i * cols_ + j]; };
  const auto same = [](const ex& a, const ex& b) { return GiNaC::expand(a - b).is_zero(); };
  mass_diagonal_ = true;
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = i + 1; j < n_; ++j) {
      if (!same(at(i, j), at(j, i))) return;
      if (!at(i, j).is_zero()) mass_diagonal_ = false;
    }
  for (std::size_t i = n_; i < rows_; ++i)
    for (std::size_t j = n_; j < cols_; ++j)
      if (!at(i, j).is_zero()) return;
  for (const int sign : {1, -1}) {
    bool transposed = true;
    for (std::size_t i = 0; i < n_ && transposed; ++i)
      for (std::size_t k = n_; k < rows_ && transposed; ++k) transposed = same(at(i, k), sign * at(k, i));
    if (transposed) {
      schur_ = true;
      schur_sign_ = sign;
      find_sparsity(rhs);
      return;
    }
  }
}

void MechanismDynamics::find_sparsity(const std::vector<GiNaC::ex>& rhs) const {
  // J's structurally non-zero columns by row, and those two rows share (a joint's row
  // touches only its two bodies): S = J M^-1 J^T sums over these alone.
  const std::size_t m = rows_ - n_;
  const auto nonzero = [&](std::size_t k, std::size_t j) { return !rhs[(n_ + k) * cols_ + j].is_zero(); };
  row_start_.assign(1, 0);
  row_columns_.clear();
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t j = 0; j < n_; ++j)
      if (nonzero(k, j)) row_columns_.push_back(static_cast<std::uint32_t>(j));
    row_start_.push_back(static_cast<std::uint32_t>(row_columns_.size()));
  }
  pair_start_.assign(1, 0);
  pair_columns_.clear();
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t l = k; l < m; ++l) {
      for (std::size_t j = 0; j < n_; ++j)
        if (nonzero(k, j) && nonzero(l, j)) pair_columns_.push_back(static_cast<std::uint32_t>(j));
      pair_start_.push_back(static_cast<std::uint32_t>(pair_columns_.size()));
    }
}

GiNaC::ex MechanismDynamics::prepare(const GiNaC::ex& e) const {
  // Expanded, as CaseEvaluator does: one form whatever GiNaC's term order.
  return substitute_in_turn(e, {&system_->lengths(), &to_state_, &system_->constants(), &system_->constants()}, true);
}

void MechanismDynamics::compile_case() const {
  if (compiled_) return;
  const sym::System& system = *system_;
  const CaseSystem c = derived_ ? *derived_ : derive_case(system, id_);
  auto prepare = [&](const ex& e) { return this->prepare(e); };
  rows_ = c.A.size();
  cols_ = c.unknowns.size();
  if (rows_ != cols_ || cols_ < n_)
    throw std::logic_error("a case's system is not square with the accelerations first");
  std::vector<ex> rhs;
  for (const auto& row : c.A) {
    throw_if_interrupted();
    for (const ex& e : row) rhs.push_back(prepare(e));
  }
  for (const ex& e : c.B) {
    throw_if_interrupted();
    rhs.push_back(prepare(e));
  }
  rhs_ = compile(rhs, input_symbols_);
  find_structure(rhs);
  if (rows_ <= kFixedRows) {
    const std::vector<GiNaC::symbol> state(input_symbols_.begin() + static_cast<std::ptrdiff_t>(parameters_),
                                           input_symbols_.end());
    if (const std::optional<StaticSolve> plan = plan_static_solve(rhs, rows_, state, system.parameter_values())) {
      // The run's constants as inputs of their own, computed here once.
      GiNaC::exmap values = system.parameter_values();
      std::vector<GiNaC::symbol> inputs = input_symbols_;
      solve_inputs_ = inputs_;
      for (const auto& [symbol, definition] : plan->constants) {
        const double value = sym::evaluate(definition, values);
        values[symbol] = value;
        inputs.push_back(symbol);
        solve_inputs_.push_back(value);
      }
      solve_ = compile(plan->outputs, inputs, plan->definitions);
      solve_.read_state_from(parameters_, 2 * n_);  // q and q' read from y itself
      // The pivots that are constants of the run (numbers, parameters' factors) checked now.
      std::vector<std::optional<double>> pivots;
      for (std::size_t k = cols_; k < plan->outputs.size(); ++k) {
        const ex& p = plan->outputs[k];
        const bool constant = GiNaC::is_a<GiNaC::numeric>(p) || (GiNaC::is_a<GiNaC::symbol>(p) && values.count(p) > 0);
        pivots.push_back(constant ? std::optional<double>(sym::evaluate(p, values)) : std::nullopt);
      }
      pivot_check_ = PivotCheck(plan->fixed_pivots, pivots);
      static_plain_ =
          power_zero_ && drivers_ == 0 && (!tree_ || n_ + static_cast<std::size_t>(constraint_rows_) <= kFixedRows);
      solve_values_.resize(solve_.output_count());
      u_.resize(idx(cols_));
    }
  }
  free_checking(rhs);

  // The sample: with the unknowns as inputs, and the eliminated forces recovered from them.
  GiNaC::exmap recovered;
  for (const Recovered& r : c.recovered) recovered[r.symbol] = r.value;
  auto prepare_output = [&](const ex& e) { return prepare(e.subs(recovered, GiNaC::subs_options::no_pattern)); };
  std::vector<GiNaC::symbol> output_inputs = input_symbols_;
  output_inputs.insert(output_inputs.end(), c.unknowns.begin(), c.unknowns.end());
  std::vector<ex> out;
  for (const sym::BodySystem& b : system.bodies()) {
    out.push_back(prepare(b.x.q));
    out.push_back(prepare(b.y.q));
    out.push_back(b.rotates ? prepare(b.theta.q) : ex(0));
  }
  for (const sym::BodySystem& b : system.bodies()) {
    throw_if_interrupted();
    out.push_back(prepare(b.x.q_dot));
    out.push_back(prepare(b.y.q_dot));
    out.push_back(b.rotates ? prepare(b.theta.q_dot) : ex(0));
  }
  // C' = dC/dq q' + dC/dt in the bodies' own coordinates, before they become the state's.
  auto rate_of = [&](const ex& phi) {
    ex rate = phi.diff(system.time());
    for (const sym::BodySystem& b : system.bodies()) {
      rate += phi.diff(b.x.q) * b.x.q_dot + phi.diff(b.y.q) * b.y.q_dot;
      if (b.rotates) rate += phi.diff(b.theta.q) * b.theta.q_dot;
    }
    return prepare(rate);
  };
  for (const sym::JointSystem& j : system.joints()) {
    throw_if_interrupted();  // a long chain's recovered forces take seconds to expand
    out.push_back(prepare(joint_coordinate(system, j.index)));
    out.push_back(prepare_output(j.force.x));
    out.push_back(prepare_output(j.force.y));
    out.push_back(prepare_output(j.moment));
    // Its first two unknowns as they stand, for a type that writes them (a rolling's N, f).
    const bool written =
        sym::joint_stages(system.mechanism().joints[static_cast<std::size_t>(j.index)].type).unknown_columns;
    for (std::size_t u = 0; u < 2; ++u)
      out.push_back(written && u < j.unknowns.size() ? prepare_output(j.unknowns[u]) : ex(0));
    // Each row on its own (as many as its type has): |C| of an expanded C^2 would cancel to
    // sqrt(round-off).
    for (const ex& phi : j.constraints) out.push_back(prepare(phi));
    for (const ex& phi : j.constraints) out.push_back(rate_of(phi));
  }
  // The kinetic energy and the angular momentum are sums over the bodies of products of
  // their rates, each a sum over the body's ancestors: expanded, a chain of n links has
  // n^3 terms, so these two are compiled as they stand (n^2 operations).
  auto substituted = [&](const ex& e) {
    return substitute_in_turn(e, {&system.lengths(), &to_state_, &system.constants(), &system.constants()}, false);
  };
  out.push_back(substituted(sym::kinetic_energy(system)));
  out.push_back(prepare(sym::potential_energy(system)));
  out.push_back(prepare(sym::nonconservative_power(system)));
  const sym::Vec2 p = sym::linear_momentum(system);
  out.push_back(prepare(p.x));
  out.push_back(prepare(p.y));
  out.push_back(substituted(sym::angular_momentum_about_centre(system)));
  const sym::Vec2 com = sym::centre_of_mass(system), com_velocity = sym::centre_of_mass_velocity(system);
  for (const ex& e : {com.x, com.y, com_velocity.x, com_velocity.y}) out.push_back(prepare(e));
  const sym::GroundReaction shaking = sym::ground_reaction(system);
  for (const ex& e : {shaking.force.x, shaking.force.y, shaking.moment}) out.push_back(prepare_output(e));
  outputs_ = compile(out, output_inputs);
  free_checking(out);
  output_symbols_ = output_inputs;

  output_inputs_.assign(output_inputs.size(), 0.0);
  values_.resize(std::max({values_.size(), rhs_.output_count(), outputs_.output_count()}));
  scratch_.resize(std::max({scratch_.size(), rhs_.scratch_size(), solve_.scratch_size(), outputs_.scratch_size()}));
  A_.resize(idx(rows_), idx(cols_));
  B_.resize(idx(rows_));
  compiled_ = true;
}

void MechanismDynamics::compile_kinematics() const {
  compile_case();
  if (kinematics_compiled_) return;
  const sym::System& system = *system_;
  // Accelerations in the state's coordinates: the maximal ones by the tree for Cases 2 and 3
  // (positions and rates are prepare()'s), then the unknowns carry q''.
  GiNaC::exmap accelerations;
  if (id_ != CaseId::maximal)
    for (const auto& [symbol, expression] : system.to_generalized()) {
      const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
      if (info != nullptr && info->role == sym::Role::acceleration) accelerations[symbol] = expression;
    }
  auto prepare = [&](const ex& e) { return this->prepare(e.subs(accelerations, GiNaC::subs_options::no_pattern)); };
  std::vector<ex> out;
  for (const sym::BodySystem& b : system.bodies()) {
    out.push_back(prepare(b.x.q_ddot));
    out.push_back(prepare(b.y.q_ddot));
    out.push_back(b.rotates ? prepare(b.theta.q_ddot) : ex(0));
  }
  for (const sym::JointSystem& j : system.joints())
    out.push_back(prepare(system.time_derivative(system.time_derivative(joint_coordinate(system, j.index)))));
  for (const NamedPoint& p : named_points(system)) {
    const sym::Vec2 position = system.point_position(static_cast<int>(p.body), p.name);
    const sym::Vec2 velocity{system.time_derivative(position.x), system.time_derivative(position.y)};
    for (const ex& e : {position.x, position.y, velocity.x, velocity.y, system.time_derivative(velocity.x),
                        system.time_derivative(velocity.y)})
      out.push_back(prepare(e));
  }
  kinematics_ = compile(out, output_symbols_);
  kinematics_compiled_ = true;
  // Compiled after attach_builtin: built in as well when the table has it.
  if (builtin_)
    if (const NativeFunction f = builtin_native(kinematics_.fingerprint()); f != nullptr) kinematics_.attach(f);
}

MechanismDynamics::~MechanismDynamics() = default;
MechanismDynamics::MechanismDynamics(MechanismDynamics&&) noexcept = default;
MechanismDynamics& MechanismDynamics::operator=(MechanismDynamics&&) noexcept = default;

Eigen::VectorXd MechanismDynamics::initial_state(const GiNaC::exmap& values) const {
  // Case 1 starts from the maximal coordinates the generalized state places the bodies at.
  Eigen::VectorXd y = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(state_size()));
  GiNaC::exmap all = constants_;
  for (const auto& [symbol, value] : values) all[symbol] = value;
  for (std::size_t i = 0; i < initial_expressions_.size(); ++i) y[idx(i)] = sym::evaluate(initial_expressions_[i], all);
  return y;
}

void MechanismDynamics::set_baumgarte(double alpha, double beta) {
  two_alpha_ = 2 * alpha;
  beta_squared_ = beta * beta;
}

void MechanismDynamics::fill_inputs(double t, const Eigen::VectorXd& y) const {
  copy_state_in(y.data(), inputs_.data() + parameters_, 2 * n_);
  inputs_[parameters_ + 2 * n_] = t;
}

void MechanismDynamics::evaluate_time_rates(double t, const Eigen::VectorXd& y) const {
  if (drivers_ == 0) return;
  fill_inputs(t, y);
  time_rates_.run(inputs_.data(), time_rate_values_.data(), scratch_.data());
}

Eigen::VectorXd MechanismDynamics::constraint_rate(double t, const Eigen::VectorXd& y) const {
  Eigen::VectorXd rate = J_ * y.segment(idx(n_), idx(n_));
  if (drivers_ == 0) return rate;
  evaluate_time_rates(t, y);
  for (Eigen::Index i = 0; i < rate.size(); ++i) rate[i] += time_rate_values_[static_cast<std::size_t>(i)];
  return rate;
}

void MechanismDynamics::evaluate_constraints(double t, const Eigen::VectorXd& y) const {
  fill_inputs(t, y);
  constraints_.run(inputs_.data(), values_.data(), scratch_.data());
  const auto m = static_cast<std::size_t>(constraint_rows_);
  std::size_t k = 0;
  for (std::size_t i = 0; i < m; ++i) constraint_values_[i] = values_[k++];
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < n_; ++j) J_(idx(i), idx(j)) = values_[k++];
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j) M_(idx(i), idx(j)) = values_[k++];
}

void MechanismDynamics::evaluate_rows(double t, const Eigen::VectorXd& y) const {
  compile_case();
  const bool baumgarte = constraint_rows_ > 0 && (two_alpha_ != 0 || beta_squared_ != 0);
  if (baumgarte) evaluate_constraints(t, y);  // first: values_ ends with the right-hand side's outputs
  fill_inputs(t, y);
  rhs_.run(inputs_.data(), values_.data(), scratch_.data());
  if (!baumgarte) return;
  // On the kept constraints' rows, the last (Case 2 has force rows before them).
  const auto m = static_cast<Eigen::Index>(constraint_rows_);
  Eigen::Map<Eigen::VectorXd> B(values_.data() + rows_ * cols_, idx(rows_));
  const Eigen::Map<const Eigen::VectorXd> C(constraint_values_.data(), m);
  B.tail(m) -= two_alpha_ * constraint_rate(t, y) + beta_squared_ * C;
}

double MechanismDynamics::unknowns(double t, const Eigen::VectorXd& y, Eigen::VectorXd& u) const {
  evaluate_rows(t, y);
  std::size_t k = 0;
  for (std::size_t i = 0; i < rows_; ++i)
    for (std::size_t j = 0; j < cols_; ++j) A_(idx(i), idx(j)) = values_[k++];
  for (std::size_t i = 0; i < rows_; ++i) B_[idx(i)] = values_[k++];
  lu_.compute(A_);
  // The pivots' spread, not Eigen's rcond(): a condition estimate costs more solves than
  // the step it guards, and only "singular or not" matters here.
  const double rcond = pivot_spread(lu_);
  if (!(rcond > std::numeric_limits<double>::epsilon())) return 0;  // NaN entries count as singular
  u = lu_.solve(B_);
  return rcond;
}

double MechanismDynamics::structured_unknowns(double t, const Eigen::VectorXd& y, Eigen::VectorXd& u) const {
  evaluate_rows(t, y);
  const auto rows = idx(rows_), n = idx(n_), m = rows - n;
  const Eigen::Map<const Eigen::VectorXd> b(values_.data() + rows_ * cols_, rows);
  if (const std::optional<double> rcond = solve_small(rows_, values_.data(), u)) return *rcond;
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> A(values_.data(), rows,
                                                                                                   rows);
  if (schur_ && mass_diagonal_ && m <= idx(kFixedRows)) return diagonal_schur(u);
  bool mass_solved = false;
  if (schur_ && mass_diagonal_) {
    mass_inverse_ = A.diagonal().head(n).cwiseInverse();
    mass_solved = mass_inverse_.allFinite() && (mass_inverse_.array() > 0).all();
    minv_g_.noalias() = mass_inverse_.asDiagonal() * A.topRightCorner(n, m);
    minv_b_ = mass_inverse_.cwiseProduct(b.head(n));
  } else if (schur_) {
    mass_ldlt_.compute(A.topLeftCorner(n, n));
    mass_solved =
        mass_ldlt_.info() == Eigen::Success && mass_ldlt_.isPositive() &&
        mass_ldlt_.vectorD().minCoeff() > std::numeric_limits<double>::epsilon() * mass_ldlt_.vectorD().maxCoeff();
    if (mass_solved) {
      minv_g_ = mass_ldlt_.solve(A.topRightCorner(n, m));
      minv_b_ = mass_ldlt_.solve(b.head(n));
    }
  }
  if (!mass_solved) return general_unknowns(u);  // no structure, or M not positive definite here
  // A is singular exactly when J M^-1 G is (M is regular here).
  // Row major, then the right-hand side: as solve_small() takes them.
  schur_values_.resize(static_cast<std::size_t>(m * (m + 1)));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> S(schur_values_.data(), m, m);
  Eigen::Map<Eigen::VectorXd> r(schur_values_.data() + m * m, m);
  S.noalias() = A.bottomLeftCorner(m, n).lazyProduct(minv_g_);
  r.noalias() = A.bottomLeftCorner(m, n).lazyProduct(minv_b_);
  r -= b.tail(m);
  double rcond = 0;
  if (const std::optional<double> small = solve_small(static_cast<std::size_t>(m), schur_values_.data(), lambda_)) {
    rcond = *small;
  } else {
    schur_lu_.compute(S);
    rcond = pivot_spread(schur_lu_);
    if (rcond > std::numeric_limits<double>::epsilon()) lambda_ = schur_lu_.solve(r);
  }
  if (!(rcond > std::numeric_limits<double>::epsilon())) return 0;
  u.resize(rows);
  u.tail(m) = lambda_;
  u.head(n) = minv_b_;
  u.head(n).noalias() -= minv_g_.lazyProduct(lambda_);
  return rcond;
}

double MechanismDynamics::general_unknowns(Eigen::VectorXd& u) const {
  const auto rows = idx(rows_);
  const double* b = values_.data() + rows_ * cols_;
  for (Eigen::Index i = 0; i < rows; ++i) B_[i] = b[i];
  A_ = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values_.data(), rows,
                                                                                                rows);
  lu_.compute(A_);
  const double rcond = pivot_spread(lu_);
  if (!(rcond > std::numeric_limits<double>::epsilon())) return 0;
  u = lu_.solve(B_);
  return rcond;
}

bool MechanismDynamics::static_unknowns(double t, const Eigen::VectorXd& y) const {
  if (!compiled_) compile_case();
  // Interpreted too, though there its steps cost more than the A and B program and the
  // compiled LU (a chain of 8: 827 instructions against 593): both evaluators then run the
  // same arithmetic, so a run's numbers do not depend on whether a compiler was found.
  if (solve_.output_count() == 0) return false;
  solve_inputs_[parameters_ + 2 * n_] = t;
  solve_.run(solve_inputs_.data(), y.data(), solve_values_.data(), scratch_.data());
  return pivot_check_.accepts(solve_values_.data() + cols_);
}

double MechanismDynamics::diagonal_schur(Eigen::VectorXd& u) const {
  const std::size_t m = rows_ - n_;
  const double* a = values_.data();
  const double* b = a + rows_ * cols_;
  const auto jac = [&](std::size_t k, std::size_t j) { return a[(n_ + k) * cols_ + j]; };
  mass_inverse_.resize(idx(n_));
  minv_b_.resize(idx(n_));
  for (std::size_t j = 0; j < n_; ++j) {
    const double inverse = 1 / a[j * cols_ + j];
    if (!(inverse > 0 && std::isfinite(inverse))) return general_unknowns(u);  // M not positive definite
    mass_inverse_[idx(j)] = inverse;
    minv_b_[idx(j)] = inverse * b[j];
  }
  // G = s J^T: (J M^-1 J^T) lambda = s (J M^-1 b1 - b2), the upper triangle only.
  std::array<double, kFixedRows * kFixedRows> p;
  std::array<double, kFixedRows> r;
  std::size_t pair = 0;
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t l = k; l < m; ++l, ++pair) {
      double sum = 0;
      for (std::uint32_t c = pair_start_[pair]; c < pair_start_[pair + 1]; ++c) {
        const std::size_t j = pair_columns_[c];
        sum += jac(k, j) * mass_inverse_[idx(j)] * jac(l, j);
      }
      p[k * kFixedRows + l] = sum;
    }
    double sum = 0;
    for (std::uint32_t c = row_start_[k]; c < row_start_[k + 1]; ++c)
      sum += jac(k, row_columns_[c]) * minv_b_[idx(row_columns_[c])];
    r[k] = schur_sign_ * (sum - b[n_ + k]);
  }
  u.resize(idx(rows_));
  const double rcond = solve_symmetric(m, p, r, u.data() + n_, std::make_index_sequence<kFixedRows>{});
  if (!(rcond > 0)) return 0;
  // u1 = M^-1 (b1 - G lambda), G = s J^T.
  for (std::size_t j = 0; j < n_; ++j) u[idx(j)] = 0;
  for (std::size_t k = 0; k < m; ++k)
    for (std::uint32_t c = row_start_[k]; c < row_start_[k + 1]; ++c)
      u[idx(row_columns_[c])] += jac(k, row_columns_[c]) * u[idx(n_ + k)];
  for (std::size_t j = 0; j < n_; ++j) u[idx(j)] = minv_b_[idx(j)] - schur_sign_ * mass_inverse_[idx(j)] * u[idx(j)];
  return rcond;
}

bool MechanismDynamics::derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
  dydt.resize(y.size());
  const bool baumgarte = constraint_rows_ > 0 && (two_alpha_ != 0 || beta_squared_ != 0);
  const bool plain = static_plain_ && structured_ && !baumgarte;
  if (plain) {
    // The common case with nothing else to decide: the static solve's one program, reading
    // q and q' from y itself, and no power to add. Raw pointers: the copies are a handful.
    const std::size_t n = n_;
    const double* in = y.data();
    solve_inputs_[parameters_ + 2 * n] = t;
    solve_.run(solve_inputs_.data(), in, solve_values_.data(), scratch_.data());
    if (pivot_check_.accepts(solve_values_.data() + cols_)) {
      double* out = dydt.data();
      const double* u = solve_values_.data();
      for (std::size_t i = 0; i < n; ++i) out[i] = in[n + i];
      for (std::size_t i = 0; i < n; ++i) out[n + i] = u[i];
      if (y.size() > idx(2 * n)) out[2 * n] = 0;
      return true;
    }
    // Pivots that do not vouch for u: the pivoting LU below decides.
  }
  bool solved = false, rows = true, straight = false;
  if (structured_ && (!tree_ || n_ + static_cast<std::size_t>(constraint_rows_) <= kFixedRows)) {
    // Straight-line code first; where its pivots do not vouch for it, the pivoting LU decides.
    solved = straight = !baumgarte && !plain && static_unknowns(t, y);  // not twice
    if (!straight) solved = structured_unknowns(t, y, u_) > 0;
  } else if (tree_ && !baumgarte) {
    solved = tree_->accelerations(t, y, u_);
    rows = false;
  } else {
    solved = unknowns(t, y, u_) > 0;
  }
  if (!solved) {
    dydt.setConstant(std::numeric_limits<double>::quiet_NaN());
    // A state or rows beyond double range is a step that ran away (the integrator reports
    // it as such), not a matrix that turned singular.
    const auto finite = [](double v) { return std::isfinite(v); };
    return !(y.allFinite() &&
             (!rows || std::all_of(values_.begin(),
                                   values_.begin() + static_cast<std::ptrdiff_t>(rows_ * cols_ + rows_), finite)));
  }
  const double* u = straight ? solve_values_.data() : u_.data();
  // Plain loops: n is a handful, and Eigen's dynamic-size copies cost more than they move.
  for (std::size_t i = 0; i < n_; ++i) {
    dydt[idx(i)] = y[idx(n_ + i)];
    dydt[idx(n_ + i)] = u[i];
  }
  if (y.size() == idx(2 * n_)) return true;  // no W
  if (power_zero_) {
    dydt[idx(2 * n_)] = 0;
  } else {
    fill_inputs(t, y);
    power_.run(inputs_.data(), power_values_.data(), scratch_.data());
    dydt[idx(2 * n_)] = power_values_[0];
  }
  if (drivers_ > 0) {
    if (straight) std::copy_n(u, cols_, u_.data());
    dydt[idx(2 * n_)] += driver_power(t, y, u_);
  }
  return true;
}

double MechanismDynamics::driver_power(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
  // Each driver's multiplier acts as the generalized force lambda dC/dq: its power is
  // lambda (dC/dq) q', the work the motor does as its constraint moves (C_t != 0).
  if (drivers_ == 0) return 0;
  evaluate_time_rates(t, y);
  const std::size_t m = static_cast<std::size_t>(constraint_rows_);
  double power = 0;
  for (std::size_t d = 0; d < drivers_; ++d) power += u[idx(cols_ - drivers_ + d)] * time_rate_values_[m + d];
  return power;
}

double MechanismDynamics::constraint_violation(double t, const Eigen::VectorXd& y) const {
  if (constraint_rows_ == 0) return 0;
  evaluate_constraints(t, y);
  double largest = 0;
  for (double v : constraint_values_) largest = std::max(largest, std::fabs(v));
  return largest;
}

std::string MechanismDynamics::worst_joint(double t, const Eigen::VectorXd& y) const {
  if (constraint_rows_ == 0) return "";
  evaluate_constraints(t, y);
  std::size_t worst = 0;
  for (std::size_t i = 1; i < constraint_values_.size(); ++i)
    if (std::fabs(constraint_values_[i]) > std::fabs(constraint_values_[worst])) worst = i;
  return system_->mechanism().joints[static_cast<std::size_t>(constraint_joint_[worst])].name;
}

double MechanismDynamics::project(double t, Eigen::VectorXd& y) const {
  if (constraint_rows_ == 0) return 0;
  const auto m = static_cast<Eigen::Index>(constraint_rows_);
  const auto n = idx(n_);
  Eigen::Map<const Eigen::VectorXd> C(constraint_values_.data(), m);
  // Round-off of the coordinates: Newton stops when |C| is there or stops falling.
  const double floor = 4 * std::numeric_limits<double>::epsilon() * (1 + y.head(n).cwiseAbs().maxCoeff());
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    evaluate_constraints(t, y);
    const double violation = C.cwiseAbs().maxCoeff();
    if (!(violation > floor) || !(violation < 0.5 * previous)) break;
    previous = violation;
    const Eigen::LDLT<Eigen::MatrixXd> metric(M_);
    const Eigen::MatrixXd MinvJt = metric.solve(J_.transpose());
    const Eigen::VectorXd lambda = (J_ * MinvJt).fullPivLu().solve(C);
    y.head(n) -= MinvJt * lambda;
  }
  evaluate_constraints(t, y);
  const Eigen::LDLT<Eigen::MatrixXd> metric(M_);
  const Eigen::MatrixXd MinvJt = metric.solve(J_.transpose());
  const Eigen::VectorXd rate = constraint_rate(t, y);
  y.segment(n, n) -= MinvJt * (J_ * MinvJt).fullPivLu().solve(rate);
  return C.cwiseAbs().maxCoeff();
}

bool MechanismDynamics::close_positions(double t, Eigen::VectorXd& y) const {
  const auto n = idx(n_);
  const Eigen::Map<const Eigen::VectorXd> C(constraint_values_.data(), n);
  // Round-off of the coordinates: Newton is done when |C| or its step is there.
  const double floor = 4 * std::numeric_limits<double>::epsilon() * (1 + y.head(n).cwiseAbs().maxCoeff());
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < 2 * kProjectionIterations; ++iteration) {
    evaluate_constraints(t, y);
    const double residual = C.cwiseAbs().maxCoeff();
    if (!std::isfinite(residual)) return false;
    if (residual <= floor) return true;
    // Quadratic convergence halves |C| at least; stalling above round-off means no root near.
    if (iteration > 2 && !(residual < 0.5 * previous)) return residual <= 1e3 * floor;
    previous = residual;
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J_);
    if (!lu.isInvertible()) return false;
    y.head(n) -= lu.solve(C);
  }
  return false;
}

void MechanismDynamics::solve_rates(double t, Eigen::VectorXd& y) const {
  evaluate_constraints(t, y);
  evaluate_time_rates(t, y);
  const Eigen::Map<const Eigen::VectorXd> c_t(time_rate_values_.data(), idx(n_));
  y.segment(idx(n_), idx(n_)) = J_.fullPivLu().solve(-c_t);
}

double MechanismDynamics::jacobian_spread(double t, const Eigen::VectorXd& y) const {
  if (constraint_rows_ == 0) return 1;
  evaluate_constraints(t, y);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J_);
  const auto& s = svd.singularValues();
  return s.size() == 0 || !(s[0] > 0) ? 0.0 : s[s.size() - 1] / s[0];
}

Program MechanismDynamics::compile_over_state(const std::vector<GiNaC::ex>& values) const {
  std::vector<ex> prepared;
  prepared.reserve(values.size());
  for (const ex& e : values) prepared.push_back(prepare(e));
  return compile(prepared, input_symbols_);
}

void MechanismDynamics::evaluate_over_state(const Program& program, double t, const Eigen::VectorXd& y, double* out,
                                            double* scratch) const {
  fill_inputs(t, y);
  program.run(inputs_.data(), out, scratch);
}

int MechanismDynamics::jacobian_sign(double t, const Eigen::VectorXd& y) const {
  evaluate_constraints(t, y);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J_);
  int sign = static_cast<int>(lu.permutationP().determinant());
  for (Eigen::Index i = 0; i < lu.matrixLU().rows(); ++i) {
    const double pivot = lu.matrixLU()(i, i);
    if (!(pivot != 0)) return 0;
    if (pivot < 0) sign = -sign;
  }
  return sign;
}

void MechanismDynamics::sample(double t, const Eigen::VectorXd& y, MechanismSample& out, bool kinematics) const {
  compile_case();
  if (kinematics) compile_kinematics();
  Eigen::VectorXd u;
  const bool solved = unknowns(t, y, u) > 0;
  fill_inputs(t, y);
  std::copy(inputs_.begin(), inputs_.end(), output_inputs_.begin());
  for (std::size_t i = 0; i < cols_; ++i)
    output_inputs_[inputs_.size() + i] = solved ? u[idx(i)] : std::numeric_limits<double>::quiet_NaN();
  std::vector<double> values(outputs_.output_count());
  std::vector<double> scratch(outputs_.scratch_size());
  outputs_.run(output_inputs_.data(), values.data(), scratch.data());
  std::size_t k = 0;
  out.pose.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(3 * bodies_));
  k += 3 * bodies_;
  out.rates.assign(values.begin() + static_cast<std::ptrdiff_t>(k),
                   values.begin() + static_cast<std::ptrdiff_t>(k + 3 * bodies_));
  k += 3 * bodies_;
  out.slider.assign(joints_, 0.0);
  out.force.assign(5 * joints_, 0.0);
  out.constraint.assign(joints_, 0.0);
  out.constraint_rate.assign(joints_, 0.0);
  for (std::size_t j = 0; j < joints_; ++j) {
    out.slider[j] = values[k++];
    for (std::size_t c = 0; c < 3; ++c) out.force[3 * j + c] = values[k++];
    for (std::size_t c = 0; c < 2; ++c) out.force[3 * joints_ + 2 * j + c] = values[k++];
    const std::size_t rows = joint_rows_[j];
    for (std::size_t r = 0; r < rows; ++r) {
      out.constraint[j] = std::hypot(out.constraint[j], values[k + r]);
      out.constraint_rate[j] = std::hypot(out.constraint_rate[j], values[k + rows + r]);
    }
    k += 2 * rows;
  }
  out.kinetic = values[k++];
  out.potential = values[k++];
  out.power = values[k++];
  out.momentum_x = values[k++];
  out.momentum_y = values[k++];
  out.angular_momentum = values[k++];
  for (double& v : out.com) v = values[k++];
  for (double& v : out.shaking) v = values[k++];
  // The drivers' torques and forces: the case's last unknowns in every case.
  out.drivers.assign(drivers_, std::numeric_limits<double>::quiet_NaN());
  if (solved)
    for (std::size_t d = 0; d < drivers_; ++d) out.drivers[d] = u[idx(cols_ - drivers_ + d)];
  if (!kinematics) return;
  values.resize(kinematics_.output_count());
  scratch.resize(kinematics_.scratch_size());
  kinematics_.run(output_inputs_.data(), values.data(), scratch.data());
  const auto at = [&](std::size_t i) { return values.begin() + static_cast<std::ptrdiff_t>(i); };
  out.accelerations.assign(at(0), at(3 * bodies_));
  out.slider_accelerations.assign(at(3 * bodies_), at(3 * bodies_ + joints_));
  out.points.assign(at(3 * bodies_ + joints_), values.end());
}

}  // namespace linkage::eval
