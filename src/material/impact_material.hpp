#pragma once
// The material of an impact body: an equation of state for the pressure, J2 plasticity for
// the deviator (with melting), heating, artificial bulk viscosity and optional Johnson-Cook
// damage, composed into one Material (docs/materials.md). The models are chosen once per material
// (variants visited once per range of points), never per point.
#include "material/eos/eos.hpp"
#include "material/material.hpp"
#include "material/strength/damage.hpp"
#include "material/strength/yield.hpp"

#include <limits>
#include <optional>
#include <string>

namespace kessler {

struct ThermalParameters {
  double specific_heat = 0.0;       // c_v, J/(kg K)
  double taylor_quinney = 0.9;      // fraction of plastic work that heats
  double room_temperature = 293.0;  // initial temperature, K
  void check() const;
};

// Linear and quadratic bulk viscosity (von Neumann-Richtmyer; e.g. Benson, CMAME 99, 1992) with
// Christensen's monotonic limiter phi on both terms, as in LULESH (PointStore::viscosity_limiter, set
// by the discretisation):
//   q = rho l ((1 - phi^2) C_q l |div v| - (1 - phi) C_l c) div v   when compressing, else 0.
// C_l = 0.5 as LULESH's monotonic q: with 0.06 a 6 km/s shock rings behind its front in 3-D
// (docs/theory.md §5).
struct ViscosityParameters {
  double linear = 0.5;
  double quadratic = 1.5;
  void check() const;
};

struct ImpactMaterialParameters {
  eos::Eos eos;                // also gives the reference density
  double shear_modulus = 0.0;  // G, Pa (0: no strength)
  strength::Yield yield = strength::NoStrength{};
  std::optional<strength::JohnsonCookDamageParameters> damage;
  ThermalParameters thermal;
  double pressure_floor = -std::numeric_limits<double>::infinity();  // tension cut-off, Pa
  // Spall: an intact point fails (PointStore::fail) once its pressure falls to -spall_strength, Pa
  // (0: never), as a hydrocode's minimum-pressure failure (docs/theory.md §8).
  double spall_strength = 0.0;
  ViscosityParameters viscosity;
  double fracture_energy = 0.0;  // G_c for eigenerosion, J/m^2 (0: no eigenerosion)
  // Plastic work drives eigenerosion only where the stress triaxiality (mean stress / von Mises
  // stress) is at least this; -infinity: all of it. Bao & Wierzbicki's cut-off is -1/3.
  double fracture_min_triaxiality = -std::numeric_limits<double>::infinity();
};

class ImpactMaterial final : public Material {
 public:
  ImpactMaterial(std::string name, ImpactMaterialParameters parameters);
  const std::string& name() const override { return name_; }
  double referenceDensity() const override { return eos::referenceDensity(p_.eos); }
  double referenceSoundSpeed() const override;
  double fractureEnergy() const override { return p_.fracture_energy; }
  double tensileLimit() const override;
  double poissonRatio() const override;
  void initialise(PointStore& points, LocalIndex begin, LocalIndex end) const override;
  void update(PointStore& points, LocalIndex begin, LocalIndex end, double dt) const override;
  // Into the specific internal energy and, through the specific heat, the temperature.
  void heat(PointStore& points, LocalIndex begin, LocalIndex end, std::span<const double> heat) const override;
  bool takesHeat() const override { return true; }
  const ImpactMaterialParameters& parameters() const { return p_; }

 private:
  std::string name_;
  ImpactMaterialParameters p_;
};

}  // namespace kessler
