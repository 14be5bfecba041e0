// SUNDIALS peers (Debian's libsundials-dev, 6.4):
//   CVODE, Adams-Moulton (orders 1-12) with the fixed-point nonlinear solver, the
//   library's recommendation for non-stiff problems, on Case 3;
//   IDA, variable-order BDF with a dense direct linear solver and its difference-
//   quotient Jacobian, on Case 1.
// IDA with the user's residual solves Case 1 as the DAE a user would write down:
// y = (x1, y1, th1, x2, y2, th2, their rates, Fx, Fy), the six Newton-Euler rows and
// the pin constraint at acceleration level (rows 7.1, 8.1), Fx and Fy algebraic. That
// is an index-1 DAE: IDA's Newton matrix is the Case 1 matrix, nonsingular. Like our
// Case 1 without stabilization, the positions may drift off the pin constraint; the
// study reports that drift. IDA with our right-hand side integrates y' = f(y) of Case 1
// (accelerations from our block solve) written as the implicit ODE y' - f(y) = 0.
// Every object is owned by a unique_ptr with the library's destructor; the library's
// error printer is silenced and a failing flag becomes the run's failure text.
#include <cvode/cvode.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <memory>
#include <string>

#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/method.hpp"
#include "bench/rhs.hpp"

namespace linkage::bench {
namespace {

// --- RAII for the C handles ---------------------------------------------------------
struct ContextDeleter {
  void operator()(SUNContext c) const { SUNContext_Free(&c); }
};
struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct CvodeDeleter {
  void operator()(void* mem) const { CVodeFree(&mem); }
};
struct IdaDeleter {
  void operator()(void* mem) const { IDAFree(&mem); }
};
struct NonlinearSolverDeleter {
  void operator()(SUNNonlinearSolver s) const { SUNNonlinSolFree(s); }
};
struct LinearSolverDeleter {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
using Context = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using CvodeMem = std::unique_ptr<void, CvodeDeleter>;
using IdaMem = std::unique_ptr<void, IdaDeleter>;
using NonlinearSolver = std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, NonlinearSolverDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;

Context make_context() {
  SUNContext c = nullptr;
  if (SUNContext_Create(nullptr, &c) != 0) throw std::runtime_error("SUNContext_Create failed");
  return Context(c);
}

/// Throws with the call's name and flag when a SUNDIALS call fails.
void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string(call) + " returned flag " + std::to_string(flag));
}

void silent_cvode(int, const char*, const char*, char*, void*) {}
void silent_ida(int, const char*, const char*, char*, void*) {}

constexpr long kMaxSteps = 50'000'000;  // users raise the default of 500 for long runs

/// Records how a solver's run ended and its step counts (CVode*/IDA* getters).
template <class Getter>
void record_run(Outcome& out, void* mem, const char* solver, int flag, sunrealtype t, Getter get_steps,
                Getter get_error_test_fails) {
  if (flag < 0)
    out.failure = std::string(solver) + " returned flag " + std::to_string(flag) + " at t = " + std::to_string(t);
  long steps = 0, fails = 0;
  check(get_steps(mem, &steps), "getting the step count");
  check(get_error_test_fails(mem, &fails), "getting the error test failures");
  out.steps = steps;
  out.rejected = fails;
}

// --- CVODE on Case 3 ------------------------------------------------------------------
struct CvodeData {
  UserConstants user;
  Case3Fast<double> ours;
  std::int64_t count = 0;
};

int cvode_user_rhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
  auto* d = static_cast<CvodeData*>(data);
  ++d->count;
  user_case3_rhs(d->user, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}
int cvode_our_rhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
  auto* d = static_cast<CvodeData*>(data);
  ++d->count;
  const double* in = N_VGetArrayPointer(y);
  double* out = N_VGetArrayPointer(ydot);
  d->ours.rhs(in, out);
  return 0;
}

