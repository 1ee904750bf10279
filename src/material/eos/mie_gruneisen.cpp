// Mie-Gruneisen EOS on the linear Us-up Hugoniot (Meyers 1994, §4), with
// Gamma rho = Gamma0 rho0. With mu = rho/rho0 - 1 the Hugoniot is written in mu, and its
// derivatives are analytic, so c^2 is exact up to rounding (docs/eos.md).
#include "material/eos/mie_gruneisen.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler::eos {

namespace {

void require(bool ok, const char* name, const char* what, double value) {
  if (!ok) throw InputError(fmt::format("eos.{} must be {} (got {})", name, what, value));
}

}  // namespace

void MieGruneisenParameters::check() const {
  require(std::isfinite(density) && density > 0.0, "density", "positive", density);
  require(std::isfinite(sound_speed) && sound_speed > 0.0, "sound_speed", "positive", sound_speed);
  require(std::isfinite(slope) && slope >= 0.0, "slope", "non-negative", slope);
  require(std::isfinite(gamma0) && gamma0 >= 0.0, "gamma0", "non-negative", gamma0);
}

MieGruneisen::MieGruneisen(const MieGruneisenParameters& p) : p_(p) {
  p_.check();
}

State MieGruneisen::evaluate(double rho, double e) const {
  if (!(rho > 0.0 && std::isfinite(rho) && std::isfinite(e)))
    throw NumericalError(fmt::format("mie-gruneisen EOS: invalid state rho = {} kg/m^3, e = {} J/kg", rho, e));
  const double rho0 = p_.density;
  const double k0 = rho0 * p_.sound_speed * p_.sound_speed;
  const double mu = rho / rho0 - 1.0;
  const double dp_de = p_.gamma0 * rho0;  // Gamma rho = Gamma0 rho0

  double p_h = 0.0, e_h = 0.0, dph_dmu = 0.0, deh_dmu = 0.0;
  if (mu > 0.0) {
    // p_H = rho0 c0^2 mu (1+mu) / d^2 with d = 1 - (s-1) mu; it diverges at mu_max = 1/(s-1)
    // (s > 1), where the shock velocity of the linear fit would have to be infinite.
    const double d = 1.0 - (p_.slope - 1.0) * mu;
    if (!(d > 0.0))
      throw NumericalError(fmt::format(
          "mie-gruneisen EOS: compression rho/rho0 = {:.6g} (rho = {:.6g} kg/m^3) reaches the Hugoniot limit "
          "rho/rho0 = s/(s-1) = {:.6g} of the linear Us-up fit (s = {})",
          rho / rho0, rho, p_.slope / (p_.slope - 1.0), p_.slope));
    const double f = mu * (1.0 + mu) / (d * d);
    const double df = ((1.0 + 2.0 * mu) * d + 2.0 * (p_.slope - 1.0) * mu * (1.0 + mu)) / (d * d * d);
    p_h = k0 * f;
    dph_dmu = k0 * df;
    // e_H = p_H (1/rho0 - 1/rho) / 2 (Rankine-Hugoniot energy jump from the reference state).
    const double g = mu / (1.0 + mu);
    const double dg = 1.0 / ((1.0 + mu) * (1.0 + mu));
    e_h = 0.5 * p_h * g / rho0;
    deh_dmu = 0.5 * (dph_dmu * g + p_h * dg) / rho0;
  } else {
    // Expansion: the linear reference p = rho0 c0^2 mu, e_ref = 0 (C1 at mu = 0, see the header).
    p_h = k0 * mu;
    dph_dmu = k0;
  }
  State s;
  s.pressure = p_h + dp_de * (e - e_h);
  s.dp_de = dp_de;
  const double dp_drho = (dph_dmu - dp_de * deh_dmu) / rho0;
  s.sound_speed2 = floorSoundSpeed2(dp_drho + s.pressure / (rho * rho) * dp_de, k0, rho);
  return s;
}

}  // namespace kessler::eos
