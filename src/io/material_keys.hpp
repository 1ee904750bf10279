#pragma once
// The deck keys of the impact-material parameter blocks (eos, strength, failure, thermal, viscosity):
// one table per parameter struct, read by the deck parser and written by the resolved-deck writer,
// so that the two cannot drift apart. Keys are the struct's field names.
#include "core/units.hpp"
#include "material/impact_material.hpp"

#include <iterator>

namespace kessler::io::material_keys {

template <typename Parameters>
struct Key {
  const char* name;
  units::Dimension dimension;
  double Parameters::*member;
  bool required;     // must be given unless the block extends a library entry's block of the same model
  const char* unit;  // SI unit, for the comments of the resolved deck ("" when dimensionless)
};

namespace u = units;
using eos::IdealGasParameters, eos::MieGruneisenParameters, eos::PolynomialParameters, eos::TillotsonParameters;
using strength::JohnsonCookDamageParameters, strength::JohnsonCookParameters, strength::LinearHardeningParameters,
    strength::PowerLawParameters;

// The reference density is the material's `density`, not a key of the eos block.
inline constexpr Key<MieGruneisenParameters> mie_gruneisen[] = {
    {"sound_speed", u::velocity, &MieGruneisenParameters::sound_speed, true, "m/s"},
    {"slope", u::dimensionless, &MieGruneisenParameters::slope, true, ""},
    {"gamma0", u::dimensionless, &MieGruneisenParameters::gamma0, true, ""},
};

inline constexpr Key<PolynomialParameters> polynomial[] = {
    {"k1", u::pressure, &PolynomialParameters::k1, true, "Pa"},
    {"k2", u::pressure, &PolynomialParameters::k2, false, "Pa"},
    {"k3", u::pressure, &PolynomialParameters::k3, false, "Pa"},
    {"gamma0", u::dimensionless, &PolynomialParameters::gamma0, true, ""},
};

inline constexpr Key<TillotsonParameters> tillotson[] = {
    {"a", u::dimensionless, &TillotsonParameters::a, true, ""},
    {"b", u::dimensionless, &TillotsonParameters::b, true, ""},
    {"A", u::pressure, &TillotsonParameters::A, true, "Pa"},
    {"B", u::pressure, &TillotsonParameters::B, true, "Pa"},
    {"E0", u::specific_energy, &TillotsonParameters::E0, true, "J/kg"},
    {"alpha", u::dimensionless, &TillotsonParameters::alpha, true, ""},
    {"beta", u::dimensionless, &TillotsonParameters::beta, true, ""},
    {"E_iv", u::specific_energy, &TillotsonParameters::E_iv, true, "J/kg"},
    {"E_cv", u::specific_energy, &TillotsonParameters::E_cv, true, "J/kg"},
};

inline constexpr Key<IdealGasParameters> ideal_gas[] = {
    {"gamma", u::dimensionless, &IdealGasParameters::gamma, true, "ratio of specific heats c_p/c_v"},
};

inline constexpr Key<PowerLawParameters> power_law[] = {
    {"sigma0", u::pressure, &PowerLawParameters::sigma0, true, "Pa"},
    {"eps0", u::dimensionless, &PowerLawParameters::eps0, true, ""},
    {"rate0", u::rate, &PowerLawParameters::rate0, false, "1/s"},
    {"n", u::dimensionless, &PowerLawParameters::n, true, ""},
    {"m", u::dimensionless, &PowerLawParameters::m, true, ""},
    {"l", u::dimensionless, &PowerLawParameters::l, false, ""},
    {"room_temperature", u::temperature, &PowerLawParameters::room_temperature, false, "K"},
    {"melt_temperature", u::temperature, &PowerLawParameters::melt_temperature, true, "K"},
    {"melt_a", u::dimensionless, &PowerLawParameters::melt_a, false, "0: constant Tm"},
    {"melt_gamma0", u::dimensionless, &PowerLawParameters::melt_gamma0, false, ""},
    {"rate_factor_cap", u::dimensionless, &PowerLawParameters::rate_factor_cap, false, "0: no cap"},
};

inline constexpr Key<JohnsonCookParameters> johnson_cook[] = {
    {"A", u::pressure, &JohnsonCookParameters::A, true, "Pa"},
    {"B", u::pressure, &JohnsonCookParameters::B, true, "Pa"},
    {"n", u::dimensionless, &JohnsonCookParameters::n, true, ""},
    {"C", u::dimensionless, &JohnsonCookParameters::C, true, ""},
    {"m", u::dimensionless, &JohnsonCookParameters::m, true, ""},
    {"rate0", u::rate, &JohnsonCookParameters::rate0, false, "1/s"},
    {"room_temperature", u::temperature, &JohnsonCookParameters::room_temperature, false, "K"},
    {"melt_temperature", u::temperature, &JohnsonCookParameters::melt_temperature, true, "K"},
};

inline constexpr Key<LinearHardeningParameters> linear_hardening[] = {
    {"sigma0", u::pressure, &LinearHardeningParameters::sigma0, true, "Pa"},
    {"H", u::pressure, &LinearHardeningParameters::H, true, "Pa"},
    {"melt_temperature", u::temperature, &LinearHardeningParameters::melt_temperature, false, "K"},
};

// melt_temperature defaults to the strength model's melting point (see deck_materials.cpp).
inline constexpr Key<JohnsonCookDamageParameters> johnson_cook_damage[] = {
    {"D1", u::dimensionless, &JohnsonCookDamageParameters::D1, true, ""},
    {"D2", u::dimensionless, &JohnsonCookDamageParameters::D2, true, ""},
    {"D3", u::dimensionless, &JohnsonCookDamageParameters::D3, true, ""},
    {"D4", u::dimensionless, &JohnsonCookDamageParameters::D4, true, ""},
    {"D5", u::dimensionless, &JohnsonCookDamageParameters::D5, true, ""},
    {"rate0", u::rate, &JohnsonCookDamageParameters::rate0, false, "1/s"},
    {"room_temperature", u::temperature, &JohnsonCookDamageParameters::room_temperature, false, "K"},
    {"melt_temperature", u::temperature, &JohnsonCookDamageParameters::melt_temperature, false, "K"},
    {"min_failure_strain", u::dimensionless, &JohnsonCookDamageParameters::min_failure_strain, false, ""},
};

inline constexpr Key<ThermalParameters> thermal[] = {
    {"specific_heat", u::specific_heat, &ThermalParameters::specific_heat, true, "J/(kg*K)"},
    {"taylor_quinney", u::dimensionless, &ThermalParameters::taylor_quinney, false, ""},
    {"room_temperature", u::temperature, &ThermalParameters::room_temperature, false, "K"},
};

inline constexpr Key<ViscosityParameters> viscosity[] = {
    {"linear", u::dimensionless, &ViscosityParameters::linear, false, ""},
    {"quadratic", u::dimensionless, &ViscosityParameters::quadratic, false, ""},
};

// Every field of every struct is a key (the EOS density being the material's `density`): a field
// added to a struct must be added here, or the deck could not set it nor the resolved deck write it.
static_assert(sizeof(MieGruneisenParameters) == (std::size(mie_gruneisen) + 1) * sizeof(double));
static_assert(sizeof(PolynomialParameters) == (std::size(polynomial) + 1) * sizeof(double));
static_assert(sizeof(TillotsonParameters) == (std::size(tillotson) + 1) * sizeof(double));
static_assert(sizeof(IdealGasParameters) == (std::size(ideal_gas) + 1) * sizeof(double));
static_assert(sizeof(PowerLawParameters) == std::size(power_law) * sizeof(double));
static_assert(sizeof(JohnsonCookParameters) == std::size(johnson_cook) * sizeof(double));
static_assert(sizeof(LinearHardeningParameters) == std::size(linear_hardening) * sizeof(double));
static_assert(sizeof(JohnsonCookDamageParameters) == std::size(johnson_cook_damage) * sizeof(double));
static_assert(sizeof(ThermalParameters) == std::size(thermal) * sizeof(double));
static_assert(sizeof(ViscosityParameters) == std::size(viscosity) * sizeof(double));

// Model names as written in decks, in the order of the eos::Eos and strength::Yield variants.
inline constexpr const char* eos_models[] = {"mie-gruneisen", "polynomial", "tillotson", "tabular", "ideal-gas"};
inline constexpr const char* strength_models[] = {"none", "linear", "power-law", "johnson-cook"};

}  // namespace kessler::io::material_keys
