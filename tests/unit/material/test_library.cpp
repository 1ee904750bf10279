// The material library: every entry is a complete, physical parameter set with its sources, and
// entries are found by name regardless of case.
#include "core/error.hpp"
#include "material/library.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace kessler::library {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

TEST(Library, HasTheEntriesInAFixedOrder) {
  std::vector<std::string> names;
  for (const Entry& entry : entries()) names.push_back(entry.name);
  EXPECT_EQ(names, (std::vector<std::string>{"Al6061-T6", "Al2024-T351", "LY12", "OFHC-copper", "OFHC-copper-powerlaw",
                                             "4340-steel", "Al-Tillotson", "ideal-gas-5/3"}));
}

TEST(Library, NamesAreUniqueIgnoringCase) {
  std::set<std::string> seen;
  for (const Entry& entry : entries()) EXPECT_TRUE(seen.insert(lower(entry.name)).second) << entry.name;
}

TEST(Library, EveryEntryIsCompletePhysicalAndSourced) {
  for (const Entry& entry : entries()) {
    SCOPED_TRACE(entry.name);
    EXPECT_FALSE(entry.description.empty());
    EXPECT_FALSE(entry.notes.empty());
    ASSERT_FALSE(entry.sources.empty());
    for (const std::string& source : entry.sources) EXPECT_FALSE(source.empty());
    const ImpactMaterialParameters& p = entry.parameters;
    std::visit(
        [](const auto& model) {
          if constexpr (std::is_same_v<std::decay_t<decltype(model)>, eos::Tabular>) {
            FAIL() << "the library ships no tabular EOS";
          } else {
            EXPECT_NO_THROW(model.parameters().check());
          }
        },
        p.eos);
    EXPECT_NO_THROW(p.thermal.check());
    EXPECT_NO_THROW(p.viscosity.check());
    EXPECT_EQ(p.pressure_floor, -std::numeric_limits<double>::infinity());
    if (std::holds_alternative<eos::IdealGas>(p.eos)) {
      // A gas: no strength, no damage, nothing to erode.
      EXPECT_TRUE(std::holds_alternative<strength::NoStrength>(p.yield));
      EXPECT_EQ(p.shear_modulus, 0.0);
      EXPECT_FALSE(p.damage.has_value());
      EXPECT_EQ(p.fracture_energy, 0.0);
      continue;
    }
    EXPECT_GT(eos::referenceDensity(p.eos), 1000.0);
    ASSERT_FALSE(std::holds_alternative<strength::NoStrength>(p.yield));
    std::visit(
        [](const auto& law) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(law)>, strength::NoStrength>) {
            EXPECT_NO_THROW(law.parameters().check());
          }
        },
        p.yield);
    EXPECT_GT(p.shear_modulus, 1e9);
    if (p.damage) {
      EXPECT_NO_THROW(p.damage->check());
    }
  }
}

TEST(Library, FindIgnoresCase) {
  EXPECT_EQ(find("al6061-t6").name, "Al6061-T6");
  EXPECT_EQ(find("OFHC-COPPER").name, "OFHC-copper");
  EXPECT_EQ(&find("LY12"), &entries()[2]);
}

TEST(Library, FindListsTheKnownNamesForAnUnknownOne) {
  try {
    find("Al7075-T6");
    FAIL() << "an unknown name was found";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'Al7075-T6'"), std::string::npos) << message;
    for (const Entry& entry : entries()) EXPECT_NE(message.find(entry.name), std::string::npos) << message;
  }
}

// A few constants against the published sources (Steinberg 1996, Liao et al. 2022, Johnson & Cook 1983 and
// 1985, Fan et al. 2019; docs/materials.md), one per parameter group, to catch a slip in transcription.
TEST(Library, CarriesThePublishedConstants) {
  const auto& al = std::get<eos::MieGruneisen>(find("Al6061-T6").parameters.eos).parameters();
  EXPECT_EQ(al.density, 2703.0);
  EXPECT_EQ(al.sound_speed, 5240.0);
  const auto& al_yield = std::get<strength::PowerLaw>(find("Al6061-T6").parameters.yield).parameters();
  EXPECT_EQ(al_yield.m, 0.01389);
  EXPECT_EQ(al_yield.melt_temperature, 1200.0);  // as published, though Al melts near 925 K

  const Entry& copper = find("OFHC-copper");
  EXPECT_EQ(std::get<strength::JohnsonCook>(copper.parameters.yield).parameters().A, 90e6);
  ASSERT_TRUE(copper.parameters.damage.has_value());
  EXPECT_EQ(copper.parameters.damage->D3, -3.03);
  EXPECT_EQ(copper.parameters.thermal.specific_heat, 383.0);

  const auto& capped = std::get<strength::PowerLaw>(find("OFHC-copper-powerlaw").parameters.yield).parameters();
  EXPECT_EQ(capped.m, 1.0);
  EXPECT_EQ(capped.rate_factor_cap, 2.0);

  const auto& ly12 = find("LY12").parameters;
  EXPECT_NEAR(ly12.shear_modulus, 68.9e9 / 2.66, 1.0);
  const auto& ly12_yield = std::get<strength::PowerLaw>(ly12.yield).parameters();
  EXPECT_EQ(ly12_yield.melt_a, 1.5);
  EXPECT_EQ(ly12_yield.melt_gamma0, 1.97);
  EXPECT_EQ(ly12_yield.rate0, 1000.0);

  const Entry& steel = find("4340-steel");
  EXPECT_EQ(steel.parameters.damage->D1, 0.05);
  EXPECT_EQ(std::get<strength::JohnsonCook>(steel.parameters.yield).parameters().melt_temperature, 1793.0);

  const auto& tillotson = std::get<eos::Tillotson>(find("Al-Tillotson").parameters.eos).parameters();
  EXPECT_EQ(tillotson.A, 75.2e9);
  EXPECT_EQ(tillotson.E_cv, 13.9e6);

  const Entry& gas = find("IDEAL-GAS-5/3");
  const auto& noh = std::get<eos::IdealGas>(gas.parameters.eos).parameters();
  EXPECT_EQ(noh.gamma, 5.0 / 3.0);
  EXPECT_EQ(noh.density, 1.0);
  EXPECT_EQ(gas.parameters.thermal.specific_heat, 3116.0);
  EXPECT_EQ(gas.parameters.viscosity.quadratic, ViscosityParameters{}.quadratic);

  EXPECT_EQ(find("Al2024-T351").parameters.damage->D4, 0.011);
  EXPECT_FALSE(find("LY12").parameters.damage.has_value());
}

}  // namespace
}  // namespace kessler::library
