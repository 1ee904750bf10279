#include "material/library.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>

namespace kessler::library {

namespace {

// Johnson & Cook's own papers, cited by most entries.
constexpr const char* jc1983 =
    "Johnson & Cook 1983, 'A constitutive model and data for metals subjected to large strains, high strain "
    "rates and high temperatures', Proc. 7th Int. Symp. Ballistics, The Hague, Table 1";
constexpr const char* jc1985 =
    "Johnson & Cook 1985, 'Fracture characteristics of three metals subjected to various strains, strain rates, "
    "temperatures and pressures', Eng. Fract. Mech. 21(1) 31-48";
constexpr const char* steinberg =
    "Steinberg 1996, 'Equation of state and strength properties of selected "
    "materials', LLNL UCRL-MA-106439";
constexpr const char* liao =
    "Liao et al. 2022, 'OTM analysis of debris cloud under hypervelocity impact', "
    "Explosion and Shock Waves, Tables 1-2";
constexpr const char* fan =
    "Fan et al. 2019, 'Whipple shield hypervelocity impact based on OTM', "
    "Explosion and Shock Waves, Tables 1-2";
constexpr const char* taylor_quinney =
    "Taylor-Quinney coefficient 0.9: the customary value for metals "
    "(Taylor & Quinney 1934, Proc. R. Soc. A 143, 307)";
constexpr const char* viscosity =
    "bulk viscosity linear 0.5, quadratic 1.5, both with Christensen's monotonic limiter as in LULESH: "
    "Kessler's defaults (Benson 1992, CMAME 99; docs/theory.md §5), not a material property";

eos::MieGruneisen mieGruneisen(double density, double sound_speed, double slope, double gamma0) {
  return eos::MieGruneisen(
      eos::MieGruneisenParameters{.density = density, .sound_speed = sound_speed, .slope = slope, .gamma0 = gamma0});
}

strength::JohnsonCook johnsonCook(double A, double B, double n, double C, double m, double melt_temperature) {
  strength::JohnsonCookParameters p;
  p.A = A;
  p.B = B;
  p.n = n;
  p.C = C;
  p.m = m;
  p.rate0 = 1.0;  // J&C normalise the strain rate by 1/s
  p.room_temperature = 293.0;
  p.melt_temperature = melt_temperature;
  return strength::JohnsonCook(p);
}

strength::JohnsonCookDamageParameters johnsonCookDamage(double D1, double D2, double D3, double D4, double D5,
                                                        double melt_temperature) {
  strength::JohnsonCookDamageParameters p;
  p.D1 = D1;
  p.D2 = D2;
  p.D3 = D3;
  p.D4 = D4;
  p.D5 = D5;
  p.rate0 = 1.0;
  p.room_temperature = 293.0;
  p.melt_temperature = melt_temperature;
  p.check();
  return p;
}

// Liao et al.'s Al 6061-T6 power law (Table 2), shared by Al6061-T6 and Al-Tillotson.
strength::PowerLaw al6061PowerLaw() {
  strength::PowerLawParameters p;
  p.sigma0 = 270e6;
  p.eps0 = 0.0025;
  p.rate0 = 1.0;
  p.n = 0.148;
  p.m = 0.01389;
  p.l = 1.0;
  p.room_temperature = 293.0;
  p.melt_temperature = 1200.0;
  return strength::PowerLaw(p);
}

ThermalParameters thermal(double specific_heat) {
  ThermalParameters t;
  t.specific_heat = specific_heat;
  t.taylor_quinney = 0.9;
  t.room_temperature = 293.0;
  t.check();
  return t;
}

// Al 6061-T6 JC damage set (commonly cited, no primary source found), with the melting point of
// the JC row it belongs to.
strength::JohnsonCookDamageParameters al6061Damage() {
  return johnsonCookDamage(-0.77, 1.45, -0.47, 0.0, 1.6, 925.0);
}

constexpr const char* al6061_damage_source =
    "JC damage D1 -0.77, D2 1.45, D3 -0.47, D4 0, D5 1.6, Tm 925 K (of the 6061-T6 JC row): commonly "
    "cited in the impact literature, no primary source";

// Eigenerosion's G_c (the default failure model, docs/materials.md). Liao et al. 2022 (Table 1) give
// 100 kJ/m^2 for Al 6061-T6 and 250 kJ/m^2 for OFHC copper; these are far above the plane-strain
// K_Ic^2/E of the alloys (~10-20 kJ/m^2): they include the plastic work of ductile tearing at the
// resolution of an OTM model. The other aluminium entries take Liao's 6061-T6 value as an
// engineering estimate (no published value for them was found).
constexpr double al6061_fracture_energy = 100e3;
constexpr double copper_fracture_energy = 250e3;
constexpr const char* al6061_fracture_source =
    "fracture energy G_c 100 kJ/m^2 (eigenerosion): Liao et al. 2022, Table 1 (Al 6061-T6)";
constexpr const char* al_estimated_fracture_source =
    "fracture energy G_c 100 kJ/m^2 (eigenerosion): engineering estimate, Liao et al. 2022's Al 6061-T6 value "
    "(Table 1) taken for this alloy, for which no published value was found";

// Spall strength of Al 6061-T6 (docs/materials.md): a constant tension, the middle of the range measured
// in plate impacts at strain rates of 10^5-10^6 /s; its rate and pulse-length dependence is left out.
constexpr double al6061_spall_strength = 1.4e9;
constexpr const char* al6061_spall_source =
    "spall strength 1.4 GPa: the middle of the 1.1-1.7 GPa measured for Al 6061-T6 in plate impacts at strain "
    "rates of 1e5-1e6 /s, as attributed to Kanel, Razorenov & Fortov, Shock-Wave Phenomena and the Properties of "
    "Condensed Matter (Springer, 2004); the primary table was not checked";

constexpr const char* damage_off =
    " The JC damage set is stored in `damage`, but a deck's `{ library: NAME }` leaves JC damage off (the default "
    "failure model is eigenerosion, docs/materials.md); `failure: { model: johnson-cook }` turns this set on.";

Entry al6061() {
  Entry e;
  e.name = "Al6061-T6";
  e.description = "Aluminium 6061-T6: Mie-Gruneisen EOS, J2 power-law viscoplasticity (Liao et al. 2022)";
  e.parameters.eos = mieGruneisen(2703.0, 5240.0, 1.40, 1.97);
  e.parameters.shear_modulus = 27.6e9;
  e.parameters.yield = al6061PowerLaw();
  e.parameters.damage = al6061Damage();
  e.parameters.thermal = thermal(896.0);
  e.parameters.fracture_energy = al6061_fracture_energy;
  e.parameters.spall_strength = al6061_spall_strength;
  e.sources = {
      al6061_fracture_source,
      al6061_spall_source,
      fmt::format("Mie-Gruneisen rho0 2703 kg/m^3, c0 5240 m/s, s 1.40, Gamma0 1.97: {}", steinberg),
      fmt::format("shear modulus G 27.6 GPa: {}", steinberg),
      fmt::format("power law sigma0 270 MPa, eps_p0 0.0025, rate0 1/s, n 0.148, m 0.01389, l 1.0, Tm 1200 K: {}", liao),
      "power-law reference temperature T0 293 K: room temperature (not given in the table)",
      "specific heat 896 J/(kg K): ASM Handbook Vol. 2 (1990), 6061-T6 (0.896 J/(g K)); Fan et al. 2019 use the "
      "same value for LY12",
      taylor_quinney,
      al6061_damage_source,
      viscosity,
  };
  e.notes =
      "Liao et al. give Tm = 1200 K although 6061 melts at about 855-925 K; the published 1200 K is kept, so "
      "thermal softening is weaker than the real alloy's. rho0 2703 is Steinberg's (Liao use 2700). The "
      "commonly cited 6061-T6 JC strength row (A 324 MPa, B 114 MPa, ...) is not used. The damage set's D1 < 0 "
      "makes the failure strain non-positive for triaxiality above about 1.35, where min_failure_strain "
      "(0 unless set) governs." +
      std::string(damage_off);
  return e;
}

Entry al2024() {
  Entry e;
  e.name = "Al2024-T351";
  e.description = "Aluminium 2024-T351: Mie-Gruneisen EOS, Johnson-Cook strength and damage";
  e.parameters.eos = mieGruneisen(2785.0, 5328.0, 1.338, 2.00);
  e.parameters.shear_modulus = 28.6e9;
  e.parameters.yield = johnsonCook(265e6, 426e6, 0.34, 0.015, 1.0, 775.0);
  e.parameters.damage = johnsonCookDamage(0.13, 0.13, -1.5, 0.011, 0.0, 775.0);
  e.parameters.thermal = thermal(875.0);
  e.parameters.fracture_energy = al6061_fracture_energy;
  e.sources = {
      al_estimated_fracture_source,
      fmt::format("Mie-Gruneisen rho0 2785 kg/m^3, c0 5328 m/s, s 1.338, Gamma0 2.00 (Al 2024): {}", steinberg),
      fmt::format("shear modulus G 28.6 GPa: {}", steinberg),
      fmt::format("JC strength A 265 MPa, B 426 MPa, n 0.34, C 0.015, m 1.0, Tm 775 K, rate0 1/s, T0 293 K: {}",
                  jc1983),
      fmt::format("JC damage D1 0.13, D2 0.13, D3 -1.5, D4 0.011, D5 0: {} (as commonly attributed)", jc1985),
      fmt::format("specific heat 875 J/(kg K): {}", jc1983),
      taylor_quinney,
      viscosity,
  };
  e.notes =
      "Tm 775 K is Johnson & Cook's value for 2024-T351 (near the alloy's solidus). The 1985 paper tested "
      "OFHC copper, Armco iron and 4340 steel; secondary sources attribute the 2024-T351 damage set to it, which "
      "is worth verifying against the primary source." +
      std::string(damage_off);
  return e;
}

Entry ly12() {
  const double youngs_modulus = 68.9e9;
  const double poisson_ratio = 0.33;
  Entry e;
  e.name = "LY12";
  e.description = "LY12 aluminium (~2A12/2024, Fan et al. 2019): power law with compression-dependent melting";
  e.parameters.eos = mieGruneisen(2700.0, 5328.0, 1.338, 2.00);
  e.parameters.shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  strength::PowerLawParameters p;
  p.sigma0 = 276e6;
  p.eps0 = 5e-4;
  p.rate0 = 1000.0;
  p.n = 0.075;
  p.m = 0.08;
  p.l = 0.5;
  p.room_temperature = 293.0;
  p.melt_temperature = 925.0;
  p.melt_a = 1.5;
  p.melt_gamma0 = 1.97;
  e.parameters.yield = strength::PowerLaw(p);
  e.parameters.thermal = thermal(896.0);
  e.parameters.fracture_energy = al6061_fracture_energy;
  e.sources = {
      al_estimated_fracture_source,
      fmt::format("density 2700 kg/m^3: {}", fan),
      fmt::format("shear modulus G = E/(2(1+nu)) = 25.90 GPa from E 68.9 GPa, nu 0.33: {}", fan),
      fmt::format("power law sigma0 276 MPa, eps_p0 5e-4, rate0 1000/s, n 0.075, m 0.08, q (l) 0.5: {}", fan),
      fmt::format("melting Tm(J) = Tm0 exp[2a(1-J)] J^(2(1/3+a-Gamma0)), Tm0 925 K, a 1.5, Gamma0 1.97: {}", fan),
      fmt::format("specific heat cp 896 J/(kg K): {}", fan),
      fmt::format("Mie-Gruneisen c0 5328 m/s, s 1.338, Gamma0 2.00 (Al 2024 Hugoniot, stand-in): {}", steinberg),
      "power-law reference temperature T0 293 K: room temperature (not given in the table)",
      taylor_quinney,
      viscosity,
  };
  e.notes =
      "Fan et al.'s EOS constants are not available here: the EOS is a stand-in, Steinberg's Al 2024 "
      "Hugoniot (c0, s, Gamma0) on Fan's density 2700 kg/m^3 (Steinberg's 2024 has 2785 kg/m^3, so the "
      "bulk modulus rho0 c0^2 is 3% below Steinberg's). Gamma0 is 2.00 in the EOS and Fan's 1.97 in Tm(J). "
      "No damage set is published for LY12.";
  return e;
}

// Copper shares its EOS, shear modulus, heat and damage between the JC and power-law entries.
Entry copperBase() {
  Entry e;
  e.parameters.eos = mieGruneisen(8930.0, 3940.0, 1.489, 2.02);
  e.parameters.shear_modulus = 47.7e9;
  e.parameters.damage = johnsonCookDamage(0.54, 4.89, -3.03, 0.014, 1.12, 1356.0);
  e.parameters.thermal = thermal(383.0);
  e.parameters.fracture_energy = copper_fracture_energy;
  e.sources = {
      "fracture energy G_c 250 kJ/m^2 (eigenerosion): Liao et al. 2022, Table 1 (OFHC copper)",
      fmt::format("Mie-Gruneisen rho0 8930 kg/m^3, c0 3940 m/s, s 1.489, Gamma0 2.02: {}", steinberg),
      fmt::format("shear modulus G 47.7 GPa: {}", steinberg),
  };
  return e;
}

Entry copper() {
  Entry e = copperBase();
  e.name = "OFHC-copper";
  e.description = "OFHC copper: Mie-Gruneisen EOS, Johnson-Cook strength and damage";
  e.parameters.yield = johnsonCook(90e6, 292e6, 0.31, 0.025, 1.09, 1356.0);
  e.sources.insert(
      e.sources.end(),
      {
          fmt::format("JC strength A 90 MPa, B 292 MPa, n 0.31, C 0.025, m 1.09, Tm 1356 K, rate0 1/s, T0 293 K: {}",
                      jc1983),
          fmt::format("JC damage D1 0.54, D2 4.89, D3 -3.03, D4 0.014, D5 1.12: {}", jc1985),
          fmt::format("specific heat 383 J/(kg K): {}", jc1983),
          taylor_quinney,
          viscosity,
      });
  e.notes =
      "Johnson-Cook is the default strength: Liao et al.'s power-law set (entry OFHC-copper-powerlaw) has "
      "m = 1 with rate0 = 1/s, which taken literally multiplies the yield stress by ~1e6 at impact strain "
      "rates (docs/strength.md)." +
      std::string(damage_off);
  return e;
}

Entry copperPowerLaw() {
  Entry e = copperBase();
  e.name = "OFHC-copper-powerlaw";
  e.description = "OFHC copper with Liao et al.'s power law, rate factor capped at 2";
  strength::PowerLawParameters p;
  p.sigma0 = 120e6;
  p.eps0 = 0.0278;
  p.rate0 = 1.0;
  p.n = 0.45;
  p.m = 1.0;
  p.l = 1.0;
  p.room_temperature = 293.0;
  p.melt_temperature = 1790.0;
  p.rate_factor_cap = 2.0;
  e.parameters.yield = strength::PowerLaw(p);
  e.sources.insert(
      e.sources.end(),
      {
          fmt::format("power law sigma0 120 MPa, eps_p0 0.0278, rate0 1/s, n 0.45, m 1.0, l 1.0, Tm 1790 K: {}", liao),
          "rate_factor_cap 2: Kessler's choice, not published (see notes)",
          "power-law reference temperature T0 293 K: room temperature (not given in the table)",
          fmt::format("JC damage D1 0.54, D2 4.89, D3 -3.03, D4 0.014, D5 1.12, Tm 1356 K: {}", jc1985),
          fmt::format("specific heat 383 J/(kg K): {}", jc1983),
          taylor_quinney,
          viscosity,
      });
  e.notes =
      "The published set (m = 1, rate0 = 1/s) multiplies the yield stress by 1 + rate/(1/s), ~1e6 at impact "
      "strain rates; the rate factor [1 + (rate/rate0)^m] is capped at 2 here so that the entry behaves. The "
      "uncapped set is the one in the paper: override with `strength: { rate_factor_cap: 0 }`. Liao's "
      "Tm 1790 K is kept although copper melts at 1356 K." +
      std::string(damage_off);
  return e;
}

Entry steel4340() {
  Entry e;
  e.name = "4340-steel";
  e.description = "4340 steel: approximate steel Mie-Gruneisen EOS, Johnson-Cook strength and damage";
  e.parameters.eos = mieGruneisen(7850.0, 4570.0, 1.49, 2.17);
  e.parameters.shear_modulus = 80e9;
  e.parameters.yield = johnsonCook(792e6, 510e6, 0.26, 0.014, 1.03, 1793.0);
  e.parameters.damage = johnsonCookDamage(0.05, 3.44, -2.12, 0.002, 0.61, 1793.0);
  e.parameters.thermal = thermal(477.0);
  e.sources = {
      fmt::format("Mie-Gruneisen rho0 7850 kg/m^3, c0 4570 m/s, s 1.49, Gamma0 2.17: generic steel after {} "
                  "(approximate, not checked against a primary source)",
                  steinberg),
      "shear modulus G 80 GPa: generic steel (approximate)",
      fmt::format("JC strength A 792 MPa, B 510 MPa, n 0.26, C 0.014, m 1.03, Tm 1793 K, rate0 1/s, T0 293 K: {}",
                  jc1983),
      fmt::format("JC damage D1 0.05, D2 3.44, D3 -2.12, D4 0.002, D5 0.61: {}", jc1985),
      fmt::format("specific heat 477 J/(kg K): {}", jc1983),
      taylor_quinney,
      viscosity,
  };
  e.notes =
      "The EOS and shear modulus are approximate values for a generic steel, not a 4340 measurement. The "
      "damage set of Zhao & Song 2010 (Explosion and Shock Waves) is garbled as printed (D1 0.47e-5, D2 -9.0, "
      "...), so Johnson & Cook's 4340 set is used. No fracture energy: none was found published "
      "for steel, so eigenerosion is off unless the deck sets `fracture_energy` (K_Ic^2/E of 4340 is of order "
      "10-50 kJ/m^2 depending on the temper)." +
      std::string(damage_off);
  return e;
}

Entry alTillotson() {
  Entry e;
  e.name = "Al-Tillotson";
  e.description = "Aluminium with the Tillotson EOS (vaporisation) and the 6061-T6 power law";
  eos::TillotsonParameters t;
  t.density = 2700.0;
  t.a = 0.5;
  t.b = 1.63;
  t.A = 75.2e9;
  t.B = 65e9;
  t.E0 = 5.0e6;
  t.alpha = 5.0;
  t.beta = 5.0;
  t.E_iv = 3.0e6;
  t.E_cv = 13.9e6;
  e.parameters.eos = eos::Tillotson(t);
  e.parameters.shear_modulus = 27.6e9;
  e.parameters.yield = al6061PowerLaw();
  e.parameters.damage = al6061Damage();
  e.parameters.thermal = thermal(896.0);
  e.parameters.fracture_energy = al6061_fracture_energy;
  e.parameters.spall_strength = al6061_spall_strength;
  e.sources = {
      al6061_fracture_source,
      al6061_spall_source,
      "Tillotson rho0 2700 kg/m^3, a 0.5, b 1.63, A 75.2 GPa, B 65 GPa, E0 5.0 MJ/kg, alpha 5, beta 5, E_iv 3.0 "
      "MJ/kg, E_cv 13.9 MJ/kg: iSALE aluminium set (after Tillotson 1962; Melosh 1989, Impact Cratering, App. II)",
      fmt::format("shear modulus G 27.6 GPa (Al 6061-T6): {}", steinberg),
      fmt::format("power law as Al6061-T6 (sigma0 270 MPa, eps_p0 0.0025, n 0.148, m 0.01389, l 1.0, Tm 1200 K): {}",
                  liao),
      "specific heat 896 J/(kg K): ASM Handbook Vol. 2 (1990), 6061-T6",
      taylor_quinney,
      al6061_damage_source,
      viscosity,
  };
  e.notes =
      "Strength, heat and damage are Al6061-T6's (see that entry's notes, Tm 1200 K in particular) on the "
      "Tillotson EOS, for impacts fast enough to vaporise aluminium." +
      std::string(damage_off);
  return e;
}

// The gas of Noh's implosion: a strengthless test material for shock capturing, not a real gas
// at a real state (its density 1 kg/m^3 and e = 0, so p = 0, are the problem's dimensionless
// initial data in SI units).
Entry idealGas() {
  Entry e;
  e.name = "ideal-gas-5/3";
  e.description = "Monatomic ideal gas, gamma = 5/3, no strength: the gas of the Noh problem (Noh 1987)";
  e.parameters.eos = eos::IdealGas({.density = 1.0, .gamma = 5.0 / 3.0});
  e.parameters.shear_modulus = 0.0;
  e.parameters.yield = strength::NoStrength{};
  e.parameters.thermal = thermal(3116.0);
  e.sources = {
      "ideal gas p = (gamma - 1) rho e, gamma 5/3, rho0 1 kg/m^3: the gas of the Noh problem (Noh 1987, "
      "'Errors for calculations of strong shocks using an artificial viscosity and an artificial heat flux', "
      "J. Comput. Phys. 72:78-120)",
      "no strength (shear modulus 0), no fracture energy: a gas",
      "specific heat c_v 3116 J/(kg K): helium, 3/2 R/M with M 4.0026 g/mol; it only sets the temperature field, "
      "never the pressure",
      "Taylor-Quinney coefficient 0.9: unused (no strength, so no plastic work)",
      viscosity,
  };
  e.notes =
      "A test gas, not a material: at e = 0 its pressure and sound speed are exactly 0 (Noh's cold gas), so only "
      "compression, through the artificial viscosity, gives it a signal speed, while the integrator wants a "
      "positive sound speed at every point (docs/materials.md). Temperatures start at the room temperature 293 K "
      "(thermal.room_temperature must be positive) rather than at e/c_v = 0 K, so they are an offset scale: the "
      "pressure follows e alone.";
  return e;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

}  // namespace

const std::vector<Entry>& entries() {
  static const std::vector<Entry> all = {al6061(),         al2024(),    ly12(),        copper(),
                                         copperPowerLaw(), steel4340(), alTillotson(), idealGas()};
  return all;
}

const Entry& find(const std::string& name) {
  const std::string wanted = lower(name);
  for (const Entry& entry : entries())
    if (lower(entry.name) == wanted) return entry;
  std::vector<std::string> names;
  for (const Entry& entry : entries()) names.push_back(entry.name);
  throw InputError(fmt::format("unknown library material '{}' (known: {})", name, fmt::join(names, ", ")));
}

}  // namespace kessler::library
