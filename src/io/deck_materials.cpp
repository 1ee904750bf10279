// The `materials` section of the deck (docs/deck.md): neo-Hookean solids, and impact materials built
// from a library entry and/or explicit eos, strength, failure, thermal and viscosity blocks.
#include "core/error.hpp"
#include "io/deck_parts.hpp"
#include "io/material_keys.hpp"
#include "material/library.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace kessler::io {

namespace {

namespace fs = std::filesystem;
namespace keys = material_keys;

static_assert(std::is_same_v<std::variant_alternative_t<0, eos::Eos>, eos::MieGruneisen> &&
                  std::is_same_v<std::variant_alternative_t<1, eos::Eos>, eos::Polynomial> &&
                  std::is_same_v<std::variant_alternative_t<2, eos::Eos>, eos::Tillotson> &&
                  std::is_same_v<std::variant_alternative_t<3, eos::Eos>, eos::Tabular> &&
                  std::is_same_v<std::variant_alternative_t<4, eos::Eos>, eos::IdealGas>,
              "material_keys::eos_models follows the order of eos::Eos");
static_assert(std::is_same_v<std::variant_alternative_t<0, strength::Yield>, strength::NoStrength> &&
                  std::is_same_v<std::variant_alternative_t<1, strength::Yield>, strength::LinearHardening> &&
                  std::is_same_v<std::variant_alternative_t<2, strength::Yield>, strength::PowerLaw> &&
                  std::is_same_v<std::variant_alternative_t<3, strength::Yield>, strength::JohnsonCook>,
              "material_keys::strength_models follows the order of strength::Yield");

constexpr std::string_view neo_hookean_keys[] = {"model", "density", "youngs_modulus", "poisson_ratio",
                                                 "fracture_energy"};
// Keys that only an impact material has: any of them makes a material without `model` an impact one.
constexpr std::string_view impact_only_keys[] = {"library",        "shear_modulus",  "eos",
                                                 "strength",       "failure",        "thermal",
                                                 "tension_cutoff", "spall_strength", "viscosity"};

// The parameter structs' check() knows what is physical but not where the value was written: report
// its complaint at the block it came from. `action` must not itself read the deck.
template <typename Action>
auto reportAt(const Field& field, Action&& action) {
  try {
    return action();
  } catch (const InputError& e) {
    field.failBare(e.what());
  }
}

// A map's entries before its keys are checked (which needs the model it names); a non-map fails.
MapField entriesOf(const Field& field) {
  return field.node().IsMap() ? field.namedMap() : field.map({});
}

template <typename P, std::size_t N>
std::vector<std::string_view> allowedKeys(const keys::Key<P> (&table)[N]) {
  std::vector<std::string_view> allowed{"model"};
  for (const keys::Key<P>& key : table) allowed.push_back(key.name);
  return allowed;
}

// Reads the keys of `table` that `map` has into `value`. Unless `complete` (value already holds a
// whole parameter set of this model, from the library), the required ones must be there.
template <typename P, std::size_t N>
P readKeys(const MapField& map, const keys::Key<P> (&table)[N], P value, bool complete) {
  for (const keys::Key<P>& key : table) {
    if (std::optional<Field> field = map.find(key.name))
      value.*(key.member) = field->quantity(key.dimension);
    else if (key.required && !complete)
      map.require(key.name);
  }
  return value;
}

// A model of parameter struct P read from `block` (key by key over `base` if given), adjusted
// (the EOS gets the material's density), then built, which checks it.
template <typename Model, typename P, std::size_t N, typename Adjust>
Model readModel(const Field& block, const keys::Key<P> (&table)[N], const Model* base, Adjust&& adjust) {
  MapField map = block.map(allowedKeys(table));
  P p = readKeys(map, table, base ? base->parameters() : P{}, base != nullptr);
  adjust(p);
  return reportAt(block, [&] { return Model(p); });
}

// The index of the model that `block` names in `known`, or the library's (`base_index`, -1 if none)
// when it names none.
std::size_t modelIndex(const MapField& block, std::span<const char* const> known, int base_index,
                       std::string_view what) {
  std::optional<Field> model = block.find("model");
  if (!model) {
    if (base_index < 0) block.require("model");
    return static_cast<std::size_t>(base_index);
  }
  const std::string name = model->text();
  auto found = std::find_if(known.begin(), known.end(), [&](const char* k) { return name == k; });
  if (found == known.end()) model->fail(fmt::format("unknown {} model (known: {})", what, fmt::join(known, ", ")));
  return static_cast<std::size_t>(found - known.begin());
}

eos::Tabular readTabular(const Field& block, const fs::path& base_dir, const std::optional<Field>& density) {
  MapField map = block.map({"model", "file", "material_id"});
  Field file = map.require("file");
  const fs::path resolved = fs::absolute(base_dir / file.text("a file path")).lexically_normal();
  std::error_code error;
  if (!fs::is_regular_file(resolved, error))
    file.fail(fmt::format("no such SESAME file (looked for '{}')", resolved.string()));
  if (!std::ifstream(resolved)) file.fail(fmt::format("cannot read the SESAME file '{}'", resolved.string()));
  eos::TabularParameters p;
  p.file = resolved.string();
  if (std::optional<Field> id = map.find("material_id"))
    p.material_id = static_cast<int>(id->integer(0, std::numeric_limits<int>::max()));
  eos::Tabular table = reportAt(file, [&] { return eos::Tabular(p); });
  const double rho0 = table.referenceDensity();
  if (density && std::abs(density->positive(units::density) - rho0) > 1e-6 * rho0)
    density->fail(
        fmt::format("contradicts the reference density {} kg/m^3 of the tabular EOS in '{}': leave "
                    "density out or make the two agree",
                    rho0, resolved.string()));
  return table;
}

// The library's EOS with the deck's density, if it gives one.
eos::Eos libraryEos(const eos::Eos& base, const std::optional<Field>& density) {
  if (!density) return base;
  const double rho0 = density->positive(units::density);
  return std::visit(
      [&](const auto& model) -> eos::Eos {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (std::is_same_v<Model, eos::Tabular>) {
          if (std::abs(rho0 - model.referenceDensity()) > 1e-6 * model.referenceDensity())
            density->fail(fmt::format("contradicts the reference density {} kg/m^3 of the library's tabular EOS",
                                      model.referenceDensity()));
          return model;
        } else {
          auto p = model.parameters();
          p.density = rho0;
          return reportAt(*density, [&] { return Model(p); });
        }
      },
      base);
}

eos::Eos parseEos(const MapField& material, const ImpactMaterialParameters* base, const fs::path& base_dir) {
  const std::optional<Field> density_field = material.find("density");
  std::optional<Field> block = material.find("eos");
  if (!block) {
    if (!base) material.require("eos");
    return libraryEos(base->eos, density_field);
  }
  const int base_index = base ? static_cast<int>(base->eos.index()) : -1;
  const std::size_t index = modelIndex(entriesOf(*block), keys::eos_models, base_index, "eos");
  if (index == 3) return readTabular(*block, base_dir, density_field);

  // The analytic models take the material's density: the deck's, else the library entry's.
  double density = 0.0;
  if (density_field)
    density = density_field->positive(units::density);
  else if (base)
    density = eos::referenceDensity(base->eos);
  else
    material.require("density");
  auto setDensity = [&](auto& p) { p.density = density; };
  // The library's parameters when the block keeps its model (get_if of a null pointer is null).
  const eos::Eos* same = base ? &base->eos : nullptr;
  if (index == 0) return readModel(*block, keys::mie_gruneisen, std::get_if<eos::MieGruneisen>(same), setDensity);
  if (index == 1) return readModel(*block, keys::polynomial, std::get_if<eos::Polynomial>(same), setDensity);
  if (index == 2) return readModel(*block, keys::tillotson, std::get_if<eos::Tillotson>(same), setDensity);
  return readModel(*block, keys::ideal_gas, std::get_if<eos::IdealGas>(same), setDensity);
}

strength::Yield parseStrength(const MapField& material, const ImpactMaterialParameters* base) {
  std::optional<Field> block = material.find("strength");
  if (!block) {
    if (!base) material.require("strength");
    return base->yield;
  }
  const int base_index = base ? static_cast<int>(base->yield.index()) : -1;
  const std::size_t index = modelIndex(entriesOf(*block), keys::strength_models, base_index, "strength");
  const strength::Yield* same = base ? &base->yield : nullptr;
  auto keep = [](auto&) {};
  switch (index) {
    case 0:
      block->map({"model"});
      return strength::NoStrength{};
    case 1:
      return readModel(*block, keys::linear_hardening, std::get_if<strength::LinearHardening>(same), keep);
    case 2:
      return readModel(*block, keys::power_law, std::get_if<strength::PowerLaw>(same), keep);
    default:
      return readModel(*block, keys::johnson_cook, std::get_if<strength::JohnsonCook>(same), keep);
  }
}

double shearModulus(const MapField& material, const ImpactMaterialParameters* base, const strength::Yield& yield) {
  const bool has_strength = !std::holds_alternative<strength::NoStrength>(yield);
  std::optional<Field> field = material.find("shear_modulus");
  if (!field) {
    if (base) return base->shear_modulus;
    if (has_strength) material.require("shear_modulus");
    return 0.0;
  }
  const double G = field->quantity(units::pressure);
  if (G < 0.0) field->fail("must not be negative");
  if (G == 0.0 && has_strength) field->fail("must be positive for a material with strength");
  return G;
}

double meltTemperature(const strength::Yield& yield) {
  return std::visit(
      [](const auto& law) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(law)>, strength::NoStrength>)
          return 0.0;
        else
          return law.parameters().melt_temperature;
      },
      yield);
}

