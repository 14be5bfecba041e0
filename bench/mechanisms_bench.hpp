#pragma once
// `linkage bench mechanisms`: the cost of any mechanism's motion, as ratios in one run.
//   1. Nanoseconds per right-hand side for every shipped mechanism and case on both paths:
//      the evaluator (the interpreter of evaluate/program.hpp) and the compiled one (the
//      native code built into the program); the closed form beside them for the homework.
//   2. A pendulum chain of n rods, n = 2 ... 64: Case 3 by the tree's O(n) recursion on
//      both paths (the chains are not shipped: compiled at run time through the cache
//      simulate uses) against MuJoCo's mj_forward on the same chain.
//   3. Work against precision on the double pendulum to t = 10 s: our integrators on the
//      compiled path, Boost.Odeint with the right-hand side a user writes, MuJoCo's RK4 and Euler.
// Targets (issue 24): compiled / closed form on the homework's Case 3 <= 1.3x; four-bar
// Case 1 <= 400 ns, Case 3 <= 200 ns; chain 32 at least 10x faster than mj_forward; chain
// 64 / chain 8 <= 9x; error 1e-8 at t = 10 s at least 15x faster than MuJoCo's RK4 at its
// best step and faster than Odeint's best.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace linkage::bench {

inline constexpr double kMaxCompiledOverClosed = 1.3;
inline constexpr double kMaxFourBarCase1Ns = 400;
inline constexpr double kMaxFourBarCase3Ns = 200;
inline constexpr double kMinSpeedupOverMujocoChain32 = 10.0;
inline constexpr double kMaxChainGrowth = 9.0;  // 64 links over 8
inline constexpr double kMinSpeedupOverMujocoRk4 = 15.0;
inline constexpr double kMinSpeedupOverOdeint = 1.0;
inline constexpr double kPendulumTargetError = 1e-8;

struct MechanismsBenchOptions {
  std::filesystem::path out = "bench-mechanisms";
  bool quick = false;  // chains to 8 links, few settings, short batches: checks the report, not the timings
  bool quiet = false;
};

/// One row of mechanisms.csv: `path` is evaluator, compiled, closed-form or mujoco.
struct RhsRow {
  std::string mechanism;
  int case_id = 3;
  std::string path;
  int bodies = 0;
  double ns_per_rhs = 0;  // this thread's CPU time, median of batches
};

/// One run of the work-precision study.
struct WorkPoint {
  std::string method;  // "ours dop853", "odeint rkf78", "mujoco rk4"
  double setting = 0;  // tolerance, or step in s
  double seconds = 0;  // the integration alone, this thread's CPU time
  double error = 0;    // max |delta theta| at t = 10 s, rad
};

struct TargetLine {
  std::string target, measured, goal;
  bool met = false;
  std::string note;  // why, when missed or not measured
};

struct MechanismsBenchResult {
  std::vector<RhsRow> rows;
  std::vector<WorkPoint> work;
  double reference_check = 0;  // |Case 3 - Case 2| of the reference at t = 10 s, rad
  /// ns per right-hand side on the compiled path with the general LU
  /// (MechanismDynamics::solve_by_structure(false)), by "mechanism Case N", for the notes.
  std::map<std::string, double> structured;
  std::vector<TargetLine> targets;
  std::vector<std::string> lines;  // the terminal summary
  std::vector<std::filesystem::path> files;
};

/// A chain of `links` uniform rods (0.3 m, 0.1 kg) hanging from a ground pin, as a
/// mechanism file's text: the chain MuJoCo is given in the same study.
[[nodiscard]] std::string pendulum_chain_toml(int links);

[[nodiscard]] MechanismsBenchResult run_mechanisms_bench(const MechanismsBenchOptions& options);

/// `linkage bench accuracy --mechanism NAME|FILE`: every integrator of ours in every
/// chosen case against a reference at rtol = atol = 1e-14 (DOP853, Case 3), itself
/// checked by a second set of equations (Case 2) and a second method (Gauss-Legendre).
struct MechanismAccuracyOptions {
  std::string mechanism;
  std::vector<int> cases{1, 2, 3};
  double duration = 10;  // s
  std::filesystem::path out = "bench-accuracy";
  bool quick = false;  // few settings, 1 s: checks the report, not the findings
  bool quiet = false;
};

struct MechanismAccuracyResult {
  std::vector<WorkPoint> work;  // method "Case N integrator"; error: max |pose - reference| of every body, m or rad
  double second_equations = 0;  // |reference - Case 2 at 1e-14|
  double second_method = 0;     // |reference - Gauss-Legendre|
  std::string path;             // what computed each case's equations: "Case 3: compiled (built in); ..."
  std::vector<std::string> lines;
  std::vector<std::filesystem::path> files;
};

[[nodiscard]] MechanismAccuracyResult run_mechanism_accuracy(const MechanismAccuracyOptions& options);

}  // namespace linkage::bench
