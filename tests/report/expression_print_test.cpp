// The GiNaC printer against the homework: the three cases' A, B and equations, built with
// GiNaC the way src/symbolic derives them (Newton-Euler rows, the pin constraint
// differentiated twice, the pin force eliminated) and expanded, must print byte for byte
// as the golden solve outputs (tests/data/solve) in Unicode, ASCII and LaTeX, whatever
// order GiNaC keeps the terms in.
#include "report/expression_print.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <sstream>

#include "report/ascii_math.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

using GiNaC::ex;
using GiNaC::symbol;
using sym::Role;
using sym::SymbolInfo;

// A coordinate with its rate and acceleration.
struct Coordinate {
  symbol q, rate, acceleration;
};

// The homework's symbols in the lead's order (src/symbolic/system.cpp): parameters in file
// order, D, I, then x, y, theta of each body with rates and accelerations, then Fx, Fy.
// `reversed` creates the GiNaC symbols in the opposite order first, so GiNaC's hash order
// of every sum and product differs, while the table (and so every rank) stays the same.
class Homework {
 public:
  explicit Homework(bool reversed) {
    std::vector<std::string> names = {"L", "w", "b", "m", "g", "D", "I"};
    for (const char* body : {"1", "2"})
      for (const char* c : {"x", "y", "theta"})
        for (const char* suffix : {"", "_dot", "_ddot"}) names.push_back(std::string(body) + "." + c + suffix);
    names.insert(names.end(), {"Fx", "Fy"});
    if (reversed) std::reverse(names.begin(), names.end());
    for (const std::string& n : names) made_.emplace(n, symbol(n));
    if (reversed) std::reverse(names.begin(), names.end());

    for (const char* p : {"L", "w", "b", "m", "g"}) add(p, Role::parameter, p, p, p);
    add("D", Role::definition, "D", "D", "D");
    add("I", Role::inertia, "I", "I", "I_{zz}^{C}");
    for (int body = 1; body <= 2; ++body) {
      const std::string n = std::to_string(body);
      const std::string sub = body == 1 ? "₁" : "₂";
      for (const auto& [c, letter, ascii, tex] :
           {std::tuple<std::string, std::string, std::string, std::string>{"x", "x", "x", "x"},
            {"y", "y", "y", "y"},
            {"theta", "θ", "th", "\\theta"}}) {
        const std::string key = n + "." + c;
        const bool greek = c == "theta";
        Coordinate coordinate;
        coordinate.q = add(key, Role::coordinate, letter + sub, ascii + n, tex + "_" + n);
        coordinate.rate = add(key + "_dot", Role::rate, greek ? letter + "\u0307" + sub : (c == "x" ? "ẋ" : "ẏ") + sub,
                              ascii + n + "'", "\\dot{" + tex + "}_" + n);
        coordinate.acceleration =
            add(key + "_ddot", Role::acceleration, greek ? letter + "\u0308" + sub : (c == "x" ? "ẍ" : "ÿ") + sub,
                ascii + n + "''", "\\ddot{" + tex + "}_" + n);
        coordinates_.push_back(coordinate);
      }
    }
    add("Fx", Role::force, "Fx", "Fx", "F_x");
    add("Fy", Role::force, "Fy", "Fy", "F_y");
  }

  [[nodiscard]] const sym::SymbolTable& table() const { return table_; }
  [[nodiscard]] const SymbolInfo& info(const std::string& key) const { return *table_.find(key); }
  [[nodiscard]] ex operator[](const std::string& key) const { return info(key).symbol; }

  // d/dt by the chain rule: coordinates to rates, rates to accelerations.
  [[nodiscard]] ex time_derivative(const ex& e) const {
    ex d = 0;
    for (const Coordinate& c : coordinates_) {
      d += e.diff(c.q) * c.rate;
      d += e.diff(c.rate) * c.acceleration;
    }
    return d;
  }

 private:
  // The table's entries move as it grows: keep the symbol, not the entry.
  symbol add(const std::string& key, Role role, const std::string& unicode, const std::string& ascii,
             const std::string& latex) {
    return table_.add({made_.at(key), role, key, unicode, ascii, latex, "", "", 0}).symbol;
  }

  std::map<std::string, symbol> made_;
  sym::SymbolTable table_;
  std::vector<Coordinate> coordinates_;
};

// A linear system A q = B, one row per equation, entries expanded.
struct System {
  std::vector<const SymbolInfo*> unknowns;
  std::vector<std::vector<ex>> A;
  std::vector<ex> B;
};

// Rows `residuals` (each = 0, linear in the unknowns) as A q = B.
System linear_system(const std::vector<ex>& residuals, const std::vector<const SymbolInfo*>& unknowns) {
  System s{unknowns, {}, {}};
  GiNaC::exmap to_zero;
  for (const SymbolInfo* u : unknowns) to_zero[u->symbol] = 0;
  for (const ex& r : residuals) {
    const ex e = r.expand();
    std::vector<ex> row;
    for (const SymbolInfo* u : unknowns) row.push_back(e.coeff(u->symbol, 1).expand());
    s.A.push_back(row);
    s.B.push_back((-e.subs(to_zero)).expand());
  }
  return s;
}

