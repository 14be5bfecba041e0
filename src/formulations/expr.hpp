#pragma once
// A compile-time expression language for the entries of the linkage matrices.
//
// Each entry is written once, as ordinary C++ arithmetic on symbols, e.g.
//   m * D * sin1          -(m * D * cos1)          D * (w1sq * cos1 + w2sq * cos2) - g
// The expression's *type* records its structure, so the same definition
//   - evaluates to a double with everything inlined (no tree walk in the step loop),
//   - prints itself as Unicode text, ASCII text or LaTeX,
//   - tells at compile time whether it is identically zero (for structured solvers).
#include <string>
#include <type_traits>

#include "core/style.hpp"

namespace linkage::expr {

/// Values every entry may use: parameters and the trigonometry of the two angles.
struct Env {
  double m = 0, I = 0, D = 0, g = 0;      // mass, centroidal inertia I_zz^C, pin offset, gravity
  double s1 = 0, c1 = 0, s2 = 0, c2 = 0;  // sin/cos of theta1, theta2
  double w1 = 0, w2 = 0;                  // theta1_dot, theta2_dot
};

using Style = linkage::Style;

/// Binding strength, for parentheses: a sum inside a product needs them.
enum class Prec { sum = 1, product = 2, atom = 3 };

struct ExprTag {};
template <class T>
concept Expression = std::is_base_of_v<ExprTag, T>;

// --- leaves --------------------------------------------------------------------

template <int N>
struct Int : ExprTag {
  static_assert(N >= 0, "write negative constants with unary minus");
  static constexpr bool is_zero = N == 0;
  static constexpr Prec prec = Prec::atom;
  [[nodiscard]] static constexpr double eval(const Env& /*env*/) { return N; }
  static void print(std::string& out, Style /*style*/) { out += std::to_string(N); }
};

/// A named leaf: `Text` gives its three spellings, `Value` reads it from the Env.
template <class Spelling>
struct Leaf : ExprTag {
  static constexpr bool is_zero = false;
  static constexpr Prec prec = Prec::atom;
  [[nodiscard]] static constexpr double eval(const Env& env) { return Spelling::value(env); }
  static void print(std::string& out, Style style) {
    out += style == Style::unicode ? Spelling::unicode : style == Style::ascii ? Spelling::ascii : Spelling::latex;
  }
};

// Spellings. Unicode uses precomposed/combining marks; ASCII is parseable by the tests.
struct MassText {
  static constexpr const char* unicode = "m";
  static constexpr const char* ascii = "m";
  static constexpr const char* latex = "m";
  static constexpr double value(const Env& e) { return e.m; }
};
struct InertiaText {
  static constexpr const char* unicode = "I";
  static constexpr const char* ascii = "I";
  static constexpr const char* latex = "I_{zz}^{C}";
  static constexpr double value(const Env& e) { return e.I; }
};
struct OffsetText {
  static constexpr const char* unicode = "D";
  static constexpr const char* ascii = "D";
  static constexpr const char* latex = "D";
  static constexpr double value(const Env& e) { return e.D; }
};
struct GravityText {
  static constexpr const char* unicode = "g";
  static constexpr const char* ascii = "g";
  static constexpr const char* latex = "g";
  static constexpr double value(const Env& e) { return e.g; }
};
struct Sin1Text {
  static constexpr const char* unicode = "sin θ₁";
  static constexpr const char* ascii = "sin(th1)";
  static constexpr const char* latex = "\\sin\\theta_1";
  static constexpr double value(const Env& e) { return e.s1; }
};
struct Cos1Text {
  static constexpr const char* unicode = "cos θ₁";
  static constexpr const char* ascii = "cos(th1)";
  static constexpr const char* latex = "\\cos\\theta_1";
  static constexpr double value(const Env& e) { return e.c1; }
};
struct Sin2Text {
  static constexpr const char* unicode = "sin θ₂";
  static constexpr const char* ascii = "sin(th2)";
  static constexpr const char* latex = "\\sin\\theta_2";
  static constexpr double value(const Env& e) { return e.s2; }
};
struct Cos2Text {
  static constexpr const char* unicode = "cos θ₂";
  static constexpr const char* ascii = "cos(th2)";
  static constexpr const char* latex = "\\cos\\theta_2";
  static constexpr double value(const Env& e) { return e.c2; }
};
struct Rate1SqText {
  static constexpr const char* unicode = "θ̇₁²";
  static constexpr const char* ascii = "th1'^2";
  static constexpr const char* latex = "\\dot{\\theta}_1^2";
  static constexpr double value(const Env& e) { return e.w1 * e.w1; }
};
struct Rate2SqText {
  static constexpr const char* unicode = "θ̇₂²";
  static constexpr const char* ascii = "th2'^2";
  static constexpr const char* latex = "\\dot{\\theta}_2^2";
  static constexpr double value(const Env& e) { return e.w2 * e.w2; }
};

// --- composite nodes -------------------------------------------------------------

namespace detail {
template <Expression E>
void print_operand(std::string& out, Style style, Prec needed) {
  const bool paren = E::prec < needed;
  if (paren) out += style == Style::latex ? "\\left(" : "(";
  E::print(out, style);
  if (paren) out += style == Style::latex ? "\\right)" : ")";
}
}  // namespace detail

template <Expression A, Expression B>
struct Mul : ExprTag {
  static constexpr bool is_zero = A::is_zero || B::is_zero;
  static constexpr Prec prec = Prec::product;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) * B::eval(env); }
  static void print(std::string& out, Style style) {
    detail::print_operand<A>(out, style, Prec::product);
    out += " ";
    detail::print_operand<B>(out, style, Prec::atom);  // a product on the right would re-associate: keep it atomic
  }
};

