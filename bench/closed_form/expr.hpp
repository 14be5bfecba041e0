#pragma once
// The homework's closed form, the fast path the general procedure is tested against: a
// compile-time expression language for the entries of the two blocks' matrices.
//
// Each entry is written as ordinary C++ arithmetic on symbols, e.g.
//   m * D * sin1          -(m * D * cos1)          D * (w1sq * cos1 + w2sq * cos2) - g
// The expression's *type* records its structure, so the same definition
//   - evaluates to a double with everything inlined (no tree walk in the step loop),
//   - tells at compile time whether it is identically zero (for structured solvers).
// It prints nothing: the printed equations come from the symbolic system (src/symbolic).
#include <type_traits>

namespace linkage::expr {

/// Values every entry may use: parameters and the trigonometry of the two angles.
struct Env {
  double m = 0, I = 0, D = 0, g = 0;      // mass, centroidal inertia I_zz^C, pin offset, gravity
  double s1 = 0, c1 = 0, s2 = 0, c2 = 0;  // sin/cos of theta1, theta2
  double w1 = 0, w2 = 0;                  // theta1_dot, theta2_dot
};

struct ExprTag {};
template <class T>
concept Expression = std::is_base_of_v<ExprTag, T>;

// --- leaves --------------------------------------------------------------------

template <int N>
struct Int : ExprTag {
  static_assert(N >= 0, "write negative constants with unary minus");
  static constexpr bool is_zero = N == 0;
  [[nodiscard]] static constexpr double eval(const Env& /*env*/) { return N; }
};

/// A named leaf: `Source::value` reads it from the Env.
template <class Source>
struct Leaf : ExprTag {
  static constexpr bool is_zero = false;
  [[nodiscard]] static constexpr double eval(const Env& env) { return Source::value(env); }
};

// The leaves' values.
struct MassValue {
  static constexpr double value(const Env& e) { return e.m; }
};
struct InertiaValue {
  static constexpr double value(const Env& e) { return e.I; }
};
struct OffsetValue {
  static constexpr double value(const Env& e) { return e.D; }
};
struct GravityValue {
  static constexpr double value(const Env& e) { return e.g; }
};
struct Sin1Value {
  static constexpr double value(const Env& e) { return e.s1; }
};
struct Cos1Value {
  static constexpr double value(const Env& e) { return e.c1; }
};
struct Sin2Value {
  static constexpr double value(const Env& e) { return e.s2; }
};
struct Cos2Value {
  static constexpr double value(const Env& e) { return e.c2; }
};
struct Rate1SqValue {
  static constexpr double value(const Env& e) { return e.w1 * e.w1; }
};
struct Rate2SqValue {
  static constexpr double value(const Env& e) { return e.w2 * e.w2; }
};

// --- composite nodes -------------------------------------------------------------

template <Expression A, Expression B>
struct Mul : ExprTag {
  static constexpr bool is_zero = A::is_zero || B::is_zero;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) * B::eval(env); }
};

template <Expression A, Expression B>
struct Add : ExprTag {
  static constexpr bool is_zero = A::is_zero && B::is_zero;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) + B::eval(env); }
};

template <Expression A, Expression B>
struct Sub : ExprTag {
  static constexpr bool is_zero = A::is_zero && B::is_zero;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) - B::eval(env); }
};

template <Expression A>
struct Neg : ExprTag {
  static constexpr bool is_zero = A::is_zero;
  [[nodiscard]] static constexpr double eval(const Env& env) { return -A::eval(env); }
};

/// 1 / A
template <Expression A>
struct Inv : ExprTag {
  static constexpr bool is_zero = false;
  [[nodiscard]] static constexpr double eval(const Env& env) { return 1.0 / A::eval(env); }
};

template <Expression A, Expression B>
constexpr Mul<A, B> operator*(A, B) {
  return {};
}
template <Expression A, Expression B>
constexpr Add<A, B> operator+(A, B) {
  return {};
}
template <Expression A, Expression B>
constexpr Sub<A, B> operator-(A, B) {
  return {};
}
template <Expression A>
constexpr Neg<A> operator-(A) {
  return {};
}
template <Expression A>
constexpr Inv<A> inv(A) {
  return {};
}

// --- the vocabulary the case definitions use ------------------------------------

inline constexpr Int<0> zero{};
inline constexpr Int<1> one{};
inline constexpr Int<2> two{};
inline constexpr Leaf<MassValue> m{};
inline constexpr Leaf<InertiaValue> I{};
inline constexpr Leaf<OffsetValue> D{};
inline constexpr Leaf<GravityValue> g{};
inline constexpr Leaf<Sin1Value> sin1{};
inline constexpr Leaf<Cos1Value> cos1{};
inline constexpr Leaf<Sin2Value> sin2{};
inline constexpr Leaf<Cos2Value> cos2{};
inline constexpr Leaf<Rate1SqValue> w1sq{};
inline constexpr Leaf<Rate2SqValue> w2sq{};

}  // namespace linkage::expr
