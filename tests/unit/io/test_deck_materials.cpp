// Impact materials in the deck: library entries, key-by-key overrides, explicit blocks and their errors.
#include "core/error.hpp"
#include "io/deck.hpp"
#include "material/library.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

const fs::path deck_dir = fs::path(KESSLER_TEST_DATA) / "decks";

// A deck around the material `al` given as the YAML text of the `materials` map. Named as if it lay in
// tests/data/decks, so that tabular files resolve there.
std::string deckWith(const std::string& materials) {
  return "materials:\n" + materials + R"(
bodies:
  - { name: ball, material: al, shape: { sphere: { center: [0, 0, 0], radius: 5 mm } }, mesh_size: 1 mm }
solver: { end_time: 10 us }
)";
}

const std::string deck_name = (deck_dir / "deck.yaml").string();

MaterialConfig material(const std::string& materials) {
  return parseDeckString(deckWith(materials), deck_name).materials.at(0);
}

std::string errorOf(const std::string& materials) {
  try {
    parseDeckString(deckWith(materials), deck_name);
  } catch (const InputError& e) {
    std::string message = e.what();
    // Drop "<deck>:<line>:<column>: ", checked by the corpus tests.
    const std::size_t key = message.find(": materials");
    return key == std::string::npos ? message : message.substr(key + 2);
  }
  return "no error";
}

template <typename Model>
const auto& eosOf(const MaterialConfig& m) {
  return std::get<Model>(m.impact.eos).parameters();
}

template <typename Law>
const auto& yieldOf(const MaterialConfig& m) {
  return std::get<Law>(m.impact.yield).parameters();
}

TEST(DeckMaterials, ALibraryEntryGivesItsParametersWithoutJohnsonCookDamage) {
  const MaterialConfig m = material("  al: { library: Al6061-T6 }");
  const library::Entry& entry = library::find("Al6061-T6");
  EXPECT_EQ(m.model, "impact");
  EXPECT_EQ(m.library, "Al6061-T6");
  EXPECT_EQ(eosOf<eos::MieGruneisen>(m).density, 2703.0);
  EXPECT_EQ(eosOf<eos::MieGruneisen>(m).slope, 1.40);
  EXPECT_EQ(m.impact.shear_modulus, entry.parameters.shear_modulus);
  EXPECT_EQ(yieldOf<strength::PowerLaw>(m).sigma0, 270e6);
  EXPECT_EQ(m.impact.thermal.specific_heat, entry.parameters.thermal.specific_heat);
  EXPECT_EQ(m.impact.viscosity.quadratic, entry.parameters.viscosity.quadratic);
  EXPECT_EQ(m.impact.pressure_floor, -std::numeric_limits<double>::infinity());
  // The default failure model is eigenerosion (docs/deck.md): JC damage only when asked for.
  EXPECT_FALSE(m.impact.damage.has_value());
}

TEST(DeckMaterials, LibraryNamesIgnoreCase) {
  EXPECT_EQ(material("  al: { library: ofhc-COPPER }").library, "OFHC-copper");
}

TEST(DeckMaterials, OverridesALibraryEntryKeyByKey) {
  const MaterialConfig m = material(R"(  al:
    library: OFHC-copper
    density: 8.9 g/cm^3
    shear_modulus: 45 GPa
    eos: { slope: 1.5 }
    strength: { A: 100 MPa }
    failure: { model: johnson-cook, min_failure_strain: 0.01 }
    thermal: { taylor_quinney: 0.8 }
    viscosity: { linear: 0.1 }
    tension_cutoff: -1.2 GPa)");
  const auto& mg = eosOf<eos::MieGruneisen>(m);
  EXPECT_DOUBLE_EQ(mg.density, 8900.0);
  EXPECT_EQ(mg.sound_speed, 3940.0);  // kept from the library
  EXPECT_EQ(mg.slope, 1.5);
  EXPECT_EQ(m.impact.shear_modulus, 45e9);
  const auto& jc = yieldOf<strength::JohnsonCook>(m);
  EXPECT_EQ(jc.A, 100e6);
  EXPECT_EQ(jc.B, 292e6);
  EXPECT_EQ(jc.melt_temperature, 1356.0);
  ASSERT_TRUE(m.impact.damage.has_value());
  EXPECT_EQ(m.impact.damage->D2, 4.89);  // the library's published set
  EXPECT_EQ(m.impact.damage->min_failure_strain, 0.01);
  EXPECT_EQ(m.impact.thermal.taylor_quinney, 0.8);
  EXPECT_EQ(m.impact.thermal.specific_heat, 383.0);
  EXPECT_EQ(m.impact.viscosity.linear, 0.1);
  EXPECT_EQ(m.impact.viscosity.quadratic, 1.5);
  EXPECT_DOUBLE_EQ(m.impact.pressure_floor, -1.2e9);
}

