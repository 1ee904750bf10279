#pragma once
// What an equation of state returns at one (rho, e).
#include <algorithm>

namespace kessler::eos {

struct State {
  double pressure = 0.0;        // Pa
  double sound_speed2 = 0.0;    // squared adiabatic (isentropic) sound speed, m^2/s^2:
                                // c^2 = dp/drho|_e + (p / rho^2) dp/de|_rho
  double dp_de = 0.0;           // dp/de at constant rho (= Gruneisen Gamma * rho), kg/m^3
};

// Floor on the squared sound speed: the effective bulk modulus rho c^2 is kept at or above
// this fraction of the model's reference bulk modulus K0 (rho0 c0^2, K1, A or the table's B0).
// The analytic c^2 can turn negative in deep tension or in the Tillotson partial-vaporisation
// region, where the formulas leave their fitted range; the floor is a guard that keeps the CFL
// step and the artificial viscosity defined, not physics (docs/eos.md, "Floors").
inline constexpr double sound_speed2_floor_fraction = 1e-4;

inline double floorSoundSpeed2(double c2, double reference_modulus, double rho) {
  return std::max(c2, sound_speed2_floor_fraction * reference_modulus / rho);
}

}  // namespace kessler::eos
