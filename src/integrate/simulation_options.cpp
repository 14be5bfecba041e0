#include "integrate/simulation_options.hpp"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "integrate/step_budget.hpp"

namespace linkage {

namespace {

constexpr std::array<IntegratorInfo, 7> kIntegrators{{
    {IntegratorKind::euler, "euler", "explicit Euler, fixed step, order 1", false, 1},
    {IntegratorKind::symplectic_euler, "symplectic-euler", "semi-implicit (symplectic) Euler, fixed step, order 1",
     false, 1},
    {IntegratorKind::rk4, "rk4", "classical Runge-Kutta, fixed step, order 4", false, 4},
    {IntegratorKind::dopri5, "dopri5", "Dormand-Prince 5(4), adaptive, dense output of order 4", true, 5},
    {IntegratorKind::dop853, "dop853", "Dormand-Prince 8(5,3), adaptive, dense output of order 7", true, 8},
    {IntegratorKind::vern7, "vern7", "Verner 7(6), adaptive, dense output of order 6", true, 7},
    {IntegratorKind::gauss2, "gauss-legendre",
     "2-stage Gauss-Legendre, implicit (Newton), symmetric, fixed step, order 4", false, 4},
}};

constexpr std::array<std::pair<Stabilization, std::string_view>, 3> kStabilizations{
    {{Stabilization::none, "none"},
     {Stabilization::baumgarte, "baumgarte"},
     {Stabilization::projection, "projection"}}};

// Limits of the options. Past a million seconds the free fall reaches 5e12 m, where a
// double keeps only millimetres; below rtol = 1e-14 round-off dominates every step.
constexpr double kMaxDuration = 1e6;  // s
constexpr double kMinRtol = 1e-14, kMaxTol = 1.0;
constexpr double kMinAtol = 1e-20;
constexpr double kMaxGain = 1e6;  // 1/s

std::string num(double v) { return format_roundtrip(v); }

void require(bool ok, const std::string& setting, double value, const std::string& unit, const std::string& range) {
  if (!ok)
    throw Error::invalid(setting, num(value) + (unit.empty() ? "" : " " + unit) + " is out of range; valid: " + range);
}

}  // namespace

const std::array<IntegratorInfo, 7>& integrators() { return kIntegrators; }

const IntegratorInfo& info(IntegratorKind kind) {
  for (const IntegratorInfo& i : kIntegrators)
    if (i.kind == kind) return i;
  throw Error::failure("unknown integrator kind");
}

IntegratorKind parse_integrator(std::string_view name, const std::string& origin) {
  std::vector<std::string> names;
  for (const IntegratorInfo& i : kIntegrators) {
    if (i.name == name) return i.kind;
    names.emplace_back(i.name);
  }
  throw Error::invalid(origin, "'" + std::string(name) + "' is not an integrator" + did_you_mean(name, names) +
                                   "; valid: " + join_names(names));
}

namespace {

// The kind spelled `name` in `spellings`, else Error::invalid naming `origin` and the valid names.
template <typename Kind, std::size_t N>
Kind parse_spelling(const std::array<std::pair<Kind, std::string_view>, N>& spellings, std::string_view name,
                    const std::string& origin, std::string_view what) {
  std::vector<std::string> names;
  for (const auto& [kind, spelling] : spellings) {
    if (spelling == name) return kind;
    names.emplace_back(spelling);
  }
  throw Error::invalid(origin, "'" + std::string(name) + "' is not " + std::string(what) + did_you_mean(name, names) +
                                   "; valid: " + join_names(names));
}

constexpr std::array<std::pair<Evaluator, std::string_view>, 3> kEvaluators{
    {{Evaluator::automatic, "auto"}, {Evaluator::compiled, "compiled"}, {Evaluator::interpreted, "interpreted"}}};

}  // namespace

Stabilization parse_stabilization(std::string_view name, const std::string& origin) {
  return parse_spelling(kStabilizations, name, origin, "a stabilization");
}

Evaluator parse_evaluator(std::string_view name, const std::string& origin) {
  return parse_spelling(kEvaluators, name, origin, "an evaluator");
}

std::string_view name(Stabilization s) {
  for (const auto& [kind, spelling] : kStabilizations)
    if (kind == s) return spelling;
  return "unknown";
}

void SimulationOptions::validate() const {
  if (case_id < 1 || case_id > 3)
    throw Error::invalid("case", std::to_string(case_id) + " is not a case; valid: 1, 2, 3");
  require(std::isfinite(duration) && duration > 0 && duration <= kMaxDuration, "duration", duration, "s",
          "0 < duration <= " + num(kMaxDuration) + " s");
  require(std::isfinite(dt) && dt > 0 && dt <= duration, "dt", dt, "s", "0 < dt <= duration (" + num(duration) + " s)");
  if (!info(integrator).adaptive && duration / dt > kMaxSteps)
    throw Error::invalid("dt", num(dt) + " s needs " + format_significant(duration / dt, 3) + " steps of " +
                                   std::string(info(integrator).name) + " for a duration of " + num(duration) +
                                   " s; the limit is 1e9 steps (use a larger dt or an adaptive integrator)");
  require(std::isfinite(rtol) && rtol >= kMinRtol && rtol <= kMaxTol, "rtol", rtol, "",
          num(kMinRtol) + " <= rtol <= " + num(kMaxTol) + " (smaller is below double precision)");
  require(std::isfinite(atol) && atol >= kMinAtol && atol <= kMaxTol, "atol", atol, "",
          num(kMinAtol) + " <= atol <= " + num(kMaxTol));
  require(std::isfinite(baumgarte_alpha) && baumgarte_alpha >= 0 && baumgarte_alpha <= kMaxGain, "baumgarte_alpha",
          baumgarte_alpha, "1/s", "0 <= alpha <= " + num(kMaxGain) + " 1/s");
  require(std::isfinite(baumgarte_beta) && baumgarte_beta >= 0 && baumgarte_beta <= kMaxGain, "baumgarte_beta",
          baumgarte_beta, "1/s", "0 <= beta <= " + num(kMaxGain) + " 1/s");
}

}  // namespace linkage