Outcome run_cvode(const Scenario& scenario, double tol, RhsKind rhs) {
  Outcome out;
  CvodeData data{UserConstants(scenario.params), Case3Fast<double>(scenario.params)};
  const Context ctx = make_context();
  const Vector y(N_VNew_Serial(8, ctx.get()));
  const Vec<8> y0 = scenario.initial.vector();
  double* yp = N_VGetArrayPointer(y.get());
  for (int i = 0; i < 8; ++i) yp[i] = y0[i];
  try {
    const CvodeMem mem(CVodeCreate(CV_ADAMS, ctx.get()));
    if (!mem) throw std::runtime_error("CVodeCreate failed");
    check(CVodeSetErrHandlerFn(mem.get(), silent_cvode, nullptr), "CVodeSetErrHandlerFn");
    check(CVodeInit(mem.get(), rhs == RhsKind::user ? cvode_user_rhs : cvode_our_rhs, 0.0, y.get()), "CVodeInit");
    check(CVodeSetUserData(mem.get(), &data), "CVodeSetUserData");
    check(CVodeSStolerances(mem.get(), tol, tol), "CVodeSStolerances");
    check(CVodeSetMaxNumSteps(mem.get(), kMaxSteps), "CVodeSetMaxNumSteps");
    const NonlinearSolver nls(SUNNonlinSol_FixedPoint(y.get(), 0, ctx.get()));
    check(CVodeSetNonlinearSolver(mem.get(), nls.get()), "CVodeSetNonlinearSolver");
    sunrealtype t = 0;
    const int flag = CVode(mem.get(), scenario.duration, y.get(), &t, CV_NORMAL);
    record_run(out, mem.get(), "CVode", flag, t, CVodeGetNumSteps, CVodeGetNumErrTestFails);
  } catch (const std::exception& e) {
    out.failure = e.what();
  }
  Vec<8> final;
  for (int i = 0; i < 8; ++i) final[i] = yp[i];
  out.final = body_state(scenario.params, State::from_vector(final));
  out.rhs_evaluations = data.count;
  return out;
}

// --- IDA on Case 1 --------------------------------------------------------------------
struct IdaData {
  UserConstants user;
  MaximalRhs ours;
  std::int64_t count = 0;
};

// The DAE as a user types it from the spec (sec. 3, corrected per docs/errata.md).
int ida_user_residual(sunrealtype /*t*/, N_Vector yy, N_Vector yp, N_Vector rr, void* data) {
  auto* d = static_cast<IdaData*>(data);
  ++d->count;
  const double* y = N_VGetArrayPointer(yy);
  const double* v = N_VGetArrayPointer(yp);
  double* r = N_VGetArrayPointer(rr);
  const double m = d->user.m, I = d->user.I, D = d->user.D, g = d->user.g;
  const double s1 = std::sin(y[2]), c1 = std::cos(y[2]), s2 = std::sin(y[5]), c2 = std::cos(y[5]);
  const double w1 = y[8], w2 = y[11], Fx = y[12], Fy = y[13];
  for (int i = 0; i < 6; ++i) r[i] = v[i] - y[i + 6];
  r[6] = m * v[6] - Fx;
  r[7] = m * v[7] - Fy + m * g;
  r[8] = I * v[8] + D * s1 * Fx - D * c1 * Fy;
  r[9] = m * v[9] + Fx;
  r[10] = m * v[10] + Fy + m * g;
  r[11] = I * v[11] + D * s2 * Fx - D * c2 * Fy;
  r[12] = v[6] - D * s1 * v[8] - v[9] - D * s2 * v[11] - D * (w1 * w1 * c1 + w2 * w2 * c2);
  r[13] = v[7] + D * c1 * v[8] - v[10] + D * c2 * v[11] - D * (w1 * w1 * s1 + w2 * w2 * s2);
  return 0;
}

// y' - f(y) = 0 with our Case 1 right-hand side.
int ida_our_residual(sunrealtype /*t*/, N_Vector yy, N_Vector yp, N_Vector rr, void* data) {
  auto* d = static_cast<IdaData*>(data);
  ++d->count;
  const Eigen::Map<const Vec<12>> y(N_VGetArrayPointer(yy));
  const Eigen::Map<const Vec<12>> v(N_VGetArrayPointer(yp));
  Eigen::Map<Vec<12>> r(N_VGetArrayPointer(rr));
  Vec<12> f;
  d->ours(0.0, y, f);
  if (!f.allFinite()) return -1;  // IDA treats a negative return as unrecoverable
  r = v - f;
  return 0;
}