// The three cases of the homework (docs/problem.md) derived with GiNaC.
std::array<System, 3> homework_cases(const Homework& h) {
  const ex m = h["m"], g = h["g"], D = h["D"], I = h["I"], Fx = h["Fx"], Fy = h["Fy"];
  auto q = [&](const char* key) { return h[key]; };
  const ex th1 = q("1.theta"), th2 = q("2.theta");
  // Newton-Euler of each block; the pin force F acts on block 1 at D along its axis, -F
  // on block 2 at -D along its axis.
  const ex x1dd = q("1.x_ddot"), y1dd = q("1.y_ddot"), th1dd = q("1.theta_ddot");
  const ex x2dd = q("2.x_ddot"), y2dd = q("2.y_ddot"), th2dd = q("2.theta_ddot");
  auto moment = [](const ex& rx, const ex& ry, const ex& fx, const ex& fy) { return rx * fy - ry * fx; };
  const ex ne1x = m * x1dd - Fx, ne1y = m * y1dd - Fy + m * g;
  const ex ne1t = I * th1dd - moment(D * cos(th1), D * sin(th1), Fx, Fy);
  const ex ne2x = m * x2dd + Fx, ne2y = m * y2dd + Fy + m * g;
  const ex ne2t = I * th2dd - moment(-D * cos(th2), -D * sin(th2), -Fx, -Fy);
  // The pin: block 1's point P minus block 2's, zero; its second time derivative.
  const ex phi_x = q("1.x") + D * cos(th1) - (q("2.x") - D * cos(th2));
  const ex phi_y = q("1.y") + D * sin(th1) - (q("2.y") - D * sin(th2));
  auto second = [&](const ex& e) { return h.time_derivative(h.time_derivative(e)); };

  const std::vector<const SymbolInfo*> u1 = {&h.info("1.x_ddot"), &h.info("1.y_ddot"), &h.info("1.theta_ddot"),
                                             &h.info("2.x_ddot"), &h.info("2.y_ddot"), &h.info("2.theta_ddot"),
                                             &h.info("Fx"),       &h.info("Fy")};
  System case1 = linear_system({ne1x, ne1y, ne1t, ne2x, ne2y, ne2t, second(phi_x), second(phi_y)}, u1);

  // Case 2: block 2's accelerations from the pin, its translation rows divided by m.
  const ex x2 = q("1.x") + D * cos(th1) + D * cos(th2), y2 = q("1.y") + D * sin(th1) + D * sin(th2);
  const GiNaC::exmap block2 = {{x2dd, second(x2)}, {y2dd, second(y2)}};
  const std::vector<const SymbolInfo*> u2 = {&h.info("1.x_ddot"),     &h.info("1.y_ddot"), &h.info("1.theta_ddot"),
                                             &h.info("2.theta_ddot"), &h.info("Fx"),       &h.info("Fy")};
  const ex row5 = (ne2x / m).subs(block2), row6 = (ne2y / m).subs(block2);
  System case2 = linear_system({ne1x, ne1y, ne1t, ne2t, row5, row6}, u2);

  // Case 3: the pin force from (1.2) and (2.2) substituted into the others.
  const GiNaC::exmap pin = {{Fx, m * x1dd}, {Fy, m * (y1dd + g)}};
  const std::vector<const SymbolInfo*> u3 = {&h.info("1.x_ddot"), &h.info("1.y_ddot"), &h.info("1.theta_ddot"),
                                             &h.info("2.theta_ddot")};
  System case3 = linear_system({ne1t.subs(pin), ne2t.subs(pin), row5.subs(pin), row6.subs(pin)}, u3);
  return {case1, case2, case3};
}

// The golden text of one case in one style: A by rows, B, each equation's two sides.
struct Golden {
  std::vector<std::vector<std::string>> A;
  std::vector<std::string> B;
  std::vector<std::pair<std::string, std::string>> equations;
};

