#pragma once
// Energy, power and momentum of a mechanism's symbolic system, as GiNaC expressions in the
// maximal coordinates x_b, y_b, theta_b, their rates and the time t (substitute
// System::to_generalized() for the generalized coordinates). With the joints
// frictionless and workless, d(T + V)/dt = P along any motion, and without external
// loads p and H_O stay constant: the checks of the derived equations of motion.
#include <ginac/ginac.h>

#include <vector>

#include "symbolic/system.hpp"

namespace linkage::sym {

/// T = sum_b m_b (x_b'^2 + y_b'^2) / 2 + I_b theta_b'^2 / 2.
[[nodiscard]] GiNaC::ex kinetic_energy(const System& system);

/// V = sum_b m_b g y_b                          gravity along -y
///   + sum_springs k (l - l0)^2 / 2             l the distance between the spring's points
///   + sum_pins k (th_b - th_a - rest)^2 / 2    torsional springs in pins;
/// a spring whose k or rest depends on the state has no potential: its force is a power term.
[[nodiscard]] GiNaC::ex potential_energy(const System& system);

/// One term of the non-conservative power: a load times the rate it works on, P_k = Q_k v_k.
/// v_k is linear in the rates; Q_k may depend on them (a damper's force), so the
/// generalized force of a coordinate q_i is sum_k Q_k dv_k/dq_i', with Q_k held fixed.
struct PowerTerm {
  GiNaC::ex load;  // a force or torque: N or N m
  GiNaC::ex rate;  // the velocity or angular velocity it acts on: m/s or rad/s
};

/// The loads that are not derived from V, each with the rate it works on:
///   linear dampers      (-c l') l'
///   torsional dampers   (-c (th_b' - th_a')) (th_b' - th_a')
///   springs whose k or rest depends on the state   (-k (l - l0)) l'   (pins alike)
///   applied forces      F_x v_x + F_y v_y of the point they act at (F may depend on t and the state)
///   applied torques     tau theta_b'.
[[nodiscard]] std::vector<PowerTerm> nonconservative_power_terms(const System& system);

/// P = sum_k Q_k v_k over nonconservative_power_terms().
[[nodiscard]] GiNaC::ex nonconservative_power(const System& system);

/// p = sum_b m_b (x_b', y_b').
[[nodiscard]] Vec2 linear_momentum(const System& system);

/// M = sum_b m_b.
[[nodiscard]] GiNaC::ex total_mass(const System& system);

/// r_G = sum_b m_b (x_b, y_b) / M, the mechanism's centre of mass.
[[nodiscard]] Vec2 centre_of_mass(const System& system);

/// r_G' = p / M, its velocity.
[[nodiscard]] Vec2 centre_of_mass_velocity(const System& system);

/// H_O = sum_b m_b (x_b y_b' - y_b x_b') + I_b theta_b', about the world origin.
[[nodiscard]] GiNaC::ex angular_momentum(const System& system);

/// H_c, about the mechanism's centre of mass: constant when only uniform gravity acts
/// from outside (a floating mechanism), where H_O is not.
[[nodiscard]] GiNaC::ex angular_momentum_about_centre(const System& system);

}  // namespace linkage::sym
