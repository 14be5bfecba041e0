#pragma once
// How a run is integrated, whatever the mechanism: the case, the integrator and its
// step and tolerances, the stabilization, the duration; their names and ranges.
#include <array>
#include <string>
#include <string_view>

namespace linkage {

enum class IntegratorKind { euler, symplectic_euler, rk4, dopri5, dop853, vern7, gauss2 };
enum class Stabilization { none, baumgarte, projection };
/// What computes the equations: native code (built in, else compiled at run time) or the
/// interpreter of evaluate/program.hpp; automatic picks (mechanism_simulation.cpp).
enum class Evaluator { automatic, compiled, interpreted };

struct IntegratorInfo {
  IntegratorKind kind;
  std::string_view name;  // CLI spelling, e.g. "dop853"
  std::string_view description;
  bool adaptive;
  int order;
};
/// Every integrator, in the order the help lists them.
[[nodiscard]] const std::array<IntegratorInfo, 7>& integrators();
[[nodiscard]] const IntegratorInfo& info(IntegratorKind kind);
/// Parses a CLI spelling; throws Error::input naming `origin` and the valid names.
[[nodiscard]] IntegratorKind parse_integrator(std::string_view name, const std::string& origin);
[[nodiscard]] Stabilization parse_stabilization(std::string_view name, const std::string& origin);
[[nodiscard]] std::string_view name(Stabilization s);
/// "auto", "compiled" or "interpreted"; throws Error::input naming `origin` and the valid names.
[[nodiscard]] Evaluator parse_evaluator(std::string_view name, const std::string& origin);

struct SimulationOptions {
  int case_id = 3;  // 1, 2 or 3
  IntegratorKind integrator = IntegratorKind::dop853;
  double dt = 1e-3;                   // s: fixed step, or first step of adaptive methods
  double rtol = 1e-10, atol = 1e-10;  // adaptive error control
  double duration = 10.0;             // s
  Stabilization stabilization = Stabilization::none;
  Evaluator evaluator = Evaluator::automatic;
  bool kinematics = false;  // the samples will need the kinematics (a column asks): native code covers them too
  // Baumgarte asks C'' + 2 alpha C' + beta^2 C = 0 of the pin constraint C (Case 1).
  // alpha = beta is critical damping: a violation decays like (1 + 10 t) e^(-10 t), in
  // about half a second, while the gains stay small enough (10/s) that explicit steps
  // up to ~0.1 s remain stable.
  double baumgarte_alpha = 10.0;  // 1/s, damping of the constraint error rate
  double baumgarte_beta = 10.0;   // 1/s, stiffness of the constraint error
  /// Validates ranges; throws Error::invalid about the setting (e.g. "dt") with its range.
  void validate() const;
};

/// The options that are numbers, by the name a lesson's run key and (with '-' for '_')
/// a flag give them, with their unit: one table for both.
struct NumberOption {
  std::string_view name;
  double SimulationOptions::*field;
  std::string_view unit;
};
inline constexpr std::array<NumberOption, 6> kNumberOptions{{
    {"dt", &SimulationOptions::dt, "s"},
    {"rtol", &SimulationOptions::rtol, ""},
    {"atol", &SimulationOptions::atol, ""},
    {"duration", &SimulationOptions::duration, "s"},
    {"baumgarte_alpha", &SimulationOptions::baumgarte_alpha, "1/s"},
    {"baumgarte_beta", &SimulationOptions::baumgarte_beta, "1/s"},
}};

}  // namespace linkage