// Copied from tests/data/solve/example-all-ascii.txt, example-all.tex and (Unicode)
// example-case1-unicode.txt and `linkage solve --unicode` before the printer existed.
// Case 1
const Golden kCase1Ascii{
    {{"m", "0", "0", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "0", "0", "-1"},
     {"0", "0", "I", "0", "0", "0", "D sin(th1)", "-D cos(th1)"},
     {"0", "0", "0", "m", "0", "0", "1", "0"},
     {"0", "0", "0", "0", "m", "0", "0", "1"},
     {"0", "0", "0", "0", "0", "I", "D sin(th2)", "-D cos(th2)"},
     {"1", "0", "-D sin(th1)", "-1", "0", "-D sin(th2)", "0", "0"},
     {"0", "1", "D cos(th1)", "0", "-1", "D cos(th2)", "0", "0"}},
    {"0", "-m g", "0", "0", "-m g", "0", "D (th1'^2 cos(th1) + th2'^2 cos(th2))",
     "D (th1'^2 sin(th1) + th2'^2 sin(th2))"},
    {{"m x1'' - Fx", "0"},
     {"m y1'' - Fy", "-m g"},
     {"I th1'' + D sin(th1) Fx - D cos(th1) Fy", "0"},
     {"m x2'' + Fx", "0"},
     {"m y2'' + Fy", "-m g"},
     {"I th2'' + D sin(th2) Fx - D cos(th2) Fy", "0"},
     {"x1'' - D sin(th1) th1'' - x2'' - D sin(th2) th2''", "D (th1'^2 cos(th1) + th2'^2 cos(th2))"},
     {"y1'' + D cos(th1) th1'' - y2'' + D cos(th2) th2''", "D (th1'^2 sin(th1) + th2'^2 sin(th2))"}},
};
const Golden kCase1Unicode{
    {{"m", "0", "0", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "0", "0", "-1"},
     {"0", "0", "I", "0", "0", "0", "D sin θ₁", "-D cos θ₁"},
     {"0", "0", "0", "m", "0", "0", "1", "0"},
     {"0", "0", "0", "0", "m", "0", "0", "1"},
     {"0", "0", "0", "0", "0", "I", "D sin θ₂", "-D cos θ₂"},
     {"1", "0", "-D sin θ₁", "-1", "0", "-D sin θ₂", "0", "0"},
     {"0", "1", "D cos θ₁", "0", "-1", "D cos θ₂", "0", "0"}},
    {"0", "-m g", "0", "0", "-m g", "0", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂)"},
    {{"m ẍ₁ - Fx", "0"},
     {"m ÿ₁ - Fy", "-m g"},
     {"I θ̈₁ + D sin θ₁ Fx - D cos θ₁ Fy", "0"},
     {"m ẍ₂ + Fx", "0"},
     {"m ÿ₂ + Fy", "-m g"},
     {"I θ̈₂ + D sin θ₂ Fx - D cos θ₂ Fy", "0"},
     {"ẍ₁ - D sin θ₁ θ̈₁ - ẍ₂ - D sin θ₂ θ̈₂", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)"},
     {"ÿ₁ + D cos θ₁ θ̈₁ - ÿ₂ + D cos θ₂ θ̈₂", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂)"}},
};
const Golden kCase1Latex{
    {{"m", "0", "0", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "0", "0", "-1"},
     {"0", "0", "I_{zz}^{C}", "0", "0", "0", R"(D \sin\theta_1)", R"(-D \cos\theta_1)"},
     {"0", "0", "0", "m", "0", "0", "1", "0"},
     {"0", "0", "0", "0", "m", "0", "0", "1"},
     {"0", "0", "0", "0", "0", "I_{zz}^{C}", R"(D \sin\theta_2)", R"(-D \cos\theta_2)"},
     {"1", "0", R"(-D \sin\theta_1)", "-1", "0", R"(-D \sin\theta_2)", "0", "0"},
     {"0", "1", R"(D \cos\theta_1)", "0", "-1", R"(D \cos\theta_2)", "0", "0"}},
    {"0", "-m g", "0", "0", "-m g", "0",
     R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))",
     R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right))"},
    {{R"(m \, \ddot{x}_1 - F_x)", "0"},
     {R"(m \, \ddot{y}_1 - F_y)", "-m g"},
     {R"(I_{zz}^{C} \, \ddot{\theta}_1 + D \sin\theta_1 \, F_x - D \cos\theta_1 \, F_y)", "0"},
     {R"(m \, \ddot{x}_2 + F_x)", "0"},
     {R"(m \, \ddot{y}_2 + F_y)", "-m g"},
     {R"(I_{zz}^{C} \, \ddot{\theta}_2 + D \sin\theta_2 \, F_x - D \cos\theta_2 \, F_y)", "0"},
     {R"(\ddot{x}_1 - D \sin\theta_1 \, \ddot{\theta}_1 - \ddot{x}_2 - D \sin\theta_2 \, \ddot{\theta}_2)",
      R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))"},
     {R"(\ddot{y}_1 + D \cos\theta_1 \, \ddot{\theta}_1 - \ddot{y}_2 + D \cos\theta_2 \, \ddot{\theta}_2)",
      R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right))"}},
};
// Case 2
const Golden kCase2Ascii{
    {{"m", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "-1"},
     {"0", "0", "I", "0", "D sin(th1)", "-D cos(th1)"},
     {"0", "0", "0", "I", "D sin(th2)", "-D cos(th2)"},
     {"1", "0", "-D sin(th1)", "-D sin(th2)", "1/m", "0"},
     {"0", "1", "D cos(th1)", "D cos(th2)", "0", "1/m"}},
    {"0", "-m g", "0", "0", "D (th1'^2 cos(th1) + th2'^2 cos(th2))", "D (th1'^2 sin(th1) + th2'^2 sin(th2)) - g"},
    {{"m x1'' - Fx", "0"},
     {"m y1'' - Fy", "-m g"},
     {"I th1'' + D sin(th1) Fx - D cos(th1) Fy", "0"},
     {"I th2'' + D sin(th2) Fx - D cos(th2) Fy", "0"},
     {"x1'' - D sin(th1) th1'' - D sin(th2) th2'' + Fx/m", "D (th1'^2 cos(th1) + th2'^2 cos(th2))"},
     {"y1'' + D cos(th1) th1'' + D cos(th2) th2'' + Fy/m", "D (th1'^2 sin(th1) + th2'^2 sin(th2)) - g"}},
};
const Golden kCase2Unicode{
    {{"m", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "-1"},
     {"0", "0", "I", "0", "D sin θ₁", "-D cos θ₁"},
     {"0", "0", "0", "I", "D sin θ₂", "-D cos θ₂"},
     {"1", "0", "-D sin θ₁", "-D sin θ₂", "1/m", "0"},
     {"0", "1", "D cos θ₁", "D cos θ₂", "0", "1/m"}},
    {"0", "-m g", "0", "0", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - g"},
    {{"m ẍ₁ - Fx", "0"},
     {"m ÿ₁ - Fy", "-m g"},
     {"I θ̈₁ + D sin θ₁ Fx - D cos θ₁ Fy", "0"},
     {"I θ̈₂ + D sin θ₂ Fx - D cos θ₂ Fy", "0"},
     {"ẍ₁ - D sin θ₁ θ̈₁ - D sin θ₂ θ̈₂ + Fx/m", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)"},
     {"ÿ₁ + D cos θ₁ θ̈₁ + D cos θ₂ θ̈₂ + Fy/m", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - g"}},
};
const Golden kCase2Latex{
    {{"m", "0", "0", "0", "-1", "0"},
     {"0", "m", "0", "0", "0", "-1"},
     {"0", "0", "I_{zz}^{C}", "0", R"(D \sin\theta_1)", R"(-D \cos\theta_1)"},
     {"0", "0", "0", "I_{zz}^{C}", R"(D \sin\theta_2)", R"(-D \cos\theta_2)"},
     {"1", "0", R"(-D \sin\theta_1)", R"(-D \sin\theta_2)", R"(\frac{1}{m})", "0"},
     {"0", "1", R"(D \cos\theta_1)", R"(D \cos\theta_2)", "0", R"(\frac{1}{m})"}},
    {"0", "-m g", "0", "0", R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))",
     R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right) - g)"},
    {{R"(m \, \ddot{x}_1 - F_x)", "0"},
     {R"(m \, \ddot{y}_1 - F_y)", "-m g"},
     {R"(I_{zz}^{C} \, \ddot{\theta}_1 + D \sin\theta_1 \, F_x - D \cos\theta_1 \, F_y)", "0"},
     {R"(I_{zz}^{C} \, \ddot{\theta}_2 + D \sin\theta_2 \, F_x - D \cos\theta_2 \, F_y)", "0"},
     {R"(\ddot{x}_1 - D \sin\theta_1 \, \ddot{\theta}_1 - D \sin\theta_2 \, \ddot{\theta}_2 + \frac{F_x}{m})",
      R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))"},
     {R"(\ddot{y}_1 + D \cos\theta_1 \, \ddot{\theta}_1 + D \cos\theta_2 \, \ddot{\theta}_2 + \frac{F_y}{m})",
      R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right) - g)"}},
};
// Case 3
const Golden kCase3Ascii{
    {{"m D sin(th1)", "-m D cos(th1)", "I", "0"},
     {"m D sin(th2)", "-m D cos(th2)", "0", "I"},
     {"2", "0", "-D sin(th1)", "-D sin(th2)"},
     {"0", "2", "D cos(th1)", "D cos(th2)"}},
    {"m g D cos(th1)", "m g D cos(th2)", "D (th1'^2 cos(th1) + th2'^2 cos(th2))",
     "D (th1'^2 sin(th1) + th2'^2 sin(th2)) - 2 g"},
    {{"m D sin(th1) x1'' - m D cos(th1) y1'' + I th1''", "m g D cos(th1)"},
     {"m D sin(th2) x1'' - m D cos(th2) y1'' + I th2''", "m g D cos(th2)"},
     {"2 x1'' - D sin(th1) th1'' - D sin(th2) th2''", "D (th1'^2 cos(th1) + th2'^2 cos(th2))"},
     {"2 y1'' + D cos(th1) th1'' + D cos(th2) th2''", "D (th1'^2 sin(th1) + th2'^2 sin(th2)) - 2 g"}},
};
const Golden kCase3Unicode{
    {{"m D sin θ₁", "-m D cos θ₁", "I", "0"},
     {"m D sin θ₂", "-m D cos θ₂", "0", "I"},
     {"2", "0", "-D sin θ₁", "-D sin θ₂"},
     {"0", "2", "D cos θ₁", "D cos θ₂"}},
    {"m g D cos θ₁", "m g D cos θ₂", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g"},
    {{"m D sin θ₁ ẍ₁ - m D cos θ₁ ÿ₁ + I θ̈₁", "m g D cos θ₁"},
     {"m D sin θ₂ ẍ₁ - m D cos θ₂ ÿ₁ + I θ̈₂", "m g D cos θ₂"},
     {"2 ẍ₁ - D sin θ₁ θ̈₁ - D sin θ₂ θ̈₂", "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)"},
     {"2 ÿ₁ + D cos θ₁ θ̈₁ + D cos θ₂ θ̈₂", "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g"}},
};
const Golden kCase3Latex{
    {{R"(m D \sin\theta_1)", R"(-m D \cos\theta_1)", "I_{zz}^{C}", "0"},
     {R"(m D \sin\theta_2)", R"(-m D \cos\theta_2)", "0", "I_{zz}^{C}"},
     {"2", "0", R"(-D \sin\theta_1)", R"(-D \sin\theta_2)"},
     {"0", "2", R"(D \cos\theta_1)", R"(D \cos\theta_2)"}},
    {R"(m g D \cos\theta_1)", R"(m g D \cos\theta_2)",
     R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))",
     R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right) - 2 g)"},
    {{R"(m D \sin\theta_1 \, \ddot{x}_1 - m D \cos\theta_1 \, \ddot{y}_1 + I_{zz}^{C} \, \ddot{\theta}_1)",
      R"(m g D \cos\theta_1)"},
     {R"(m D \sin\theta_2 \, \ddot{x}_1 - m D \cos\theta_2 \, \ddot{y}_1 + I_{zz}^{C} \, \ddot{\theta}_2)",
      R"(m g D \cos\theta_2)"},
     {R"(2 \, \ddot{x}_1 - D \sin\theta_1 \, \ddot{\theta}_1 - D \sin\theta_2 \, \ddot{\theta}_2)",
      R"(D \left(\dot{\theta}_1^2 \cos\theta_1 + \dot{\theta}_2^2 \cos\theta_2\right))"},
     {R"(2 \, \ddot{y}_1 + D \cos\theta_1 \, \ddot{\theta}_1 + D \cos\theta_2 \, \ddot{\theta}_2)",
      R"(D \left(\dot{\theta}_1^2 \sin\theta_1 + \dot{\theta}_2^2 \sin\theta_2\right) - 2 g)"}},
};

