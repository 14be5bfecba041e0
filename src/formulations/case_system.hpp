#pragma once
// A case of a mechanism: A(q, q', t) u = B(q, q', t) with labelled rows and named
// unknowns u, every entry a GiNaC expression built from the one symbolic system
// (symbolic/system.hpp). The three cases are three transforms of that system:
//   case_maximal.cpp      Case 1: x, y, theta of every body and every joint force
//   case_generalized.cpp  Case 2: the tree's generalized coordinates, joint forces kept
//   case_reduced.cpp      Case 3: the tree's joint forces eliminated
//   case_lagrange.cpp     Case 3 in Lagrange's form, the board's M(q) q'' = Q
#include <ginac/ginac.h>

#include <array>
#include <string>
#include <vector>

#include "symbolic/system.hpp"

namespace linkage {

enum class CaseId { maximal = 1, generalized = 2, reduced = 3 };
inline constexpr std::array<CaseId, 3> kAllCases{CaseId::maximal, CaseId::generalized, CaseId::reduced};

[[nodiscard]] constexpr int case_number(CaseId id) { return static_cast<int>(id); }
/// Case numbers (each 1, 2 or 3, checked by the caller) as ids, in their order.
[[nodiscard]] inline std::vector<CaseId> case_ids(const std::vector<int>& numbers) {
  std::vector<CaseId> ids;
  for (int n : numbers) ids.push_back(static_cast<CaseId>(n));
  return ids;
}

/// A quantity a case does not solve for but yields from its unknowns: a body's
/// acceleration through the kinematics, or an eliminated joint force through the
/// equation it was eliminated with.
struct Recovered {
  GiNaC::symbol symbol;  // the acceleration or force symbol
  GiNaC::ex value;       // in this case's unknowns, the state and parameters
};

struct CaseSystem {
  CaseId id = CaseId::maximal;
  std::string title;                      // "eight equations in maximal coordinates with the pin force"
  std::vector<GiNaC::symbol> unknowns;    // accelerations, then forces
  std::vector<std::string> labels;        // "1.1", "2.1", ...
  std::vector<std::vector<GiNaC::ex>> A;  // rows x unknowns
  std::vector<GiNaC::ex> B;
  /// Whether the entries are in maximal coordinates (Case 1) or generalized ones.
  bool maximal = false;
  std::vector<Recovered> recovered;
};

/// Rows r_i(u) = 0, linear in the unknowns, as A u = B.
[[nodiscard]] CaseSystem linear_system(CaseId id, const std::vector<GiNaC::ex>& rows,
                                       const std::vector<GiNaC::symbol>& unknowns);

[[nodiscard]] CaseSystem maximal_case(const sym::System& system);
[[nodiscard]] CaseSystem generalized_case(const sym::System& system);
[[nodiscard]] CaseSystem reduced_case(const sym::System& system);
[[nodiscard]] CaseSystem derive_case(const sym::System& system, CaseId id);
/// Case 3's unknowns in Lagrange's form: one row per generalized coordinate, M(q) q'' = Q
/// with M symmetric and sums of sin/cos products contracted (cos(θ₁ - θ₂)), the
/// loop-closing forces entering as J^T lambda; then the loop rows. Recovers what Case 3 does.
[[nodiscard]] CaseSystem lagrange_case(const sym::System& system);

/// "pin force" (one pin), "slider force" (one slider) or "joint forces", for titles.
[[nodiscard]] std::string force_phrase(const sym::System& system);

/// Case 2's rows before they become A and B, shared with Case 3 (which eliminates from them).
struct GeneralizedRows {
  std::vector<GiNaC::ex> rows;
  std::vector<GiNaC::symbol> unknowns;
  std::vector<Recovered> recovered;  // the bodies' accelerations the coordinates do not include
};
[[nodiscard]] GeneralizedRows generalized_rows(const sym::System& system);

/// "eight", "twelve": the count as the homework writes it in titles.
[[nodiscard]] std::string count_word(std::size_t n);

}  // namespace linkage
