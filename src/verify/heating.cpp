// adiabatic-heating: the temperature path of ImpactMaterial::update against a closed form. One
// material point of a copper-like ImpactMaterial (Mie-Gruneisen EOS; linear hardening
// sigma_y = sigma0 + H eps_p, no rate or thermal softening) is driven, without a mesh, through
// isochoric pure shear dF = Q diag(e^dg, e^-dg, 1) Q^T at a constant rate. The path is coaxial, so
// the equivalent strain is x = (2/sqrt 3) gamma and, once yielded, 3G (x - eps_p) = sigma0 + H eps_p
// gives eps_p = (3G x - sigma0)/(3G + H). Adiabatic heating by the Taylor-Quinney share beta of
// the plastic work (no volume change: no Gruneisen term, no bulk viscosity):
//   T - T0 = beta / (rho c_v) * int_0^eps_p sigma_y de = beta (sigma0 eps_p + H eps_p^2 / 2) / (rho c_v),
// and the specific internal energy holds the plastic work plus the stored deviatoric elastic
// energy sigma_y^2 / (6G) (log-strain Hencky energy G |dev eps_e|^2):
//   e - e0 = (sigma0 eps_p + H eps_p^2 / 2 + sigma_y^2 / (6G)) / rho.
// The update integrates the plastic work by backward Euler (sigma_y at the end of each step), which
// overestimates the integral by H sum(d eps_p^2)/2 ~ H eps_p d eps_p / 2: 2.9e-5 relative here, within
// the tolerance of 1e-4.
#include "material/impact_material.hpp"
#include "verify/strength_problems.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler::verify {

Outcome adiabaticHeating() {
  const double rho = 8930.0, G = 47.7e9, cv = 383.0, beta = 0.9, T0 = 293.0;
  const double sigma0 = 400e6, H = 100e6;
  ImpactMaterialParameters p;
  p.eos = eos::MieGruneisen({.density = rho, .sound_speed = 3940.0, .slope = 1.489, .gamma0 = 2.02});
  p.shear_modulus = G;
  p.yield = strength::LinearHardening({.sigma0 = sigma0, .H = H});
  p.thermal.specific_heat = cv;
  p.thermal.taylor_quinney = beta;
  p.thermal.room_temperature = T0;
  const ImpactMaterial material("heating copper", p);

  PointStore points;
  points.resize(1);
  const double volume = 1e-9;
  points.mass[0] = rho * volume;
  points.volume[0] = points.volume0[0] = volume;
  points.spacing0[0] = 1e-3;
  material.initialise(points, 0, 1);

  // Shear to gamma = 0.9 (eps_p ~ 1) in 4000 steps at an equivalent strain rate of 1e4 /s.
  const int steps = 4000;
  const double gamma = 0.9, dg = gamma / steps, dt = 2.0 / std::sqrt(3.0) * dg / 1e4;
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Mat3 dF = Q * Vec3(std::exp(dg), std::exp(-dg), 1.0).asDiagonal() * Q.transpose();
  for (int k = 0; k < steps; ++k) {
    points.dF[0] = dF;
    points.F[0] = dF * points.F[0];
    points.volume[0] *= dF.determinant();
    material.update(points, 0, 1, dt);
  }

  const double x = 2.0 / std::sqrt(3.0) * gamma;
  const double eps_p = (3.0 * G * x - sigma0) / (3.0 * G + H);
  const double plastic_work = sigma0 * eps_p + 0.5 * H * eps_p * eps_p;
  const double sigma_y = sigma0 + H * eps_p;
  const double energy = (plastic_work + sigma_y * sigma_y / (6.0 * G)) / rho;
  const double e_energy = std::abs(points.energy[0] / energy - 1.0);
  const double e_strain = std::abs(points.plastic_strain[0] / eps_p - 1.0);
  Outcome o;
  o.name = "adiabatic-heating";
  o.quantity = "temperature rise (K)";
  o.measured = points.temperature[0] - T0;
  o.reference = beta * plastic_work / (rho * cv);
  o.tolerance = 1e-4;
  o = compare(o);
  // The internal energy and the plastic strain must hold to the same tolerance.
  o.passed = o.passed && e_energy <= 1e-4 && e_strain <= 1e-4;
  o.note = fmt::format(
      "pure shear to gamma {} in {} steps at 1e4/s: eps_p {:.6f} vs {:.6f} ({:.1e}); e - e0 {:.6g} J/kg "
      "vs {:.6g} ({:.1e}); tol 1e-4 each",
      gamma, steps, points.plastic_strain[0], eps_p, e_strain, points.energy[0], energy, e_energy);
  return o;
}

}  // namespace kessler::verify