const Golden& golden(int id, Style style) {
  static const std::array<std::array<const Golden*, 3>, 3> kGoldens{{
      {&kCase1Unicode, &kCase1Ascii, &kCase1Latex},
      {&kCase2Unicode, &kCase2Ascii, &kCase2Latex},
      {&kCase3Unicode, &kCase3Ascii, &kCase3Latex},
  }};
  return *kGoldens[static_cast<std::size_t>(id - 1)][static_cast<std::size_t>(style)];
}

constexpr std::array<Style, 3> kStyles{Style::unicode, Style::ascii, Style::latex};

std::string style_name(Style s) { return s == Style::unicode ? "unicode" : s == Style::ascii ? "ascii" : "latex"; }

// GiNaC's own rendering, to show the two builds really differ in term order.
std::string ginac_text(const ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

void expect_case_prints_golden(const Homework& h, bool reversed_note) {
  const std::array<System, 3> cases = homework_cases(h);
  for (int id = 1; id <= 3; ++id) {
    const System& s = cases[static_cast<std::size_t>(id - 1)];
    for (Style style : kStyles) {
      const Golden& expected = golden(id, style);
      ASSERT_EQ(s.A.size(), expected.A.size());
      for (std::size_t r = 0; r < s.A.size(); ++r) {
        SCOPED_TRACE("case " + std::to_string(id) + " row " + std::to_string(r + 1) + " " + style_name(style) +
                     (reversed_note ? " (symbols made in reverse)" : ""));
        ASSERT_EQ(s.A[r].size(), expected.A[r].size());
        for (std::size_t c = 0; c < s.A[r].size(); ++c)
          EXPECT_EQ(strip_marks(print(s.A[r][c], h.table(), style)), expected.A[r][c]) << "column " << c + 1;
        EXPECT_EQ(strip_marks(print(s.B[r], h.table(), style)), expected.B[r]);
        const EquationSides eq = equation_sides(s.A[r], s.B[r], s.unknowns, h.table(), style);
        EXPECT_EQ(strip_marks(eq.lhs), expected.equations[r].first);
        EXPECT_EQ(strip_marks(eq.rhs), expected.equations[r].second);
      }
    }
  }
}

TEST(ExpressionPrint, HomeworkCasesPrintAsTheGoldens) { expect_case_prints_golden(Homework(false), false); }

TEST(ExpressionPrint, GinacTermOrderDoesNotMatter) {
  const Homework forward(false), reversed(true);
  // The same B entry of (4.3) is stored in another order by GiNaC in each build...
  const ex b43_forward = homework_cases(forward)[2].B[3], b43_reversed = homework_cases(reversed)[2].B[3];
  EXPECT_NE(ginac_text(b43_forward), ginac_text(b43_reversed));
  // ...and prints the same.
  expect_case_prints_golden(reversed, true);

  // Built by hand in scrambled orders, with the common factor left in or pulled out.
  const Homework& h = reversed;
  const ex D = h["D"], g = h["g"], w1 = h["1.theta_dot"], w2 = h["2.theta_dot"];
  const ex th1 = h["1.theta"], th2 = h["2.theta"];
  const std::string expected = "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g";
  EXPECT_EQ(
      strip_marks(print(-2 * g + sin(th2) * pow(w2, 2) * D + D * pow(w1, 2) * sin(th1), h.table(), Style::unicode)),
      expected);
  EXPECT_EQ(strip_marks(print(D * (pow(w2, 2) * sin(th2) + sin(th1) * pow(w1, 2)) - g * 2, h.table(), Style::unicode)),
            expected);
  EXPECT_EQ(print(h["m"] * sin(th1) * D, h.table(), Style::unicode), "m D sin θ₁");
  EXPECT_EQ(print(D * h["m"] * sin(th1), h.table(), Style::unicode), "m D sin θ₁");
}

TEST(ExpressionPrint, BreakMarksBeforeEverySumOperatorInTextOnly) {
  const Homework h(false);
  const System case3 = homework_cases(h)[2];
  const std::string mark(1, kBreakMark);
  EXPECT_EQ(print(case3.B[3], h.table(), Style::ascii),
            "D (th1'^2 sin(th1)" + mark + " + th2'^2 sin(th2))" + mark + " - 2 g");
  EXPECT_EQ(print(case3.B[2], h.table(), Style::unicode), "D (θ̇₁² cos θ₁" + mark + " + θ̇₂² cos θ₂)");  // nested
  EXPECT_EQ(print(case3.B[3], h.table(), Style::latex).find(kBreakMark), std::string::npos);
  const EquationSides eq = equation_sides(case3.A[2], case3.B[2], case3.unknowns, h.table(), Style::ascii);
  EXPECT_EQ(eq.lhs, "2 x1''" + mark + " - D sin(th1) th1''" + mark + " - D sin(th2) th2''");
  const EquationSides tex = equation_sides(case3.A[2], case3.B[2], case3.unknowns, h.table(), Style::latex);
  EXPECT_EQ(tex.lhs.find(kBreakMark), std::string::npos);
}

TEST(ExpressionPrint, EquationSidesSkipZerosAndParenthesizeSumCoefficients) {
  const Homework h(false);
  const ex m = h["m"], g = h["g"], L = h["L"], w = h["w"], D = h["D"];
  const std::vector<const SymbolInfo*> unknowns = {&h.info("1.x_ddot"), &h.info("Fx"), &h.info("Fy")};
  auto sides = [&](const std::vector<ex>& row, Style style) {
    const EquationSides eq = equation_sides(row, 0, unknowns, h.table(), style);
    return strip_marks(eq.lhs) + " = " + eq.rhs;
  };
  EXPECT_EQ(sides({L + w, -(g - D), 0}, Style::ascii), "(L + w) x1'' + (D - g) Fx = 0");
  EXPECT_EQ(sides({-L - w, 0, 0}, Style::ascii), "-(L + w) x1'' = 0");
  EXPECT_EQ(sides({0, 0, 0}, Style::ascii), "0 = 0");
  EXPECT_EQ(sides({m, 1 / (2 * m), -1 / m}, Style::ascii), "m x1'' + Fx / (2 m) - Fy/m = 0");
  EXPECT_EQ(sides({L + w, 0, -1 / m}, Style::latex), R"(\left(L + w\right) \, \ddot{x}_1 - \frac{F_y}{m} = 0)");
  EXPECT_THROW((void)equation_sides({m}, 0, unknowns, h.table(), Style::ascii), std::logic_error);
}

// Values the spec's example substitutes (tests/data/solve), as a report would show them.
std::string example_value(const SymbolInfo& s) {
  static const std::map<std::string, std::string> kValues{{"L", "0.3"},
                                                          {"w", "0.1"},
                                                          {"b", "0.04"},
                                                          {"m", "0.1"},
                                                          {"g", "9.81"},
                                                          {"D", "0.11"},
                                                          {"I", "0.000833333"},
                                                          {"1.x", "1"},
                                                          {"1.y", "2"},
                                                          {"1.theta", "0.1"},
                                                          {"2.x", "1.21726"},
                                                          {"2.y", "2.03284"},
                                                          {"2.theta", "0.2"},
                                                          {"1.x_dot", "0.15"},
                                                          {"1.y_dot", "0.25"},
                                                          {"1.theta_dot", "0.35"},
                                                          {"2.x_dot", "0.136322"},
                                                          {"2.y_dot", "0.336821"},
                                                          {"2.theta_dot", "0.45"},
                                                          {"Fx", "-0.5"}};
  return kValues.at(s.key);
}

TEST(ExpressionPrint, SubstitutedFormsShowTheNumbersInTheSameLayout) {
  const Homework h(false);
  const ex L = h["L"], w = h["w"], b = h["b"], m = h["m"], g = h["g"], D = h["D"], I = h["I"];
  const ex x1 = h["1.x"], y1 = h["1.y"], y2 = h["2.y"], th1 = h["1.theta"], th2 = h["2.theta"];
  const ex x1d = h["1.x_dot"], y1d = h["1.y_dot"], x2d = h["2.x_dot"], y2d = h["2.y_dot"];
  const ex w1 = h["1.theta_dot"], w2 = h["2.theta_dot"];
  auto both = [&](const ex& e, Style style) {
    return strip_marks(print(e, h.table(), style)) + " = " +
           strip_marks(print_substituted(e, h.table(), style, example_value));
  };
  // The derivation of the worked solution (tests/data/solve), as GiNaC gives it: expanded.
  // The rectangle's inertia reads L² + w² (parameters in file order); the golden's
  // hand-made formula has w² + L².
  const ex inertia = (m * (pow(w, 2) + pow(L, 2)) / 12).expand();
  EXPECT_EQ(both(inertia, Style::unicode), "m (L² + w²) / 12 = 0.1 × (0.3² + 0.1²) / 12");
  EXPECT_EQ(both(inertia, Style::ascii), "m (L^2 + w^2) / 12 = 0.1 * (0.3^2 + 0.1^2) / 12");
  EXPECT_EQ(both(inertia, Style::latex),
            R"(\frac{m \left(L^2 + w^2\right)}{12} = \frac{0.1 \times \left(0.3^2 + 0.1^2\right)}{12})");
  EXPECT_EQ(both(L / 2 - b, Style::unicode), "L / 2 - b = 0.3 / 2 - 0.04");
  EXPECT_EQ(both(L / 2 - b, Style::latex), R"(\frac{L}{2} - b = \frac{0.3}{2} - 0.04)");
  EXPECT_EQ(both(I + m * pow(D, 2), Style::unicode), "I + m D² = 0.000833333 + 0.1 × 0.11²");
  EXPECT_EQ(both(x1 + D * cos(th1), Style::unicode), "x₁ + D cos θ₁ = 1 + 0.11 × cos 0.1");
  EXPECT_EQ(both(x1 + D * cos(th1), Style::ascii), "x1 + D cos(th1) = 1 + 0.11 * cos(0.1)");
  EXPECT_EQ(both(x1 + D * cos(th1), Style::latex), R"(x_1 + D \cos\theta_1 = 1 + 0.11 \times \cos 0.1)");
  const ex x2_dot = (x1d - D * (w1 * sin(th1) + w2 * sin(th2))).expand();
  EXPECT_EQ(both(x2_dot, Style::unicode),
            "ẋ₁ - D (θ̇₁ sin θ₁ + θ̇₂ sin θ₂) = 0.15 - 0.11 × (0.35 × sin 0.1 + 0.45 × sin 0.2)");
  EXPECT_EQ(both((m * g * (y1 + y2)).expand(), Style::unicode), "m g (y₁ + y₂) = 0.1 × 9.81 × (2 + 2.03284)");
  const ex T =
      (m * (pow(x1d, 2) + pow(y1d, 2) + pow(x2d, 2) + pow(y2d, 2)) / 2 + I * (pow(w1, 2) + pow(w2, 2)) / 2).expand();
  EXPECT_EQ(both(T, Style::unicode),
            "m (ẋ₁² + ẏ₁² + ẋ₂² + ẏ₂²) / 2 + I (θ̇₁² + θ̇₂²) / 2 = "
            "0.1 × (0.15² + 0.25² + 0.136322² + 0.336821²) / 2 + 0.000833333 × (0.35² + 0.45²) / 2");
  EXPECT_EQ(print_substituted(T, h.table(), Style::ascii, example_value), [] {
    const std::string mk(1, kBreakMark);
    return "0.1 * (0.15^2" + mk + " + 0.25^2" + mk + " + 0.136322^2" + mk + " + 0.336821^2) / 2" + mk +
           " + 0.000833333 * (0.35^2" + mk + " + 0.45^2) / 2";
  }());
  EXPECT_EQ(both(T, Style::latex),
            R"(\frac{m \left(\dot{x}_1^2 + \dot{y}_1^2 + \dot{x}_2^2 + \dot{y}_2^2\right)}{2} + )"
            R"(\frac{I_{zz}^{C} \left(\dot{\theta}_1^2 + \dot{\theta}_2^2\right)}{2} = )"
            R"(\frac{0.1 \times \left(0.15^2 + 0.25^2 + 0.136322^2 + 0.336821^2\right)}{2} + )"
            R"(\frac{0.000833333 \times \left(0.35^2 + 0.45^2\right)}{2})");
  // A negative value is parenthesized, except where a function's parentheses hold it.
  const ex Fx = h["Fx"];
  EXPECT_EQ(both(D - Fx, Style::unicode), "D - Fx = 0.11 - (-0.5)");
  EXPECT_EQ(both(pow(Fx, 2), Style::unicode), "Fx² = (-0.5)²");
  EXPECT_EQ(both(m * cos(Fx), Style::unicode), "m cos Fx = 0.1 × cos(-0.5)");
  EXPECT_EQ(both(m * cos(Fx), Style::ascii), "m cos(Fx) = 0.1 * cos(-0.5)");
  EXPECT_EQ(both(Fx / m, Style::ascii), "Fx/m = (-0.5) / 0.1");
}

TEST(ExpressionPrint, OrderOfTermsAndFactors) {
  const Homework h(false);
  const ex L = h["L"], w = h["w"], m = h["m"], g = h["g"], D = h["D"], I = h["I"];
  const ex x1 = h["1.x"], x2 = h["2.x"], th1 = h["1.theta"], w1 = h["1.theta_dot"], Fx = h["Fx"];
  auto text = [&](const ex& e) { return strip_marks(print(e, h.table(), Style::ascii)); };
  EXPECT_EQ(text(x1 - x2), "x1 - x2");
  EXPECT_EQ(text(x2 - x1), "x2 - x1");  // no leading minus while a term is positive
  EXPECT_EQ(text(-x1 - x2), "-x1 - x2");
  EXPECT_EQ(text(-(D * x1) - D * x2), "-D (x1 + x2)");
  EXPECT_EQ(text(Fx * sin(th1) * w1 * m * x1), "m th1' x1 sin(th1) Fx");
  EXPECT_EQ(text(g + D * cos(th1)), "D cos(th1) + g");              // constants after terms with coordinates
  EXPECT_EQ(text(m * pow(D, 2) + I + L + 3), "L + I + m D^2 + 3");  // fewer factors first, numbers last
  EXPECT_EQ(text(2 * L + 2 * w), "2 L + 2 w");                      // a numeric factor alone stays in
  EXPECT_EQ(text((m * g * L + m * g * w) / 3), "m g (L + w) / 3");
  EXPECT_EQ(text(m * (L + w) * (g + D)), "m (L + w) (g + D)");
  EXPECT_EQ(text(pow(L + w, 2) * m), "m (L + w)^2");
  EXPECT_EQ(text(pow(D * L + D * w, 2)), "D^2 (L + w)^2");
  // A sum inside a product: fewer negative terms, on a tie the last term positive,
  // however GiNaC signed it.
  EXPECT_EQ(text(m * (x2 - x1)), "m (x2 - x1)");
  EXPECT_EQ(text(-m * (x1 - x2)), "m (x2 - x1)");
  EXPECT_EQ(text(m * (x1 - x2)), "-m (x2 - x1)");
  EXPECT_EQ(text(m * (L - w - g)), "-m (w - L + g)");
  EXPECT_EQ(text(pow(x1 - x2, 2)), "(x2 - x1)^2");
}

TEST(ExpressionPrint, NumbersPowersAndFunctions) {
  const Homework h(false);
  const ex L = h["L"], m = h["m"], g = h["g"], D = h["D"], I = h["I"], t = h["1.x"];
  const ex th1 = h["1.theta"], th2 = h["2.theta"];
  auto all = [&](const ex& e) {
    std::string out;
    for (Style s : kStyles) out += (out.empty() ? "" : " | ") + strip_marks(print(e, h.table(), s));
    return out;
  };
  EXPECT_EQ(all(ex(0)), "0 | 0 | 0");
  EXPECT_EQ(all(GiNaC::numeric(1, 12)), R"(1/12 | 1/12 | \frac{1}{12})");
  EXPECT_EQ(all(-3 * L / 2), R"(-3 L / 2 | -3 L / 2 | -\frac{3 L}{2})");
  EXPECT_EQ(all(1 / m), R"(1/m | 1/m | \frac{1}{m})");
  EXPECT_EQ(all(g / (L * m)), R"(g / (L m) | g / (L m) | \frac{g}{L m})");
  EXPECT_EQ(all(pow(L, 3) * pow(I, 2)), R"(L³ I² | L^3 I^2 | L^3 {I_{zz}^{C}}^2)");
  EXPECT_EQ(all(pow(L, 12)), R"(L¹² | L^12 | L^{12})");
  EXPECT_EQ(all(sqrt(g / L)), R"(√(g/L) | sqrt(g/L) | \sqrt{\frac{g}{L}})");
  EXPECT_EQ(all(sqrt(L)), R"(√L | sqrt(L) | \sqrt{L})");
  EXPECT_EQ(all(1 / sqrt(L)), R"(1 / √L | 1 / sqrt(L) | \frac{1}{\sqrt{L}})");
  EXPECT_EQ(all(sin(th1 - th2)), R"(sin(θ₁ - θ₂) | sin(th1 - th2) | \sin\left(\theta_1 - \theta_2\right))");
  EXPECT_EQ(all(D * cos(2 * th1)), R"(D cos(2 θ₁) | D cos(2 th1) | D \cos\left(2 \theta_1\right))");
  EXPECT_EQ(all(pow(sin(th1), 2)), R"(sin² θ₁ | sin(th1)^2 | \sin^2\theta_1)");
  EXPECT_EQ(all(tan(th1) * cos(th1) * sin(th1)), R"(sin θ₁ cos θ₁ tan θ₁ | sin(th1) cos(th1) tan(th1) | )"
                                                 R"(\sin\theta_1 \cos\theta_1 \tan\theta_1)");
  EXPECT_EQ(all(exp(-g * t)), R"(exp(-g x₁) | exp(-g x1) | e^{-g x_1})");
  EXPECT_EQ(all(log(L)), R"(ln L | log(L) | \ln L)");
  EXPECT_EQ(all(2 * GiNaC::Pi * L), R"(2 π L | 2 pi L | 2 \pi L)");
  EXPECT_EQ(all(cos(ex(GiNaC::numeric(1, 3)))), R"(cos(1/3) | cos(1/3) | \cos\left(\frac{1}{3}\right))");
  // Floats in shortest round-trip form.
  EXPECT_EQ(all(GiNaC::numeric(0.1) * m), "0.1 m | 0.1 m | 0.1 m");
  EXPECT_EQ(all(GiNaC::numeric(0.1 + 0.2)), "0.30000000000000004 | 0.30000000000000004 | 0.30000000000000004");
  EXPECT_EQ(all(GiNaC::numeric(-2.5e-7) * L), R"(-2.5e-07 L | -2.5e-07 L | -2.5 \times 10^{-7} L)");
  EXPECT_EQ(all(sin(ex(2))), R"(sin 2 | sin(2) | \sin 2)");
}

TEST(ExpressionPrint, WhatHasNoNotationIsAProgrammingError) {
  const Homework h(false);
  const symbol stray("stray");
  EXPECT_THROW((void)print(h["m"] * stray, h.table(), Style::ascii), std::logic_error);
  EXPECT_THROW((void)print_substituted(sin(stray), h.table(), Style::unicode, example_value), std::logic_error);
  EXPECT_THROW((void)print(abs(h["m"]), h.table(), Style::ascii), std::logic_error);
  EXPECT_THROW((void)print(GiNaC::I * h["m"], h.table(), Style::ascii), std::logic_error);
  EXPECT_THROW((void)print(GiNaC::Euler, h.table(), Style::ascii), std::logic_error);
  EXPECT_THROW((void)print(h["m"] == h["g"], h.table(), Style::ascii), std::logic_error);
}

// Random expressions in the homework's symbols, printed in ASCII and read back: the
// printed text means the expression, whatever grouping and order the printer chose; and
// the same expression in symbols made in the reverse order (so GiNaC keeps other term
// orders and other signs of sums inside products) prints the same in every style.
// (test::AsciiMath reads squares only: each monomial takes a symbol once, and the
// factor multiplying a sum comes from other symbols than the sum's.)
TEST(ExpressionPrint, RandomExpressionsPrintTheirValueWhateverGinacOrder) {
  const Homework h(false), other(true);
  GiNaC::exmap to_other;
  for (const SymbolInfo& s : h.table().all()) to_other[s.symbol] = other[s.key];
  const std::vector<std::string> inner = {"m", "D", "1.theta", "1.theta_dot", "1.x_ddot"};
  const std::vector<std::string> outer = {"g", "I", "2.theta", "2.theta_dot", "Fx"};
  std::mt19937 rng(20260522);
  std::uniform_int_distribution<int> small(-3, 3), coin(0, 3);
  std::uniform_real_distribution<double> value(0.2, 1.7);
  auto monomial = [&](std::vector<std::string> keys) -> ex {
    ex t = GiNaC::numeric(small(rng) == 0 ? 1 : small(rng), 1 + coin(rng));
    std::shuffle(keys.begin(), keys.end(), rng);
    const int n = 1 + coin(rng);
    for (int i = 0; i < n; ++i) {
      const ex s = h[keys[static_cast<std::size_t>(i)]];
      const int kind = coin(rng);
      t *= kind == 0 ? sin(s) : kind == 1 ? cos(s) : kind == 2 ? pow(s, small(rng) % 2 == 0 ? 2 : -1) : s;
    }
    return t;
  };
  auto sum = [&](const std::vector<std::string>& keys) {
    ex e = 0;
    const int terms = 1 + coin(rng) + coin(rng);
    for (int i = 0; i < terms; ++i) e += monomial(keys);
    return e;
  };
  int differently_kept = 0;
  for (int trial = 0; trial < 400; ++trial) {
    ex e = sum(inner);
    if (trial % 4 == 1) e = e * monomial(outer) + monomial(outer);
    if (trial % 4 == 2) e = e * sum(outer);
    if (trial % 4 == 3) e = pow(e, 2) * monomial(outer);

    std::map<std::string, double> ascii_values;
    GiNaC::exmap ginac_values;
    for (const auto& keys : {inner, outer}) {
      for (const std::string& key : keys) {
        const double v = value(rng);
        ascii_values[h.info(key).ascii] = v;
        ginac_values[h[key]] = v;
      }
    }
    const std::string printed = strip_marks(print(e, h.table(), Style::ascii));
    const double expected = GiNaC::ex_to<GiNaC::numeric>(e.subs(ginac_values).evalf()).to_double();
    if (trial % 4 != 3) {  // AsciiMath reads no fourth powers
      const double got = test::AsciiMath(ascii_values).eval(printed);
      EXPECT_NEAR(got, expected, 1e-9 * (1 + std::abs(expected))) << printed << "  from GiNaC " << ginac_text(e);
    }
    const ex same = e.subs(to_other);
    if (ginac_text(same) != ginac_text(e)) ++differently_kept;
    for (Style style : kStyles)
      EXPECT_EQ(print(same, other.table(), style), print(e, h.table(), style)) << "from GiNaC " << ginac_text(e);
  }
  EXPECT_GT(differently_kept, 100);  // GiNaC's order did differ
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

TEST(ExpressionPrint, DecimalsFromTheFileStayDecimalsStructuralFractionsStayFractions) {
  sym::SymbolTable table;
  const GiNaC::symbol L = table.add({GiNaC::symbol("L"), sym::Role::parameter, "L", "L", "L", "L", "m", ""}).symbol;
  using GiNaC::numeric;
  EXPECT_EQ(print(numeric(3, 10) * L, table, Style::unicode), "0.3 L");
  EXPECT_EQ(strip_marks(print(numeric(2, 25) + L, table, Style::unicode)), "L + 0.08");
  EXPECT_EQ(print(numeric(1, 2) * L, table, Style::unicode), "L / 2");
  EXPECT_EQ(print(numeric(5, 16) * L, table, Style::unicode), "5 L / 16");
  EXPECT_EQ(print(numeric(1, 12) * L, table, Style::latex), "\\frac{L}{12}");
}

}  // namespace
}  // namespace linkage
