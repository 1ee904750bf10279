// Ideal-gas EOS (e.g. Zel'dovich & Raizer 1966, "Physics of Shock Waves and High-Temperature
// Hydrodynamic Phenomena", ch. I):
//   p = (gamma - 1) rho e,   dp/de|_rho = (gamma - 1) rho,   dp/drho|_e = (gamma - 1) e,
//   c^2 = dp/drho|_e + p/rho^2 dp/de|_rho = gamma (gamma - 1) e = gamma p / rho.
// c^2 goes to 0 with e and is not floored (no reference modulus to floor it against): the Noh
// problem starts from p0 = 0 (Noh 1987, J. Comput. Phys. 72:78).
#include "material/eos/ideal_gas.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace kessler::eos {

namespace {

void require(bool ok, const char* name, const char* what, double value) {
  if (!ok) throw InputError(fmt::format("eos.{} must be {} (got {})", name, what, value));
}

}  // namespace

void IdealGasParameters::check() const {
  require(std::isfinite(density) && density > 0.0, "density", "positive", density);
  // gamma = 1 would be an isothermal gas with no pressure from its energy; gamma < 1 has c^2 < 0.
  require(std::isfinite(gamma) && gamma > 1.0, "gamma", "greater than 1", gamma);
}

IdealGas::IdealGas(const IdealGasParameters& p) : p_(p) {
  p_.check();
}

State IdealGas::evaluate(double rho, double e) const {
  if (!(rho > 0.0 && std::isfinite(rho) && std::isfinite(e)))
    throw NumericalError(fmt::format("ideal-gas EOS: invalid state rho = {} kg/m^3, e = {} J/kg", rho, e));
  // A gas has no energy below its cold state e = 0; a slightly negative e is the round-off of the
  // energy update (a cold gas expanding), so it counts as 0 rather than giving p < 0 and c^2 < 0.
  const double energy = std::max(e, 0.0);
  State s;
  s.dp_de = (p_.gamma - 1.0) * rho;
  s.pressure = s.dp_de * energy;
  s.sound_speed2 = p_.gamma * (p_.gamma - 1.0) * energy;
  return s;
}

}  // namespace kessler::eos
