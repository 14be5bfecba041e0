#pragma once
// Matrices whose entries are expr:: expressions: `matrix(row(...), ...)` and
// `column(...)` build a type that can fill a fixed-size Eigen matrix and say which
// entries are identically zero, both from the one definition.
#include <array>

#include "bench/closed_form/expr.hpp"
#include "core/types.hpp"

namespace linkage {

template <expr::Expression... E>
struct RowDef {
  static constexpr int size = sizeof...(E);
  static constexpr std::array<bool, sizeof...(E)> zeros{E::is_zero...};

  template <class Out>
  static void eval(Out& out, int r, const expr::Env& env) {
    int c = 0;
    ((out(r, c++) = E::eval(env)), ...);
  }
};

template <class... Rows>
struct MatrixDef {
  static constexpr int rows = sizeof...(Rows);
  static constexpr int cols = std::array<int, sizeof...(Rows)>{Rows::size...}[0];
  static_assert(((Rows::size == cols) && ...), "every row needs the same number of entries");

  /// Fills a rows x cols matrix (Eigen or anything with operator()(r, c)).
  template <class Out>
  static void eval(Out& out, const expr::Env& env) {
    int r = 0;
    (Rows::eval(out, r++, env), ...);
  }
  [[nodiscard]] static Mat<rows, cols> evaluate(const expr::Env& env) {
    Mat<rows, cols> out;
    eval(out, env);
    return out;
  }
  /// True when entry (r, c) is zero by construction, whatever the state.
  [[nodiscard]] static constexpr bool structural_zero(int r, int c) {
    constexpr std::array<const bool*, rows> table{Rows::zeros.data()...};
    return table[static_cast<std::size_t>(r)][c];
  }
};

template <expr::Expression... E>
constexpr RowDef<E...> row(E...) {
  return {};
}
template <class... Rows>
constexpr MatrixDef<Rows...> matrix(Rows...) {
  return {};
}
template <expr::Expression... E>
constexpr MatrixDef<RowDef<E>...> column(E...) {
  return {};
}

}  // namespace linkage