Outcome run_ida(const Scenario& scenario, double tol, RhsKind rhs) {
  Outcome out;
  IdaData data{UserConstants(scenario.params), MaximalRhs(scenario.params, 0.0, 0.0)};
  const int n = rhs == RhsKind::user ? 14 : 12;
  const Context ctx = make_context();
  const Vector yy(N_VNew_Serial(n, ctx.get())), yp(N_VNew_Serial(n, ctx.get())), id(N_VNew_Serial(n, ctx.get()));
  double* y = N_VGetArrayPointer(yy.get());
  double* v = N_VGetArrayPointer(yp.get());
  double* is_differential = N_VGetArrayPointer(id.get());
  // Consistent initial values: the state on the constraint, its derivative and the pin
  // force from the Case 1 equations.
  const Vec<12> y0 = body_state(scenario.params, scenario.initial).vector();
  Vec<12> f0;
  data.ours(0.0, y0, f0);
  for (int i = 0; i < 12; ++i) y[i] = y0[i], v[i] = f0[i], is_differential[i] = 1.0;
  if (n == 14) {
    const double m = scenario.params.m;
    y[12] = m * f0[6];                        // Fx = m x1''      (1.1)
    y[13] = m * (f0[7] + scenario.params.g);  // Fy = m (y1'' + g) (2.1)
    v[12] = v[13] = 0.0;                      // not used: Fx, Fy are algebraic
    is_differential[12] = is_differential[13] = 0.0;
  }
  try {
    const IdaMem mem(IDACreate(ctx.get()));
    if (!mem) throw std::runtime_error("IDACreate failed");
    check(IDASetErrHandlerFn(mem.get(), silent_ida, nullptr), "IDASetErrHandlerFn");
    check(IDAInit(mem.get(), rhs == RhsKind::user ? ida_user_residual : ida_our_residual, 0.0, yy.get(), yp.get()),
          "IDAInit");
    check(IDASetUserData(mem.get(), &data), "IDASetUserData");
    check(IDASStolerances(mem.get(), tol, tol), "IDASStolerances");
    check(IDASetId(mem.get(), id.get()), "IDASetId");
    check(IDASetMaxNumSteps(mem.get(), kMaxSteps), "IDASetMaxNumSteps");
    const Matrix A(SUNDenseMatrix(n, n, ctx.get()));
    const LinearSolver ls(SUNLinSol_Dense(yy.get(), A.get(), ctx.get()));
    check(IDASetLinearSolver(mem.get(), ls.get(), A.get()), "IDASetLinearSolver");
    sunrealtype t = 0;
    const int flag = IDASolve(mem.get(), scenario.duration, &t, yy.get(), yp.get(), IDA_NORMAL);
    record_run(out, mem.get(), "IDASolve", flag, t, IDAGetNumSteps, IDAGetNumErrTestFails);
  } catch (const std::exception& e) {
    out.failure = e.what();
  }
  Vec<12> final;
  for (int i = 0; i < 12; ++i) final[i] = y[i];
  out.final = BodyState::from_vector(final);
  out.rhs_evaluations = data.count;
  return out;
}

}  // namespace

std::vector<Method> sundials_methods() {
  std::vector<Method> out;
  for (RhsKind rhs : {RhsKind::user, RhsKind::fastest}) {
    Method m;
    m.id = "cvode-adams";
    m.library = "SUNDIALS";
    m.label = "CVODE Adams";
    m.case_id = 3;
    m.rhs = rhs;
    m.adaptive = true;
    m.run = [rhs](const Scenario& s, double tol) { return run_cvode(s, tol, rhs); };
    out.push_back(m);
  }
  for (RhsKind rhs : {RhsKind::user, RhsKind::fastest}) {
    Method m;
    m.id = "ida";
    m.library = "SUNDIALS";
    m.label = "IDA";
    m.case_id = 1;
    m.rhs = rhs;
    m.adaptive = true;
    m.run = [rhs](const Scenario& s, double tol) { return run_ida(s, tol, rhs); };
    out.push_back(m);
  }
  return out;
}

}  // namespace linkage::bench