// Off unless the deck asks: a library entry's published set is only the starting point of
// `failure: { model: johnson-cook }` (the default failure model is eigenerosion: docs/deck.md,
// docs/theory.md §8).
std::optional<strength::JohnsonCookDamageParameters> parseFailure(const MapField& material,
                                                                  const ImpactMaterialParameters* base,
                                                                  const strength::Yield& yield) {
  std::optional<Field> block = material.find("failure");
  if (!block) return std::nullopt;
  constexpr const char* failure_models[] = {"none", "johnson-cook"};
  if (modelIndex(entriesOf(*block), failure_models, -1, "failure") == 0) {
    block->map({"model"});
    return std::nullopt;
  }
  if (std::holds_alternative<strength::NoStrength>(yield))
    block->failBare("Johnson-Cook damage accumulates plastic strain, so it needs a strength model other than none");
  const bool from_library = base && base->damage;
  strength::JohnsonCookDamageParameters p;
  if (from_library)
    p = *base->damage;
  else
    p.melt_temperature = meltTemperature(yield);
  p = readKeys(block->map(allowedKeys(keys::johnson_cook_damage)), keys::johnson_cook_damage, p, from_library);
  reportAt(*block, [&] { p.check(); });
  return p;
}

// A parameter block whose every key is optional over the library's values (or the defaults),
// except those the table requires when there is no library entry.
template <typename P, std::size_t N>
P parseBlock(const MapField& material, std::string_view key, const keys::Key<P> (&table)[N], const P* base,
             bool required) {
  std::optional<Field> block = material.find(key);
  if (!block) {
    if (base) return *base;
    if (required) material.require(key);
    return P{};
  }
  std::vector<std::string_view> allowed = allowedKeys(table);
  allowed.erase(allowed.begin());  // these blocks have no model
  P p = readKeys(block->map(allowed), table, base ? *base : P{}, base != nullptr);
  reportAt(*block, [&] { p.check(); });
  return p;
}

