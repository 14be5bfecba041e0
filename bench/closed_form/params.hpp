#pragma once
// The two identical uniform blocks and the world they move in, and the quantities
// derived from them alone (spec sec. 1 and 2).
//   I_zz^C = m (w^2 + L^2) / 12      centroidal moment of inertia
//   D      = L/2 - b                 distance from each centre of mass to the pin P
//   I_zz^P = I_zz^C + m D^2          about the pin, by the parallel-axis theorem

namespace linkage {

struct Params {
  double L = 0.3;   // block length, m
  double w = 0.1;   // block width, m
  double b = 0.04;  // pin distance from one end of each block, m
  double m = 0.1;   // mass of each block, kg
  double g = 9.81;  // gravitational acceleration along -y, m/s^2

  [[nodiscard]] double inertia_centroidal() const { return m * (w * w + L * L) / 12.0; }
  [[nodiscard]] double pin_offset() const { return L / 2.0 - b; }
  [[nodiscard]] double inertia_about_pin() const {
    const double D = pin_offset();
    return inertia_centroidal() + m * D * D;
  }
};

}  // namespace linkage
