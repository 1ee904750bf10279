// Cubic polynomial EOS (LS-DYNA *EOS_LINEAR_POLYNOMIAL with C0 = C4 = C6 = 0, C5 = Gamma0):
// p = K1 mu + K2 mu^2 + K3 mu^3 + Gamma0 rho e, with the K2, K3 terms dropped in tension.
#include "material/eos/polynomial.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler::eos {

namespace {

void require(bool ok, const char* name, const char* what, double value) {
  if (!ok) throw InputError(fmt::format("eos.{} must be {} (got {})", name, what, value));
}

}  // namespace

void PolynomialParameters::check() const {
  require(std::isfinite(density) && density > 0.0, "density", "positive", density);
  require(std::isfinite(k1) && k1 > 0.0, "k1", "positive", k1);
  require(std::isfinite(k2), "k2", "finite", k2);
  require(std::isfinite(k3), "k3", "finite", k3);
  require(std::isfinite(gamma0) && gamma0 >= 0.0, "gamma0", "non-negative", gamma0);
}

Polynomial::Polynomial(const PolynomialParameters& p) : p_(p) {
  p_.check();
}

State Polynomial::evaluate(double rho, double e) const {
  if (!(rho > 0.0 && std::isfinite(rho) && std::isfinite(e)))
    throw NumericalError(fmt::format("polynomial EOS: invalid state rho = {} kg/m^3, e = {} J/kg", rho, e));
  const double mu = rho / p_.density - 1.0;
  double cold = p_.k1 * mu;
  double dcold_dmu = p_.k1;
  if (mu > 0.0) {
    cold += mu * mu * (p_.k2 + p_.k3 * mu);
    dcold_dmu += mu * (2.0 * p_.k2 + 3.0 * p_.k3 * mu);
  }
  State s;
  s.dp_de = p_.gamma0 * rho;  // Gamma0 E (1 + mu) with E = rho0 e
  s.pressure = cold + s.dp_de * e;
  const double dp_drho = dcold_dmu / p_.density + p_.gamma0 * e;
  s.sound_speed2 = floorSoundSpeed2(dp_drho + s.pressure / (rho * rho) * s.dp_de, p_.k1, rho);
  return s;
}

}  // namespace kessler::eos