TEST(DeckMaterials, ADifferentModelReplacesTheWholeBlock) {
  const MaterialConfig m = material(R"(  al:
    library: OFHC-copper
    eos: { model: polynomial, k1: 140 GPa, gamma0: 2 }
    strength: { model: linear, sigma0: 400 MPa, H: 100 MPa })");
  const auto& polynomial = eosOf<eos::Polynomial>(m);
  EXPECT_EQ(polynomial.density, 8930.0);  // the density stays the library entry's
  EXPECT_EQ(polynomial.k1, 140e9);
  EXPECT_EQ(polynomial.k2, 0.0);
  EXPECT_EQ(yieldOf<strength::LinearHardening>(m).H, 100e6);
  EXPECT_EQ(errorOf("  al: { library: OFHC-copper, eos: { model: tillotson, a: 0.5 } }"),
            "materials.al.eos: missing required key 'b'");
}

TEST(DeckMaterials, ReadsExplicitBlocksInSIUnits) {
  const MaterialConfig m = material(R"(  al:
    density: 2.7 g/cm^3
    shear_modulus: 26 GPa
    eos: { model: tillotson, a: 0.5, b: 1.63, A: 75.2 GPa, B: 65 GPa, E0: 5 MJ/kg, alpha: 5, beta: 5,
           E_iv: 3 MJ/kg, E_cv: 13.9 MJ/kg }
    strength: { model: power-law, sigma0: 276 MPa, eps0: 5e-4, rate0: 1000 1/s, n: 0.075, m: 0.08, l: 0.5,
                melt_temperature: 925 K, melt_a: 1.5, melt_gamma0: 1.97 }
    failure: { model: johnson-cook, D1: 0.13, D2: 0.13, D3: -1.5, D4: 0.011, D5: 0 }
    thermal: { specific_heat: 896 J/(kg*K), room_temperature: 300 K })");
  EXPECT_EQ(m.library, "");
  const auto& tillotson = eosOf<eos::Tillotson>(m);
  EXPECT_DOUBLE_EQ(tillotson.density, 2700.0);
  EXPECT_DOUBLE_EQ(tillotson.E0, 5e6);
  EXPECT_DOUBLE_EQ(tillotson.E_cv, 13.9e6);
  const auto& power_law = yieldOf<strength::PowerLaw>(m);
  EXPECT_DOUBLE_EQ(power_law.rate0, 1000.0);
  EXPECT_EQ(power_law.room_temperature, 293.0);  // the strength's own reference temperature
  EXPECT_EQ(power_law.rate_factor_cap, 0.0);
  ASSERT_TRUE(m.impact.damage.has_value());
  EXPECT_EQ(m.impact.damage->melt_temperature, 925.0);  // from the strength model
  EXPECT_EQ(m.impact.thermal.room_temperature, 300.0);
  EXPECT_EQ(m.impact.viscosity.linear, ViscosityParameters{}.linear);
}

TEST(DeckMaterials, AMaterialWithoutStrengthNeedsNoShearModulus) {
  const MaterialConfig m = material(R"(  al:
    density: 1000
    eos: { model: polynomial, k1: 2.2 GPa, gamma0: 0.1 }
    strength: { model: none }
    thermal: { specific_heat: 4180 J/(kg*K) })");
  EXPECT_EQ(m.impact.shear_modulus, 0.0);
  EXPECT_TRUE(std::holds_alternative<strength::NoStrength>(m.impact.yield));
}

