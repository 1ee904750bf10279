#pragma once
// Tillotson equation of state (Tillotson 1962; as in iSALE / Melosh "Impact Cratering" 1989,
// appendix II): compressed (or cold expanded, e < E_iv) branch, expanded vaporised branch
// (e > E_cv, rho < rho0), and a linear interpolation between them in the partial vaporisation
// region E_iv < e < E_cv for rho < rho0.
#include "material/eos/state.hpp"

namespace kessler::eos {

struct TillotsonParameters {
  double density = 0.0;    // rho0, kg/m^3
  double a = 0.0;          // dimensionless
  double b = 0.0;          // dimensionless
  double A = 0.0;          // Pa
  double B = 0.0;          // Pa
  double E0 = 0.0;         // J/kg
  double alpha = 0.0;
  double beta = 0.0;
  double E_iv = 0.0;       // J/kg, incipient vaporisation
  double E_cv = 0.0;       // J/kg, complete vaporisation
  void check() const;
};

class Tillotson {
 public:
  Tillotson() = default;  // unchecked zero parameters, so configurations can be default-built
  explicit Tillotson(const TillotsonParameters& p);
  State evaluate(double rho, double e) const;
  double referenceDensity() const { return p_.density; }
  const TillotsonParameters& parameters() const { return p_; }

 private:
  TillotsonParameters p_;
};

}  // namespace kessler::eos
