#include "report/derivation.hpp"

#include "report/notation.hpp"

namespace linkage {

std::vector<DerivationGroup> derivation(const WorkedSolution& worked) {
  const Inputs& in = worked.inputs;
  auto input = [&](std::string_view key) { return input_symbol(*find_input_key(key), in); };
  const Symbol L = input("L"), w = input("w"), b = input("b"), m = input("m"), g = input("g");
  const Symbol x1 = input("x1"), y1 = input("y1"), th1 = input("theta1"), th2 = input("theta2");
  const Symbol x1d = input("x1_dot"), y1d = input("y1_dot"), th1d = input("theta1_dot"), th2d = input("theta2_dot");

  const Derived& d = worked.derived;
  const Invariants& inv = d.invariants;
  const Symbol I{"I_zz^C", "I_zz^C", "I_{zz}^{C}", d.I_zz_C};
  const Symbol D{"D", "D", "D", d.D};
  const Symbol IP{"I_zz^P", "I_zz^P", "I_{zz}^{P}", d.I_zz_P};
  const Symbol xP{"x_P", "xP", "x_P", d.pin.x()};
  const Symbol yP{"y_P", "yP", "y_P", d.pin.y()};
  const Symbol x2{"x₂", "x2", "x_2", d.C2.x()};
  const Symbol y2{"y₂", "y2", "y_2", d.C2.y()};
  const Symbol x2d{"ẋ₂", "x2'", "\\dot{x}_2", d.C2_dot.x()};
  const Symbol y2d{"ẏ₂", "y2'", "\\dot{y}_2", d.C2_dot.y()};
  const Symbol T{"T", "T", "T", inv.kinetic_energy};
  const Symbol V{"V", "V", "V", inv.potential_energy};
  const Symbol E{"E", "E", "E", inv.energy};
  const Symbol px{"p_x", "p_x", "p_x", inv.momentum.x()};
  const Symbol py{"p_y", "p_y", "p_y", inv.momentum.y()};
  const Symbol H{"H_c", "H_c", "H_c", inv.angular_momentum};
  const Formula two = Formula::integer(2), twelve = Formula::integer(12);

  return {
      {"Moments of inertia and the pin offset",
       "The centroidal inertia is about each block's centre of mass; the parallel-axis theorem "
       "moves it to the pin.",
       {{I, m * (square(w) + square(L)) / twelve, "kg m^2"}, {D, L / two - b, "m"}, {IP, I + m * square(D), "kg m^2"}},
       ReportPart::inertia},
      {"The pin constraint: positions and velocity",
       "Block 2 hangs from the pin, so its centre and velocity follow from block 1's coordinates "
       "and the two angles.",
       {{xP, x1 + D * cos(th1), "m"},
        {yP, y1 + D * sin(th1), "m"},
        {x2, xP + D * cos(th2), "m"},
        {y2, yP + D * sin(th2), "m"},
        {x2d, x1d - D * (th1d * sin(th1) + th2d * sin(th2)), "m/s"},
        {y2d, y1d + D * (th1d * cos(th1) + th2d * cos(th2)), "m/s"}},
       ReportPart::constraints},
      {"Energy and momentum",
       "Only uniform gravity acts: the energy, the horizontal momentum and the angular momentum "
       "about the centre of mass stay constant; the vertical momentum falls at the rate 2 m g.",
       {{T, m * (square(x1d) + square(y1d) + square(x2d) + square(y2d)) / two + I * (square(th1d) + square(th2d)) / two,
         "J"},
        {V, m * g * (y1 + y2), "J"},
        {E, T + V, "J"},
        {px, m * (x1d + x2d), "kg m/s"},
        {py, m * (y1d + y2d), "kg m/s"},
        {H, m * (x2 - x1) * (y2d - y1d) / two - m * (y2 - y1) * (x2d - x1d) / two + I * (th1d + th2d), "kg m^2/s"}},
       ReportPart::energy},
  };
}

}  // namespace linkage