TEST(DeckMaterials, ReadsAnIdealGas) {
  const MaterialConfig air = material(R"(  al:
    density: 1.2 kg/m^3
    eos: { model: ideal-gas, gamma: 1.4 }
    strength: { model: none }
    thermal: { specific_heat: 718 J/(kg*K) })");
  EXPECT_EQ(eosOf<eos::IdealGas>(air).density, 1.2);
  EXPECT_EQ(eosOf<eos::IdealGas>(air).gamma, 1.4);
  EXPECT_EQ(air.impact.shear_modulus, 0.0);
  EXPECT_TRUE(std::holds_alternative<strength::NoStrength>(air.impact.yield));

  const MaterialConfig noh = material("  al: { library: Ideal-Gas-5/3 }");
  EXPECT_EQ(noh.library, "ideal-gas-5/3");
  EXPECT_EQ(eosOf<eos::IdealGas>(noh).density, 1.0);
  EXPECT_EQ(eosOf<eos::IdealGas>(noh).gamma, 5.0 / 3.0);
  EXPECT_EQ(noh.impact.fracture_energy, 0.0);
  const MaterialConfig hot = material("  al: { library: ideal-gas-5/3, density: 2 kg/m^3, eos: { gamma: 1.4 } }");
  EXPECT_EQ(eosOf<eos::IdealGas>(hot).density, 2.0);
  EXPECT_EQ(eosOf<eos::IdealGas>(hot).gamma, 1.4);
}

TEST(DeckMaterials, ReportsABadIdealGasAtItsKey) {
  EXPECT_EQ(errorOf("  al: { library: ideal-gas-5/3, eos: { gamma: 1 } }"),
            "materials.al.eos: eos.gamma must be greater than 1 (got 1)");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, eos: { model: ideal-gas } }"),
            "materials.al.eos: missing required key 'gamma'");
  EXPECT_EQ(errorOf("  al: { library: ideal-gas-5/3, eos: { gamma: 1.4, k1: 1 GPa } }"),
            "materials.al.eos.k1: unknown key (allowed: model, gamma)");
  EXPECT_EQ(errorOf("  al: { library: ideal-gas-5/3, eos: { gamma: 1.4 GPa } }"),
            "materials.al.eos.gamma: '1.4 GPa' has units of kg/m*s^2, expected 1 (dimensionless)");
  EXPECT_EQ(errorOf("  al: { library: ideal-gas-5/3, density: 0 }").rfind("materials.al.density: ", 0), 0u);
  EXPECT_EQ(errorOf("  al: { library: ideal-gas-5/3, eos: { model: gas } }"),
            "materials.al.eos.model: unknown eos model (known: mie-gruneisen, polynomial, tillotson, tabular, "
            "ideal-gas) (got 'gas')");
}

TEST(DeckMaterials, ReadsATabularEosNextToTheDeck) {
  const RunConfig c = parseDeck(deck_dir / "good_tabular.yaml");
  const auto& table = std::get<eos::Tabular>(c.materials.at(0).impact.eos);
  EXPECT_EQ(table.referenceDensity(), 2703.0);
  EXPECT_EQ(table.table().material_id, 3719);
  // The density may be left out: the table gives it.
  const MaterialConfig m = material(R"(  al:
    eos: { model: tabular, file: al_mie_gruneisen.ses }
    strength: { model: none }
    thermal: { specific_heat: 896 J/(kg*K) })");
  EXPECT_EQ(eos::referenceDensity(m.impact.eos), 2703.0);
}

TEST(DeckMaterials, ChoosesTheModelFromTheKeys) {
  EXPECT_EQ(material("  al: { density: 2700, youngs_modulus: 70 GPa, poisson_ratio: 0.3 }").model, "neo-hookean");
  EXPECT_EQ(errorOf("  al: { density: 2700, shear_modulus: 26 GPa }"), "materials.al: missing required key 'eos'");
  EXPECT_EQ(errorOf("  al: { model: neo-hookean, library: Al6061-T6 }"),
            "materials.al.library: unknown key (allowed: model, density, youngs_modulus, poisson_ratio, "
            "fracture_energy)");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, youngs_modulus: 70 GPa }"),
            "materials.al.youngs_modulus: unknown key (allowed: model, density, library, shear_modulus, eos, "
            "strength, failure, thermal, tension_cutoff, spall_strength, viscosity, fracture_energy, "
            "fracture_min_triaxiality)");
}

TEST(DeckMaterials, FractureEnergyHasUnitsAndDefaultsToTheLibrary) {
  EXPECT_EQ(material("  al: { library: Al6061-T6, fracture_energy: 20 kJ/m^2 }").impact.fracture_energy, 20e3);
  EXPECT_EQ(material("  al: { library: Al6061-T6 }").impact.fracture_energy,
            library::find("Al6061-T6").parameters.fracture_energy);
  EXPECT_EQ(material("  al: { density: 2700, youngs_modulus: 70 GPa, poisson_ratio: 0.3, fracture_energy: 1 kJ/m^2 }")
                .neo_hookean.fracture_energy,
            1e3);
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, fracture_energy: -1 }"),
            "materials.al.fracture_energy: must not be negative (0 switches eigenerosion off) (got '-1')");
  EXPECT_TRUE(
      errorOf("  al: { library: Al6061-T6, fracture_energy: 100 kJ }").starts_with("materials.al.fracture_energy: "));
}

