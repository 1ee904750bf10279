#include "material/neo_hookean.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler {

void NeoHookeanParameters::check() const {
  if (!(density > 0.0)) throw InputError(fmt::format("density must be positive, got {}", density));
  if (!(youngs_modulus > 0.0)) throw InputError(fmt::format("youngs_modulus must be positive, got {}", youngs_modulus));
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    throw InputError(fmt::format("poisson_ratio must lie in (-1, 0.5), got {}", poisson_ratio));
  if (!(fracture_energy >= 0.0))
    throw InputError(fmt::format("fracture_energy must not be negative, got {}", fracture_energy));
}

NeoHookean::NeoHookean(std::string name, const NeoHookeanParameters& parameters)
    : name_(std::move(name)), p_(parameters), mu_(parameters.shearModulus()), lambda_(parameters.lameLambda()) {
  p_.check();
}

double NeoHookean::referenceSoundSpeed() const {
  return std::sqrt((lambda_ + 2.0 * mu_) / p_.density);
}

Mat3 NeoHookean::stress(const Mat3& F) const {
  const double J = F.determinant();
  const Mat3 B = F * F.transpose();
  return (mu_ * (B - Mat3::Identity()) + lambda_ * std::log(J) * Mat3::Identity()) / J;
}

double NeoHookean::energyDensity(const Mat3& F) const {
  const double J = F.determinant();
  const double lnJ = std::log(J);
  return 0.5 * mu_ * ((F * F.transpose()).trace() - 3.0) - mu_ * lnJ + 0.5 * lambda_ * lnJ * lnJ;
}

void NeoHookean::update(PointStore& points, LocalIndex begin, LocalIndex end, double /*dt*/) const {
  const double rho0 = p_.density;
#pragma omp parallel for schedule(static)
  for (LocalIndex p = begin; p < end; ++p) {
    if (points.broken[p]) {
      // Debris: no stress; its internal energy (the strain energy it had, and any heat of
      // erosion and capture) stays.
      points.stress[p].setZero();
      continue;
    }
    const Mat3& F = points.F[p];
    const double J = F.determinant();
    points.stress[p] = stress(F);
    const double w = energyDensity(F);
    points.energy[p] = w / rho0;
    points.strain_energy[p] = w;
    // Tangent wave speed of the deformed state: lambda and mu scale like 1/J in the spatial
    // moduli, with an extra (mu - lambda ln J) from the log term; take the larger, safe value.
    const double modulus = (lambda_ + 2.0 * (mu_ - lambda_ * std::log(J))) / J;
    const double rho = rho0 / J;
    points.sound_speed[p] = std::sqrt(std::max(modulus, lambda_ + 2.0 * mu_) / rho);
  }
}

}  // namespace kessler
