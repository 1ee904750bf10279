#pragma once
// Compressible neo-Hookean elasticity, used to verify the kinematics before impact physics:
//   W(F) = mu/2 (tr B - 3) - mu ln J + lambda/2 (ln J)^2,   B = F F^T, J = det F,
//   sigma = [mu (B - I) + lambda ln J I] / J
// (e.g. Bonet & Wood, Nonlinear Continuum Mechanics, 2nd ed., eqs. 6.27-6.29).
#include "material/material.hpp"

namespace kessler {

struct NeoHookeanParameters {
  double density = 0.0;          // kg/m^3
  double youngs_modulus = 0.0;   // Pa
  double poisson_ratio = 0.0;
  double fracture_energy = 0.0;  // G_c for eigenerosion, J/m^2 (0: none)

  // Throws kessler::InputError if a parameter is unphysical.
  void check() const;
  double shearModulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double lameLambda() const {
    return youngs_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  double bulkModulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
};

class NeoHookean final : public Material {
 public:
  NeoHookean(std::string name, const NeoHookeanParameters& parameters);
  const std::string& name() const override { return name_; }
  double referenceDensity() const override { return p_.density; }
  double referenceSoundSpeed() const override;
  double fractureEnergy() const override { return p_.fracture_energy; }
  double poissonRatio() const override { return p_.poisson_ratio; }
  void update(PointStore& points, LocalIndex begin, LocalIndex end, double dt) const override;

  // Point-wise law, exposed for unit tests.
  Mat3 stress(const Mat3& F) const;
  double energyDensity(const Mat3& F) const;  // per reference volume

 private:
  std::string name_;
  NeoHookeanParameters p_;
  double mu_, lambda_;
};

}  // namespace kessler
