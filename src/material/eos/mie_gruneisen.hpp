#pragma once
// Mie-Gruneisen equation of state referenced to the shock Hugoniot Us = c0 + s up, with
// Gamma rho = Gamma0 rho0 (docs/eos.md; e.g. Steinberg 1996, Meyers "Dynamic Behavior of
// Materials" §4.6). Hugoniot reference in compression (mu = rho/rho0 - 1 > 0):
//   p_H = rho0 c0^2 mu (1 + mu) / (1 - (s - 1) mu)^2,  e_H = p_H mu / (2 rho0 (1 + mu)),
//   p = p_H + Gamma rho (e - e_H).
// In expansion (mu < 0) the reference is the linear p_H = rho0 c0^2 mu, e_H = 0 (a common,
// smooth continuation; document any other choice).
#include "material/eos/state.hpp"

namespace kessler::eos {

struct MieGruneisenParameters {
  double density = 0.0;      // rho0, kg/m^3
  double sound_speed = 0.0;  // c0, m/s
  double slope = 0.0;        // s, dimensionless
  double gamma0 = 0.0;       // Gruneisen Gamma0
  void check() const;        // throws kessler::InputError naming the bad parameter
};

class MieGruneisen {
 public:
  MieGruneisen() = default;  // unchecked zero parameters, so configurations can be default-built
  explicit MieGruneisen(const MieGruneisenParameters& p);
  State evaluate(double rho, double e) const;
  double referenceDensity() const { return p_.density; }
  const MieGruneisenParameters& parameters() const { return p_; }

 private:
  MieGruneisenParameters p_;
};

}  // namespace kessler::eos
