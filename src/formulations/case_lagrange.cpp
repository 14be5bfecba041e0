// Case 3 in Lagrange's form, as a lecturer writes it on the board: one row per generalized
// coordinate q_i of the spanning tree,
//   d/dt (dT/dq_i') - dT/dq_i = Q_i   =>   sum_j M_ij(q) q_j'' = Q_i(q, q', t),
// M_ij = d(dT/dq_i')/dq_j' (symmetric), Q_i = sum_k F_k . dv_k/dq_i' + M_k dw_k/dq_i' over
// every load (gravity, springs and dampers with their length symbols, applied loads) less
// the velocity terms of T. A loop-closing joint's force is one more load, J^T lambda with
// its force components as lambda (Case 3's unknowns), and its constraint at the
// acceleration level one more row, J q'' = -J' q'; a driver's likewise, its torque or
// force lambda one more load, lambda dC/dq. Trigonometry contracted:
// sin a sin b + cos a cos b = cos(a - b) and the like.
#include <algorithm>
#include <map>

#include "formulations/case_system.hpp"
#include "symbolic/energy.hpp"
#include "symbolic/joints.hpp"

namespace linkage {

namespace {

using GiNaC::ex;

// A product's numeric factor, its other factors, and its sin/cos factors of power one.
struct Term {
  GiNaC::numeric number = 1;
  ex rest = 1;
  std::vector<ex> trig;
};

bool is_trig(const ex& e) {
  if (!GiNaC::is_a<GiNaC::function>(e)) return false;
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  return name == "sin" || name == "cos";
}

Term split(const ex& term) {
  Term out;
  const auto factor = [&](const ex& f) {
    if (GiNaC::is_a<GiNaC::numeric>(f))
      out.number *= GiNaC::ex_to<GiNaC::numeric>(f);
    else if (is_trig(f))
      out.trig.push_back(f);
    else
      out.rest *= f;
  };
  if (GiNaC::is_a<GiNaC::mul>(term))
    for (std::size_t i = 0; i < term.nops(); ++i) factor(term.op(i));
  else
    factor(term);
  return out;
}

bool is_sin(const ex& f) { return GiNaC::ex_to<GiNaC::function>(f).get_name() == "sin"; }

// Whether argument `a` comes before `b` in print: by the ranks of their symbols (θ₁ before
// θ₂), a stable order where GiNaC's own follows hash values that change from run to run.
bool before(const ex& a, const ex& b, const sym::SymbolTable& table) {
  const auto ranks = [&](const ex& e) {
    std::vector<int> out;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
      if (GiNaC::is_a<GiNaC::symbol>(*it)) {
        const sym::SymbolInfo* info = table.find(GiNaC::ex_to<GiNaC::symbol>(*it));
        out.push_back(info == nullptr ? 0 : info->rank);
      }
    std::sort(out.begin(), out.end());
    return out;
  };
  return ranks(a) < ranks(b);
}

// Sums of products of sin and cos of two different arguments with equal coefficients,
// contracted: sin a sin b + cos a cos b = cos(a - b), cos a cos b - sin a sin b =
// cos(a + b), sin a cos b - cos a sin b = sin(a - b), sin a cos b + cos a sin b = sin(a + b).
ex contract_trig(const ex& e, const sym::SymbolTable& table) {
  const ex expanded = GiNaC::expand(e);
  std::vector<ex> terms;
  if (GiNaC::is_a<GiNaC::add>(expanded))
    for (std::size_t i = 0; i < expanded.nops(); ++i) terms.push_back(expanded.op(i));
  else
    terms.push_back(expanded);
  // Per (rest, a, b), a before b: the coefficients of sin a sin b, cos a cos b, sin a cos
  // b and cos a sin b.
  enum { ss, cc, sc, cs };
  std::map<ex, std::array<GiNaC::numeric, 4>, GiNaC::ex_is_less> pairs;
  ex out = 0;
  for (const ex& t : terms) {
    const Term term = split(t);
    if (term.trig.size() != 2 || term.trig[0].op(0).is_equal(term.trig[1].op(0))) {
      out += t;
      continue;
    }
    const bool swap = before(term.trig[1].op(0), term.trig[0].op(0), table);
    const ex& fa = term.trig[swap ? 1 : 0];
    const ex& fb = term.trig[swap ? 0 : 1];
    const int kind = is_sin(fa) ? (is_sin(fb) ? ss : sc) : (is_sin(fb) ? cs : cc);
    pairs[GiNaC::lst{term.rest, fa.op(0), fb.op(0)}][static_cast<std::size_t>(kind)] += term.number;
  }
  for (auto& [key, k] : pairs) {
    const ex &rest = key.op(0), &a = key.op(1), &b = key.op(2);
    if (!k[ss].is_zero() && k[ss] == k[cc]) {
      out += k[cc] * rest * GiNaC::cos(a - b);
      k[ss] = k[cc] = 0;
    } else if (!k[ss].is_zero() && k[ss] == -k[cc]) {
      out += k[cc] * rest * GiNaC::cos(a + b);
      k[ss] = k[cc] = 0;
    }
    if (!k[sc].is_zero() && k[sc] == -k[cs]) {
      out += k[sc] * rest * GiNaC::sin(a - b);
      k[sc] = k[cs] = 0;
    } else if (!k[sc].is_zero() && k[sc] == k[cs]) {
      out += k[sc] * rest * GiNaC::sin(a + b);
      k[sc] = k[cs] = 0;
    }
    out += k[ss] * rest * GiNaC::sin(a) * GiNaC::sin(b) + k[cc] * rest * GiNaC::cos(a) * GiNaC::cos(b) +
           k[sc] * rest * GiNaC::sin(a) * GiNaC::cos(b) + k[cs] * rest * GiNaC::cos(a) * GiNaC::sin(b);
  }
  return out;
}

// A force at a world point and a couple, on one body: a load, or a loop-closing joint's
// force on one of its bodies.
struct Application {
  int body = -1;
  sym::Vec2 force, at;
  ex moment = 0;
};

std::vector<Application> applications(const sym::System& system) {
  std::vector<Application> out;
  for (const sym::Load& load : system.loads()) out.push_back({load.body, load.force, load.point, load.moment});
  for (const sym::DriverSystem& d : system.drivers())  // lambda dC/dq
    for (const sym::Load& load : d.loads) out.push_back({load.body, load.force, load.point, load.moment});
  // A loop-closing joint's force on both its bodies, as Newton-Euler applies it.
  const Mechanism& m = system.mechanism();
  for (int j : system.tree().loop_joints) {
    const sym::JointSystem& js = system.joints()[static_cast<std::size_t>(j)];
    const Joint& joint = m.joints[static_cast<std::size_t>(j)];
    const int a = m.body_index(joint.bodies[0]), b = m.body_index(joint.bodies[1]);
    const auto [at_a, at_b] = sym::force_points(system, j);
    out.push_back({a, js.force, at_a, js.moment});
    out.push_back({b, ex(-1) * js.force, at_b, -js.moment});
  }
  return out;
}

}  // namespace

CaseSystem lagrange_case(const sym::System& system) {
  const GiNaC::exmap& to_q = system.to_generalized();
  const auto in_q = [&](const ex& e) { return GiNaC::expand(e.subs(to_q)); };
  const ex T = in_q(sym::kinetic_energy(system));
  const std::vector<Application> loads = applications(system);
  const auto& coordinates = system.coordinates();

  std::vector<ex> rows;
  for (const sym::GeneralizedCoordinate& g : coordinates) {
    const GiNaC::symbol& rate = g.symbols.q_dot;
    ex Q = 0;
    for (const Application& load : loads) {
      if (load.body < 0) continue;
      const sym::BodySystem& b = system.bodies()[static_cast<std::size_t>(load.body)];
      // The velocity of the material point at `at` and the body's angular velocity.
      sym::Vec2 v{b.x.q_dot, b.y.q_dot};
      if (b.rotates) v = v + sym::Vec2{-b.theta.q_dot * (load.at.y - b.y.q), b.theta.q_dot * (load.at.x - b.x.q)};
      Q += in_q(load.force.x) * in_q(v.x).diff(rate) + in_q(load.force.y) * in_q(v.y).diff(rate);
      if (b.rotates) Q += in_q(load.moment) * in_q(b.theta.q_dot).diff(rate);
    }
    rows.push_back(system.time_derivative(T.diff(rate)) - T.diff(g.symbols.q) - Q);
  }
  for (int j : system.tree().loop_joints)
    for (const ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints)
      rows.push_back(system.time_derivative(system.time_derivative(in_q(phi))));
  for (const sym::DriverSystem& d : system.drivers())
    rows.push_back(system.time_derivative(system.time_derivative(in_q(d.constraint))));

  CaseSystem reduced = reduced_case(system);  // the same unknowns; what it recovers from them
  CaseSystem out = linear_system(CaseId::reduced, rows, reduced.unknowns);
  for (auto& row : out.A)
    for (ex& e : row) e = contract_trig(e, system.table());
  for (ex& e : out.B) e = contract_trig(e, system.table());
  for (std::size_t r = 0; r < out.labels.size(); ++r) out.labels[r] = std::to_string(r + 1) + ".L";
  out.recovered = std::move(reduced.recovered);
  // "M symmetric" and what lambda is fit one 80-column heading only without loops.
  const bool loops = !system.tree().loop_joints.empty(), drivers = !system.drivers().empty();
  const std::string kept = loops ? (drivers ? "loop and driver rows" : "loop rows") : "driver rows";
  out.title =
      count_word(rows.size()) + (!loops && !drivers ? " equations in Lagrange's form M(q) q'' = Q, M symmetric"
                                                    : " equations, Lagrange's form M(q) q'' = Q + J^T lambda, " + kept);
  return out;
}

}  // namespace linkage