double parseTensionCutoff(const MapField& material, double base) {
  std::optional<Field> field = material.find("tension_cutoff");
  if (!field) return base;
  if (field->node().IsScalar() && field->node().Scalar() == "none") return -std::numeric_limits<double>::infinity();
  const double floor = field->quantity(units::pressure);
  if (floor > 0.0)
    field->fail("must not be positive: it is the most negative pressure the material bears, such as '-1.5 GPa'");
  return floor;
}

// The tension at which intact material spalls ("1.4 GPa"); `none` or 0: never.
double parseSpallStrength(const MapField& material, double base) {
  std::optional<Field> field = material.find("spall_strength");
  if (!field) return base;
  if (field->node().IsScalar() && field->node().Scalar() == "none") return 0.0;
  const double strength = field->quantity(units::pressure);
  if (strength < 0.0)
    field->fail("must not be negative: it is a tension given as a positive pressure, such as '1.4 GPa'");
  return strength;
}

// Eigenerosion's critical energy-release rate G_c ("100 kJ/m^2"); 0 switches eigenerosion off.
double parseFractureEnergy(const MapField& material, double base) {
  std::optional<Field> field = material.find("fracture_energy");
  if (!field) return base;
  const double gc = field->quantity(units::energy_per_area);
  if (gc < 0.0) field->fail("must not be negative (0 switches eigenerosion off)");
  return gc;
}

