#pragma once
// A method of the work-precision study: one integrator (ours or a peer library's), on
// one case, with one right-hand side, run over a scenario at one setting of its
// accuracy knob (a tolerance for adaptive methods, a step count for fixed-step ones).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/closed_form/state.hpp"
#include "bench/scenarios.hpp"

namespace linkage::bench {

/// What one run produced.
struct Outcome {
  BodyState final;                       // the state at the scenario's duration
  std::int64_t rhs_evaluations = 0;      // right-hand side (or DAE residual) evaluations
  std::int64_t steps = 0;                // accepted steps
  std::optional<std::int64_t> rejected;  // rejected step attempts, when the library reports them
  std::string failure;                   // empty when the run reached the end
};

/// Which right-hand side a run uses.
enum class RhsKind {
  fastest,     // ours: the closed-form Case 3 (case3_fast.hpp); Cases 1, 2: the block solve
  definition,  // ours: the formulation's matrices + block solve (what every case shares)
  user,        // what a user of the library writes: Eigen fixed-size partial-pivot LU
  general,     // ours: the general path, two-blocks.toml's Case 3 as simulate runs it (general_rhs.hpp)
};
[[nodiscard]] const char* name(RhsKind kind);

struct Method {
  std::string id;       // unique, for the CSV and --integrators: e.g. "dop853", "odeint-rkf78"
  std::string library;  // "linkage", "Boost.Odeint", "SUNDIALS"
  std::string label;    // legend text, e.g. "Odeint RKF78"
  int case_id = 3;
  RhsKind rhs = RhsKind::fastest;
  bool adaptive = true;
  int order = 0;  // of the method (fixed-step ones: sets the step counts tried)
  /// Runs the scenario with `knob` = the tolerance (rtol = atol) or the step count.
  std::function<Outcome(const Scenario&, double knob)> run;
};

/// A peer library of the study. Each is compiled in only when CMake found it.
struct PeerLibrary {
  std::string library;           // Method::library of its methods
  std::string integrators;       // for people: "CVODE, IDA"
  std::string package;           // the Debian package that provides it
  std::vector<std::string> ids;  // its Method::id values
  bool built = false;            // compiled into this build
  /// "peer SUNDIALS (CVODE, IDA) not built: install libsundials-dev and re-run cmake"
  [[nodiscard]] std::string not_built_note() const;
};
/// Every peer library, built or not: Boost.Odeint, SUNDIALS.
[[nodiscard]] std::vector<PeerLibrary> peer_libraries();
/// The library names of the peers this build does not have.
[[nodiscard]] std::vector<std::string> peers_not_built();

/// Our integrators on one case (its fastest right-hand side), in the order of
/// integrate/simulation_options.hpp's integrators().
[[nodiscard]] std::vector<Method> linkage_methods(int case_id);
/// Boost.Odeint RKF78, Dopri5 (dense output) and Bulirsch-Stoer on Case 3, each with
/// the user's and with our right-hand side. Defined only when Boost is built in.
[[nodiscard]] std::vector<Method> odeint_methods();
/// SUNDIALS CVODE (Adams) on Case 3 and IDA on Case 1, each with the user's and with
/// our right-hand side. Defined only when SUNDIALS is built in.
[[nodiscard]] std::vector<Method> sundials_methods();
/// The methods of the peers this build has: Boost.Odeint RKF78, Dopri5 (dense output),
/// Bulirsch-Stoer and SUNDIALS CVODE (Adams) on Case 3, SUNDIALS IDA on Case 1; each
/// with the user's and with our right-hand side.
[[nodiscard]] std::vector<Method> peer_methods();

}  // namespace linkage::bench