template <Expression A, Expression B>
struct Add : ExprTag {
  static constexpr bool is_zero = A::is_zero && B::is_zero;
  static constexpr Prec prec = Prec::sum;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) + B::eval(env); }
  static void print(std::string& out, Style style) {
    A::print(out, style);
    out += " + ";
    detail::print_operand<B>(out, style, Prec::product);
  }
};

template <Expression A, Expression B>
struct Sub : ExprTag {
  static constexpr bool is_zero = A::is_zero && B::is_zero;
  static constexpr Prec prec = Prec::sum;
  [[nodiscard]] static constexpr double eval(const Env& env) { return A::eval(env) - B::eval(env); }
  static void print(std::string& out, Style style) {
    A::print(out, style);
    out += " - ";
    detail::print_operand<B>(out, style, Prec::product);
  }
};

template <Expression A>
struct Neg : ExprTag {
  static constexpr bool is_zero = A::is_zero;
  static constexpr Prec prec = Prec::sum;  // a leading minus binds like a sum: "-(a + b)" and "x (-a)"
  [[nodiscard]] static constexpr double eval(const Env& env) { return -A::eval(env); }
  static void print(std::string& out, Style style) {
    out += "-";
    detail::print_operand<A>(out, style, Prec::product);
  }
};

/// 1 / A
template <Expression A>
struct Inv : ExprTag {
  static constexpr bool is_zero = false;
  static constexpr Prec prec = Prec::atom;
  [[nodiscard]] static constexpr double eval(const Env& env) { return 1.0 / A::eval(env); }
  static void print(std::string& out, Style style) {
    if (style == Style::latex) {
      out += "\\frac{1}{";
      A::print(out, style);
      out += "}";
    } else {
      out += "1/";
      detail::print_operand<A>(out, style, Prec::atom);
    }
  }
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

/// The printed form of expression `E`.
template <Expression E>
[[nodiscard]] std::string to_string(E /*unused*/, Style style) {
  std::string out;
  E::print(out, style);
  return out;
}

// --- the vocabulary the case definitions use ------------------------------------

inline constexpr Int<0> zero{};
inline constexpr Int<1> one{};
inline constexpr Int<2> two{};
inline constexpr Leaf<MassText> m{};
inline constexpr Leaf<InertiaText> I{};
inline constexpr Leaf<OffsetText> D{};
inline constexpr Leaf<GravityText> g{};
inline constexpr Leaf<Sin1Text> sin1{};
inline constexpr Leaf<Cos1Text> cos1{};
inline constexpr Leaf<Sin2Text> sin2{};
inline constexpr Leaf<Cos2Text> cos2{};
inline constexpr Leaf<Rate1SqText> w1sq{};
inline constexpr Leaf<Rate2SqText> w2sq{};

}  // namespace linkage::expr