// The stress triaxiality below which plastic work does not drive eigenerosion ("-0.333", Bao &
// Wierzbicki's cut-off); `none` counts all plastic work.
double parseFractureTriaxiality(const MapField& material, double base) {
  std::optional<Field> field = material.find("fracture_min_triaxiality");
  if (!field) return base;
  if (field->node().IsScalar() && field->node().Scalar() == "none") return -std::numeric_limits<double>::infinity();
  return field->quantity(units::dimensionless);
}

MaterialConfig parseImpact(const std::string& name, const Field& field, const fs::path& base_dir) {
  std::vector<std::string_view> allowed{"model", "density"};
  allowed.insert(allowed.end(), std::begin(impact_only_keys), std::end(impact_only_keys));
  allowed.push_back("fracture_energy");
  allowed.push_back("fracture_min_triaxiality");
  MapField map = field.map(allowed);
  MaterialConfig material;
  material.name = name;
  material.model = "impact";
  const library::Entry* entry = nullptr;
  if (std::optional<Field> library = map.find("library")) {
    const std::string wanted = library->text("a library material such as Al6061-T6");
    entry = reportAt(*library, [&] { return &library::find(wanted); });
    material.library = entry->name;
  }
  const ImpactMaterialParameters* base = entry ? &entry->parameters : nullptr;
  ImpactMaterialParameters& p = material.impact;
  p.eos = parseEos(map, base, base_dir);
  p.yield = parseStrength(map, base);
  p.shear_modulus = shearModulus(map, base, p.yield);
  p.damage = parseFailure(map, base, p.yield);
  p.thermal = parseBlock(map, "thermal", keys::thermal, base ? &base->thermal : nullptr, true);
  const ViscosityParameters default_viscosity;
  p.viscosity = parseBlock(map, "viscosity", keys::viscosity, base ? &base->viscosity : &default_viscosity, false);
  p.pressure_floor = parseTensionCutoff(map, base ? base->pressure_floor : p.pressure_floor);
  p.spall_strength = parseSpallStrength(map, base ? base->spall_strength : 0.0);
  p.fracture_energy = parseFractureEnergy(map, base ? base->fracture_energy : 0.0);
  p.fracture_min_triaxiality =
      parseFractureTriaxiality(map, base ? base->fracture_min_triaxiality : p.fracture_min_triaxiality);
  return material;
}

MaterialConfig parseNeoHookean(const std::string& name, const Field& field) {
  MapField map = field.map(std::vector<std::string_view>(std::begin(neo_hookean_keys), std::end(neo_hookean_keys)));
  MaterialConfig material;
  material.name = name;
  material.model = "neo-hookean";
  NeoHookeanParameters& p = material.neo_hookean;
  p.density = map.require("density").positive(units::density);
  p.youngs_modulus = map.require("youngs_modulus").positive(units::pressure);
  Field poisson = map.require("poisson_ratio");
  p.poisson_ratio = poisson.quantity(units::dimensionless);
  if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5)) poisson.fail("must lie in (-1, 0.5)");
  p.fracture_energy = parseFractureEnergy(map, 0.0);
  // The model's own check stays the authority on what is physical, should it grow stricter.
  reportAt(field, [&] { p.check(); });
  return material;
}

MaterialConfig parseMaterial(const std::string& name, const Field& field, const fs::path& base_dir) {
  const MapField entries = entriesOf(field);
  if (std::optional<Field> model = entries.find("model")) {
    const std::string text = model->text();
    if (text == "neo-hookean") return parseNeoHookean(name, field);
    if (text == "impact") return parseImpact(name, field, base_dir);
    model->fail("unknown material model (known: neo-hookean, impact)");
  }
  for (std::string_view key : impact_only_keys)
    if (entries.find(key)) return parseImpact(name, field, base_dir);
  return parseNeoHookean(name, field);
}

}  // namespace

std::vector<MaterialConfig> parseMaterials(const Field& field, const fs::path& base_dir) {
  MapField map = field.namedMap();
  if (map.entries().empty()) field.fail("must define at least one material");
  std::vector<MaterialConfig> materials;
  for (const MapField::Entry& entry : map.entries())
    materials.push_back(parseMaterial(entry.key, entry.value, base_dir));
  return materials;
}

}  // namespace kessler::io
