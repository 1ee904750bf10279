// Impact materials in the resolved deck: written out in full, in SI units, without the library
// indirection, and parsed back to the same parameters bit for bit.
#include "io/deck.hpp"
#include "io/material_keys.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;
namespace keys = material_keys;

const fs::path deck_dir = fs::path(KESSLER_TEST_DATA) / "decks";

// material_keys.hpp checks that its tables cover every field, so comparing through them compares all.
template <typename P, std::size_t N>
void expectSameKeys(const P& a, const P& b, const keys::Key<P> (&table)[N]) {
  for (const keys::Key<P>& key : table) EXPECT_EQ(a.*(key.member), b.*(key.member)) << key.name;
}

template <typename Model, typename Variant, typename P, std::size_t N>
void expectSameModel(const Variant& a, const Variant& b, const keys::Key<P> (&table)[N]) {
  if (const auto* x = std::get_if<Model>(&a)) expectSameKeys(x->parameters(), std::get<Model>(b).parameters(), table);
}

void expectSameImpact(const ImpactMaterialParameters& a, const ImpactMaterialParameters& b) {
  ASSERT_EQ(a.eos.index(), b.eos.index());
  EXPECT_EQ(eos::referenceDensity(a.eos), eos::referenceDensity(b.eos));
  expectSameModel<eos::MieGruneisen>(a.eos, b.eos, keys::mie_gruneisen);
  expectSameModel<eos::Polynomial>(a.eos, b.eos, keys::polynomial);
  expectSameModel<eos::Tillotson>(a.eos, b.eos, keys::tillotson);
  expectSameModel<eos::IdealGas>(a.eos, b.eos, keys::ideal_gas);
  EXPECT_EQ(a.shear_modulus, b.shear_modulus);
  ASSERT_EQ(a.yield.index(), b.yield.index());
  expectSameModel<strength::LinearHardening>(a.yield, b.yield, keys::linear_hardening);
  expectSameModel<strength::PowerLaw>(a.yield, b.yield, keys::power_law);
  expectSameModel<strength::JohnsonCook>(a.yield, b.yield, keys::johnson_cook);
  ASSERT_EQ(a.damage.has_value(), b.damage.has_value());
  if (a.damage) expectSameKeys(*a.damage, *b.damage, keys::johnson_cook_damage);
  expectSameKeys(a.thermal, b.thermal, keys::thermal);
  expectSameKeys(a.viscosity, b.viscosity, keys::viscosity);
  EXPECT_EQ(a.pressure_floor, b.pressure_floor);
}

TEST(ResolvedDeckMaterials, ParseBackToTheSameParameters) {
  const RunConfig original = parseDeck(deck_dir / "good_materials.yaml");
  const fs::path file = fs::temp_directory_path() / "kessler_resolved_good_materials.yaml";
  writeResolvedDeck(original, file);
  const RunConfig again = parseDeck(file);
  ASSERT_EQ(original.materials.size(), again.materials.size());
  for (std::size_t i = 0; i < original.materials.size(); ++i) {
    const MaterialConfig& a = original.materials[i];
    const MaterialConfig& b = again.materials[i];
    SCOPED_TRACE(a.name);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.model, b.model);
    if (a.model == "impact") {
      expectSameImpact(a.impact, b.impact);
      EXPECT_EQ(b.library, "");  // the resolved deck names no library entry: it gives every value
    } else {
      EXPECT_EQ(a.neo_hookean.density, b.neo_hookean.density);
    }
  }
  // The second writing differs from the first only by the comments naming the library entries.
  std::string first = resolvedDeckText(original);
  for (const MaterialConfig& m : original.materials) {
    if (m.library.empty()) continue;
    const std::string comment = fmt::format("  # library entry {}, every parameter written out", m.library);
    const std::size_t at = first.find(comment);
    ASSERT_NE(at, std::string::npos) << comment << "\n" << first;
    first.erase(at, comment.size());
  }
  EXPECT_EQ(resolvedDeckText(again), first);
  fs::remove(file);
}

TEST(ResolvedDeckMaterials, WriteEveryParameterInSIUnits) {
  const std::string text = resolvedDeckText(parseDeck(deck_dir / "good_materials.yaml"));
  for (const char* expected : {"model: impact",
                               "library entry OFHC-copper",
                               "density: 8930",
                               "shear_modulus: 47700000000",
                               "model: mie-gruneisen",
                               "sound_speed: 3940",
                               "model: johnson-cook",
                               "A: 100000000",
                               "melt_temperature: 1356",
                               "min_failure_strain: 0.01",
                               "tension_cutoff: -1200000000",
                               "fracture_min_triaxiality: -0.333",
                               "model: tillotson",
                               "E0: 5000000",
                               "model: ideal-gas",
                               "gamma: 1.4",
                               "library entry ideal-gas-5/3",
                               "gamma: 1.6666666666666667",
                               "density: 1.2",
                               "model: polynomial",
                               "k1: 149000000000",
                               "model: linear",
                               "H: 100000000",
                               "model: power-law",
                               "rate_factor_cap: 3",
                               "specific_heat: 383",
                               "taylor_quinney: 0.85",
                               "quadratic: 2",
                               "model: none",
                               "model: neo-hookean"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << text;
  EXPECT_EQ(text.find("library:"), std::string::npos) << text;
}

}  // namespace
}  // namespace kessler::io
