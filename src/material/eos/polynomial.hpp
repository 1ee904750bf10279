#pragma once
// Cubic polynomial equation of state (docs/eos.md), mu = rho/rho0 - 1:
//   p = K1 mu + K2 mu^2 + K3 mu^3 + Gamma0 E (1 + mu),
// with E = rho0 e the internal energy per unit reference volume (so the energy term is
// Gamma0 rho e). In tension (mu < 0) the K2 and K3 terms are dropped, the usual convention
// (e.g. LS-DYNA's linear-polynomial EOS).
#include "material/eos/state.hpp"

namespace kessler::eos {

struct PolynomialParameters {
  double density = 0.0;  // rho0, kg/m^3
  double k1 = 0.0;       // Pa (bulk modulus)
  double k2 = 0.0;       // Pa
  double k3 = 0.0;       // Pa
  double gamma0 = 0.0;
  void check() const;
};

class Polynomial {
 public:
  Polynomial() = default;  // unchecked zero parameters, so configurations can be default-built
  explicit Polynomial(const PolynomialParameters& p);
  State evaluate(double rho, double e) const;
  double referenceDensity() const { return p_.density; }
  const PolynomialParameters& parameters() const { return p_; }

 private:
  PolynomialParameters p_;
};

}  // namespace kessler::eos
