// adiabatic-heating: the temperature path of ImpactMaterial::update against a closed form. One
// material point of a copper-like ImpactMaterial (linear hardening sigma_y = sigma0 + H eps_p, no
// rate or thermal softening) is driven, without a mesh, at a constant rate along two coaxial
// paths, on which the equivalent strain x is known and, once yielded, 3G (x - eps_p) = sigma0 +
// H eps_p gives eps_p = (3G x - sigma0)/(3G + H). Adiabatic heating by the Taylor-Quinney share
// beta of the plastic work (per unit reference volume):
//   T - T0 = beta / (rho0 c_v) * int_0^eps_p sigma_y de = beta (sigma0 eps_p + H eps_p^2 / 2) / (rho0 c_v).
//   (a) isochoric pure shear dF = Q diag(e^dg, e^-dg, 1) Q^T, x = (2/sqrt 3) gamma, with a
//       Mie-Gruneisen EOS (no volume change: no Gruneisen term, no bulk viscosity). The specific
//       internal energy holds the plastic work plus the stored deviatoric elastic energy
//       sigma_y^2 / (6G) (log-strain Hencky energy G |dev eps_e|^2): e - e0 = (that sum) / rho0.
//   (b) uniaxial compression dF = diag(1, 1, e^de) to eps_zz = -0.3 (J = 0.74), x = (2/3)|eps_zz|,
//       with a linear bulk response without Gruneisen term (polynomial EOS, Gamma0 = 0) and no
//       bulk viscosity, so that only the plastic work heats: checks its scaling with the volume.
// The update integrates the plastic work by backward Euler (sigma_y at the end of each step), which
// overestimates the integral by H sum(d eps_p^2)/2 ~ H eps_p d eps_p / 2: 2.9e-5 relative on path
// (a), within the tolerance of 1e-4.
#include "material/impact_material.hpp"
#include "verify/strength_problems.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace kessler::verify {
namespace {

constexpr double rho = 8930.0, G = 47.7e9, cv = 383.0, beta = 0.9, T0 = 293.0;
constexpr double sigma0 = 400e6, H = 100e6;

ImpactMaterialParameters copper(const eos::Eos& eos) {
  ImpactMaterialParameters p;
  p.eos = eos;
  p.shear_modulus = G;
  p.yield = strength::LinearHardening({.sigma0 = sigma0, .H = H});
  p.thermal.specific_heat = cv;
  p.thermal.taylor_quinney = beta;
  p.thermal.room_temperature = T0;
  return p;
}

struct PointState {
  double temperature_rise = 0.0, energy = 0.0, plastic_strain = 0.0;
};

// Applies the same increment dF `steps` times to one point of `material`.
PointState drive(const ImpactMaterial& material, const Mat3& dF, int steps, double dt) {
  PointStore points;
  points.resize(1);
  const double volume = 1e-9;
  points.mass[0] = rho * volume;
  points.volume[0] = points.volume0[0] = volume;
  points.spacing0[0] = 1e-3;
  material.initialise(points, 0, 1);
  for (int k = 0; k < steps; ++k) {
    points.dF[0] = dF;
    points.F[0] = dF * points.F[0];
    points.volume[0] *= dF.determinant();
    material.update(points, 0, 1, dt);
  }
  return {points.temperature[0] - T0, points.energy[0], points.plastic_strain[0]};
}

double plasticStrain(double x) {
  return (3.0 * G * x - sigma0) / (3.0 * G + H);
}
double plasticWork(double eps_p) {
  return sigma0 * eps_p + 0.5 * H * eps_p * eps_p;
}
double relative(double value, double reference) {
  return std::abs(value / reference - 1.0);
}

}  // namespace

Outcome adiabaticHeating() {
  const int steps = 4000;
  // (a) Pure shear to gamma = 0.9 (eps_p ~ 1) at an equivalent strain rate of 1e4 /s.
  const ImpactMaterial shear_material(
      "heating copper",
      copper(eos::MieGruneisen({.density = rho, .sound_speed = 3940.0, .slope = 1.489, .gamma0 = 2.02})));
  const double gamma = 0.9, dg = gamma / steps, x_a = 2.0 / std::sqrt(3.0) * gamma;
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Mat3 dF_a = Q * Vec3(std::exp(dg), std::exp(-dg), 1.0).asDiagonal() * Q.transpose();
  const PointState a = drive(shear_material, dF_a, steps, 2.0 / std::sqrt(3.0) * dg / 1e4);
  const double eps_a = plasticStrain(x_a);
  const double sigma_a = sigma0 + H * eps_a;
  const double energy_a = (plasticWork(eps_a) + sigma_a * sigma_a / (6.0 * G)) / rho;

  // (b) Uniaxial compression to eps_zz = -0.3 at 1e4 /s, without Gruneisen term or viscosity.
  ImpactMaterialParameters pb =
      copper(eos::Polynomial({.density = rho, .k1 = 140e9, .k2 = 0.0, .k3 = 0.0, .gamma0 = 0.0}));
  pb.viscosity.linear = pb.viscosity.quadratic = 0.0;
  const ImpactMaterial compression_material("heating copper, no viscosity", pb);
  const double strain = -0.3, de = strain / steps, x_b = 2.0 / 3.0 * std::abs(strain);
  const PointState b =
      drive(compression_material, Vec3(1.0, 1.0, std::exp(de)).asDiagonal(), steps, std::abs(de) / 1e4);
  const double eps_b = plasticStrain(x_b);

  const double rise_a = beta * plasticWork(eps_a) / (rho * cv), rise_b = beta * plasticWork(eps_b) / (rho * cv);
  const double e_rise_b = relative(b.temperature_rise, rise_b);
  const double e_energy = relative(a.energy, energy_a);
  const double e_strain = std::max(relative(a.plastic_strain, eps_a), relative(b.plastic_strain, eps_b));
  Outcome o;
  o.name = "adiabatic-heating";
  o.quantity = "temperature rise in pure shear (K)";
  o.measured = a.temperature_rise;
  o.reference = rise_a;
  o.tolerance = 1e-4;
  o = compare(o);
  // The compression path, the internal energy and the plastic strains must hold to the same tolerance.
  o.passed = o.passed && e_rise_b <= 1e-4 && e_energy <= 1e-4 && e_strain <= 1e-4;
  o.note = fmt::format(
      "pure shear to gamma {}, {} steps at 1e4/s: eps_p {:.6f} vs {:.6f}, e - e0 {:.6g} J/kg vs {:.6g} ({:.1e}); "
      "uniaxial compression to {}: T - T0 {:.4f} K vs {:.4f} ({:.1e}), eps_p {:.6f} vs {:.6f}; worst eps_p {:.1e}; "
      "tol 1e-4 each",
      gamma, steps, a.plastic_strain, eps_a, a.energy, energy_a, e_energy, strain, b.temperature_rise, rise_b, e_rise_b,
      b.plastic_strain, eps_b, e_strain);
  return o;
}

}  // namespace kessler::verify