TEST(DeckMaterials, FractureTriaxialityIsANumberOrNone) {
  EXPECT_EQ(material("  al: { library: Al6061-T6, fracture_min_triaxiality: -0.25 }").impact.fracture_min_triaxiality,
            -0.25);
  EXPECT_EQ(material("  al: { library: Al6061-T6, fracture_min_triaxiality: none }").impact.fracture_min_triaxiality,
            -std::numeric_limits<double>::infinity());
  EXPECT_EQ(material("  al: { library: Al6061-T6 }").impact.fracture_min_triaxiality,
            -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(errorOf("  al: { library: Al6061-T6, fracture_min_triaxiality: low }")
                  .starts_with("materials.al.fracture_min_triaxiality: "));
}

TEST(DeckMaterials, TensionCutoffNoneRemovesTheFloor) {
  EXPECT_EQ(material("  al: { library: Al6061-T6, tension_cutoff: none }").impact.pressure_floor,
            -std::numeric_limits<double>::infinity());
  EXPECT_EQ(material("  al: { library: Al6061-T6, tension_cutoff: 0 }").impact.pressure_floor, 0.0);
}

TEST(DeckMaterials, SpallStrengthFromTheLibraryOrTheDeck) {
  EXPECT_EQ(material("  al: { library: Al6061-T6 }").impact.spall_strength, 1.4e9);
  EXPECT_EQ(material("  al: { library: Al6061-T6, spall_strength: 2 GPa }").impact.spall_strength, 2e9);
  EXPECT_EQ(material("  al: { library: Al6061-T6, spall_strength: none }").impact.spall_strength, 0.0);
  EXPECT_TRUE(
      errorOf("  al: { library: Al6061-T6, spall_strength: -1 GPa }").starts_with("materials.al.spall_strength: "));
}

TEST(DeckMaterials, CommandLineSettingsOverrideLibraryKeys) {
  const RunConfig c =
      parseDeckString(deckWith("  al: { library: OFHC-copper }"), deck_name,
                      {"materials.al.strength.A=120 MPa", "materials.al.failure={model: johnson-cook}"});
  EXPECT_EQ(std::get<strength::JohnsonCook>(c.materials[0].impact.yield).parameters().A, 120e6);
  EXPECT_TRUE(c.materials[0].impact.damage.has_value());
}

TEST(DeckMaterials, ReportsEachProblemAtItsKey) {
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, strength: { n: 0.2 GPa } }"),
            "materials.al.strength.n: '0.2 GPa' has units of kg/m*s^2, expected 1 (dimensionless)");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, eos: mie-gruneisen }"),
            "materials.al.eos: must be a map such as { key: value } (got 'mie-gruneisen')");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, failure: { D1: 0.1 } }"),
            "materials.al.failure: missing required key 'model'");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, failure: { model: none, D1: 0.1 } }"),
            "materials.al.failure.D1: unknown key (allowed: model)");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, thermal: { model: x } }"),
            "materials.al.thermal.model: unknown key (allowed: specific_heat, taylor_quinney, room_temperature)");
  EXPECT_EQ(errorOf("  al: { library: [Al6061-T6] }"),
            "materials.al.library: must be a library material such as Al6061-T6, not a list (got '[Al6061-T6]')");
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, density: 2.8 g/cm^3, eos: { model: tabular, file: "
                    "al_mie_gruneisen.ses } }"),
            "materials.al.density: contradicts the reference density 2703 kg/m^3 of the tabular EOS in '" +
                (deck_dir / "al_mie_gruneisen.ses").lexically_normal().string() +
                "': leave density out or make the two agree (got '2.8 g/cm^3')");
  // The structs' own checks, reported at the block.
  EXPECT_EQ(errorOf("  al: { library: Al6061-T6, thermal: { specific_heat: -1 } }").rfind("materials.al.thermal: ", 0),
            0u);
  EXPECT_EQ(errorOf("  al: { library: 4340-steel, failure: { model: johnson-cook, rate0: 0 } }")
                .rfind("materials.al.failure: failure.rate0 must be positive", 0),
            0u);
}

}  // namespace
}  // namespace kessler::io
