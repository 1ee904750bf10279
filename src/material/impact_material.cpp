#include "material/impact_material.hpp"

#include "core/error.hpp"
#include "material/strength/damage.hpp"
#include "material/strength/radial_return.hpp"

#include <cmath>
#include <limits>

namespace kessler {

ImpactMaterial::ImpactMaterial(std::string name, ImpactMaterialParameters parameters)
    : name_(std::move(name)), p_(std::move(parameters)) {
  if (!(p_.shear_modulus >= 0.0))
    throw InputError(fmt::format("shear_modulus must not be negative (got {})", p_.shear_modulus));
  p_.thermal.check();
  p_.viscosity.check();
  if (!(p_.spall_strength >= 0.0) || std::isinf(p_.spall_strength))
    throw InputError(fmt::format("spall_strength must be a finite tension of at least 0 (got {})", p_.spall_strength));
  if (std::isnan(p_.fracture_min_triaxiality) || p_.fracture_min_triaxiality == std::numeric_limits<double>::infinity())
    throw InputError(
        fmt::format("fracture_min_triaxiality must be a finite number or none (got {})", p_.fracture_min_triaxiality));
}

double ImpactMaterial::referenceSoundSpeed() const {
  const double rho0 = referenceDensity();
  const eos::State s = std::visit([&](const auto& eos) { return eos.evaluate(rho0, 0.0); }, p_.eos);
  return std::sqrt(s.sound_speed2 + 4.0 * p_.shear_modulus / (3.0 * rho0));
}

double ImpactMaterial::tensileLimit() const {
  double limit = std::numeric_limits<double>::infinity();
  if (p_.spall_strength > 0.0) limit = p_.spall_strength;
  if (std::isfinite(p_.pressure_floor)) limit = std::min(limit, std::max(-p_.pressure_floor, 0.0));
  return limit;
}

double ImpactMaterial::poissonRatio() const {
  // From the bulk modulus of the reference state and the shear modulus: nu = (3K - 2G)/(6K + 2G).
  const double rho0 = referenceDensity();
  const eos::State s = std::visit([&](const auto& eos) { return eos.evaluate(rho0, 0.0); }, p_.eos);
  const double K = rho0 * s.sound_speed2, G = p_.shear_modulus;
  return (3.0 * K - 2.0 * G) / (6.0 * K + 2.0 * G);
}

void ImpactMaterial::initialise(PointStore& points, LocalIndex begin, LocalIndex end) const {
  for (LocalIndex p = begin; p < end; ++p) {
    points.temperature[p] = p_.thermal.room_temperature;
    points.be[p] = Mat3::Identity();
  }
}

namespace {

// Everything one point needs besides its own state: resolved once per range.
struct UpdateConstants {
  double dt, shear_modulus, cv, beta, floor, spall, c_linear, c_quadratic, min_triaxiality;
  const std::optional<strength::JohnsonCookDamage>* damage;
};

// One point (docs/theory.md §5). The deviator comes from the log-strain radial return; the
// pressure from the equation of state at the new density and an internal energy updated with
// the work of the step, p dV by a predictor-corrector (trapezoidal rule), the deviatoric work by
// the midpoint rule; the artificial viscosity q adds to the pressure and its work heats.
// A failed point (PointStore::failed: fractured, not yet released) has no deviator and bears
// compression only, as a hydrocode's failed cell does (docs/theory.md §8): the pressure of the
// equation of state while it is denser than its reference (the fragments squeezed together), none
// once it has expanded; the same energy update gives it the work of that pressure and of the
// viscosity.
template <typename Eos, typename Law>
void updatePoint(const Eos& eos, const Law& law, const UpdateConstants& k, PointStore& points, LocalIndex p) {
  const double m = points.mass[p];
  const double volume = points.volume[p];
  const Mat3& dF = points.dF[p];
  const double j_step = dF.determinant();
  const double volume_old = volume / j_step;
  const double rho = m / volume;
  const double dv = volume - volume_old;
  const double h = points.spacing(p);
  const double J = points.F[p].determinant();

  const Mat3 stress_old = points.stress[p];
  const double q_old = points.viscous_pressure[p];
  const double p_old = -stress_old.trace() / 3.0 - q_old;
  const Mat3 s_old = stress_old + (p_old + q_old) * Mat3::Identity();

  const bool failed = points.failed(p);
  const double shear = failed ? 0.0 : k.shear_modulus;
  // Plain sound speed at the new density and old energy, for the viscosity.
  const eos::State guess = eos.evaluate(rho, points.energy[p]);
  const double c_bulk = std::sqrt(std::max(guess.sound_speed2, 0.0) + 4.0 * shear / (3.0 * rho));
  const double div_v = k.dt > 0.0 ? std::log(j_step) / k.dt : 0.0;
  // The limiter phi (Christensen 1990, as in LULESH) takes both terms off where the compression is
  // smooth over the point's support, the linear as (1 - phi) and the quadratic as (1 - phi^2), so that
  // a smooth compression is not heated (Noh 1987); left whole, the linear term heated a 2 km/s
  // plate's shocked plateau 6% above the Rankine-Hugoniot energy (docs/theory.md §5).
  const double phi = points.viscosity_limiter[p];
  const double linear = (1.0 - phi) * k.c_linear, quadratic = (1.0 - phi * phi) * k.c_quadratic;
  const double q = div_v < 0.0 ? rho * (quadratic * h * h * div_v * div_v - linear * h * c_bulk * div_v) : 0.0;

  // Deviator by radial return (plastic strain, elastic b_e updated in place); none once failed.
  strength::ReturnResult r;
  if (!failed) {
    strength::ReturnInput in;
    in.dF = dF;
    in.dt = k.dt;
    in.shear_modulus = k.shear_modulus;
    in.temperature = points.temperature[p];
    in.melt_temperature = law.meltingTemperature(J);
    r = strength::radialReturnWith(law, in, points.be[p], points.plastic_strain[p]);
  } else {
    r.deviatoric_stress.setZero();
  }
  const double floor = failed ? 0.0 : k.floor;
  // Expanded fractured material pushes no more: the fragments have separated.
  const bool separated = failed && volume >= points.volume0[p];

  // Rate of deformation over the step by the midpoint rule: D dt = sym(2 (dF - I)(dF + I)^-1).
  const Mat3 l_dt = 2.0 * (dF - Mat3::Identity()) * (dF + Mat3::Identity()).inverse();
  const Mat3 d_dt = 0.5 * (l_dt + l_dt.transpose());
  const Mat3 d_dev = d_dt - d_dt.trace() / 3.0 * Mat3::Identity();
  const double deviatoric_work =
      0.5 * (s_old + r.deviatoric_stress).cwiseProduct(d_dev).sum() * 0.5 * (volume + volume_old);
  // The viscous pressure's work with the mean of the old q (which the step's forces carried) and the
  // new one (which the next step's will), as the pressure's: booked with the new q alone, it differs
  // from what the forces did wherever the compression rate changes from step to step (in flyer-plate
  // by 0.3% of the energy jump; docs/theory.md §5).
  const double viscous_work = -0.5 * (q_old + q) * dv;

  const double e_old = points.energy[p];
  const double e_pred = e_old + (-p_old * dv + deviatoric_work + viscous_work) / m;
  const double p_eos = eos.evaluate(rho, e_pred).pressure;
  const double p_pred = separated ? 0.0 : failed ? std::max(p_eos, 0.0) : p_eos;
  const double e_new = e_old + (-0.5 * (p_old + p_pred) * dv + deviatoric_work + viscous_work) / m;
  const eos::State state = eos.evaluate(rho, e_new);
  const double pressure = separated ? 0.0 : std::max(state.pressure, floor);

  // Heat: the Taylor-Quinney share of plastic work, the viscous work (shock heating), and the
  // reversible Gruneisen cooling/heating dT = -T Gamma dV/V with Gamma = (dp/de)/rho.
  const double plastic_heat = k.beta * r.plastic_work * volume;
  const double gamma = state.dp_de / rho;
  double T = points.temperature[p];
  T += (plastic_heat + viscous_work) / (m * k.cv) - T * gamma * std::log(j_step);
  points.temperature[p] = std::max(T, 0.0);

  double damage = points.damage[p];
  if (*k.damage && r.plastic_increment > 0.0) {
    const double sigma_eq = std::sqrt(1.5) * r.deviatoric_stress.norm();
    const double triaxiality = sigma_eq > 0.0 ? -pressure / sigma_eq : 0.0;
    const double rate = k.dt > 0.0 ? r.plastic_increment / k.dt : 0.0;
    damage = std::min(1.0, damage + (*k.damage)->increment(r.plastic_increment, triaxiality, rate, T));
    points.damage[p] = damage;
  }

  points.energy[p] = e_new;
  // Energy density for eigenerosion (per reference volume): elastic deviatoric energy, elastic
  // volumetric energy in tension only (compression does not open cracks), and the plastic work
  // done at a stress triaxiality -(p + q)/sigma_eq of at least the material's cut-off (Bao &
  // Wierzbicki, Eng. Fract. Mech. 72:1049, 2005: metals do not fracture below -1/3; in a shock the
  // pressure exceeds the flow stress a hundredfold); docs/theory.md §8.
  const double bulk = rho * std::max(state.sound_speed2, 0.0);
  const double sigma_eq = std::sqrt(1.5) * r.deviatoric_stress.norm();
  if (std::isinf(k.min_triaxiality) || -(pressure + q) >= k.min_triaxiality * sigma_eq)
    points.ductile_work[p] += r.plastic_work * volume / points.volume0[p];
  const double tension = pressure < 0.0 && bulk > 0.0 ? pressure * pressure / (2.0 * bulk) : 0.0;
  const double elastic = k.shear_modulus > 0.0 ? r.deviatoric_stress.squaredNorm() / (4.0 * k.shear_modulus) : 0.0;
  points.strain_energy[p] = (elastic + tension) * J + points.ductile_work[p];
  points.viscous_pressure[p] = q;
  const double c = std::sqrt(std::max(state.sound_speed2, 0.0) + 4.0 * shear / (3.0 * rho));
  // Signal speed with the viscosity correction of the stable step (e.g. LS-DYNA theory manual):
  // dt = h / (Q + sqrt(Q^2 + c^2)), Q = C_l c + C_q h |div v| (limited as q) when compressing.
  const double Q = div_v < 0.0 ? linear * c + quadratic * h * std::abs(div_v) : 0.0;
  points.sound_speed[p] = Q + std::sqrt(Q * Q + c * c);
  // Fractured by ductile damage or by spall (the equation of state's tension reaching the spall
  // strength): from now on compression only.
  if (!failed && (damage >= 1.0 || (k.spall > 0.0 && state.pressure <= -k.spall))) {
    points.fail(p);
    points.stress[p] = -(std::max(pressure, 0.0) + q) * Mat3::Identity();
    return;
  }
  points.stress[p] = r.deviatoric_stress - (pressure + q) * Mat3::Identity();
}

}  // namespace

void ImpactMaterial::heat(PointStore& points, LocalIndex begin, LocalIndex end, std::span<const double> heat) const {
  const double cv = p_.thermal.specific_heat;
#pragma omp parallel for schedule(static)
  for (LocalIndex p = begin; p < end; ++p) {
    const double q = heat[static_cast<std::size_t>(p - begin)];
    if (q == 0.0 || points.debris(p)) continue;
    points.energy[p] += q / points.mass[p];
    points.temperature[p] += q / (points.mass[p] * cv);
  }
}

void ImpactMaterial::update(PointStore& points, LocalIndex begin, LocalIndex end, double dt) const {
  std::optional<strength::JohnsonCookDamage> damage;
  if (p_.damage) damage.emplace(*p_.damage);
  const UpdateConstants k{dt,
                          p_.shear_modulus,
                          p_.thermal.specific_heat,
                          p_.thermal.taylor_quinney,
                          p_.pressure_floor,
                          p_.spall_strength,
                          p_.viscosity.linear,
                          p_.viscosity.quadratic,
                          p_.fracture_min_triaxiality,
                          &damage};
  LocalIndex failed = end;
  std::string why;
  std::visit(
      [&](const auto& eos, const auto& law) {
        // Dynamic: points in plastic flow (the impact zone, all in one part of the body) cost
        // several times more than elastic ones, and each point's update is its own.
#pragma omp parallel for schedule(dynamic, 512)
        for (LocalIndex p = begin; p < end; ++p) {
          if (points.debris(p)) {
            // Debris: keeps mass and momentum, carries no stress.
            points.stress[p].setZero();
            points.viscous_pressure[p] = 0.0;
            continue;
          }
          // An exception must not leave the parallel loop (it would end the program): the first
          // failing point, by index, is kept and reported once the loop is done.
          try {
            updatePoint(eos, law, k, points, p);
          } catch (const NumericalError& e) {
#pragma omp critical(kessler_material_failure)
            if (p < failed) {
              failed = p;
              why = e.what();
            }
          }
        }
      },
      p_.eos, p_.yield);
  if (failed < end) throw PointError(failed, why);
}

}  // namespace kessler
