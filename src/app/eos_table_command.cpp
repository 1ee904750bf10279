// `kessler eos-table --eos MODEL [parameters] [grid] FILE`: tabulates a Mie-Gruneisen, polynomial
// or Tillotson EOS on a (rho, T) grid with e = c_v (T - T0) and writes it as SESAME ASCII (not the
// ideal gas: see eos::tabulate).
// Quantities accept units ("5.24 km/s", "75.2 GPa", "2.7 g/cm^3"); bare numbers are SI.
#include "app/eos_table_command.hpp"

#include "core/error.hpp"
#include "core/units.hpp"
#include "material/eos/tabulate.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

namespace kessler::app {

namespace {

// One model parameter as a command-line option: which models take it, and its default if it
// may be left out (k2, k3 of the polynomial).
struct Parameter {
  const char* option;
  units::Dimension dimension;
  std::vector<std::string> models;
  const char* help;
  std::optional<double> fallback;
};

const std::vector<Parameter>& parameters() {
  const std::string mg = "mie-gruneisen", poly = "polynomial", till = "tillotson";
  static const std::vector<Parameter> all{
      {"--c0", units::velocity, {mg}, "Bulk sound speed c0 of Us = c0 + s up", std::nullopt},
      {"--s", units::dimensionless, {mg}, "Hugoniot slope s of Us = c0 + s up", std::nullopt},
      {"--gamma0", units::dimensionless, {mg, poly}, "Gruneisen parameter Gamma0", std::nullopt},
      {"--k1", units::pressure, {poly}, "K1 (bulk modulus)", std::nullopt},
      {"--k2", units::pressure, {poly}, "K2 (default 0)", 0.0},
      {"--k3", units::pressure, {poly}, "K3 (default 0)", 0.0},
      {"--a", units::dimensionless, {till}, "Tillotson a", std::nullopt},
      {"--b", units::dimensionless, {till}, "Tillotson b", std::nullopt},
      {"--A", units::pressure, {till}, "Tillotson A", std::nullopt},
      {"--B", units::pressure, {till}, "Tillotson B", std::nullopt},
      {"--E0", units::specific_energy, {till}, "Tillotson E0", std::nullopt},
      {"--alpha", units::dimensionless, {till}, "Tillotson alpha", std::nullopt},
      {"--beta", units::dimensionless, {till}, "Tillotson beta", std::nullopt},
      {"--Eiv", units::specific_energy, {till}, "Tillotson incipient vaporisation energy E_iv", std::nullopt},
      {"--Ecv", units::specific_energy, {till}, "Tillotson complete vaporisation energy E_cv", std::nullopt},
  };
  return all;
}

struct EosTableArguments {
  std::string model;
  std::string output;
  std::map<std::string, std::string> text;  // option -> as given, for every quantity
  int n_rho = 100, n_t = 100, material_id = 1;
};

double quantity(const EosTableArguments& args, const std::string& option, units::Dimension dimension) {
  try {
    return units::toSI(args.text.at(option), dimension);
  } catch (const InputError& e) {
    throw InputError(fmt::format("eos-table: {}: {}", option, e.what()));
  }
}

eos::Eos buildEos(const EosTableArguments& args) {
  std::map<std::string, double> v;
  for (const Parameter& p : parameters()) {
    const bool used = std::find(p.models.begin(), p.models.end(), args.model) != p.models.end();
    const bool given = args.text.count(p.option) > 0;
    if (given && !used)
      throw InputError(fmt::format("eos-table: {} is not a parameter of the {} EOS", p.option, args.model));
    if (!used) continue;
    if (!given && !p.fallback)
      throw InputError(fmt::format("eos-table: {} is required for the {} EOS", p.option, args.model));
    v[p.option] = given ? quantity(args, p.option, p.dimension) : *p.fallback;
  }
  const double rho0 = quantity(args, "--density", units::density);
  try {
    if (args.model == "mie-gruneisen")
      return eos::MieGruneisen({.density = rho0, .sound_speed = v["--c0"], .slope = v["--s"], .gamma0 = v["--gamma0"]});
    if (args.model == "polynomial")
      return eos::Polynomial(
          {.density = rho0, .k1 = v["--k1"], .k2 = v["--k2"], .k3 = v["--k3"], .gamma0 = v["--gamma0"]});
    return eos::Tillotson({.density = rho0,
                           .a = v["--a"],
                           .b = v["--b"],
                           .A = v["--A"],
                           .B = v["--B"],
                           .E0 = v["--E0"],
                           .alpha = v["--alpha"],
                           .beta = v["--beta"],
                           .E_iv = v["--Eiv"],
                           .E_cv = v["--Ecv"]});
  } catch (const InputError& e) {
    throw InputError(fmt::format("eos-table: {}", e.what()));
  }
}

void runEosTable(const EosTableArguments& args) {
  const eos::Eos model = buildEos(args);
  const double rho0 = eos::referenceDensity(model);
  auto optional = [&](const char* option, units::Dimension dimension, double fallback) {
    return args.text.count(option) ? quantity(args, option, dimension) : fallback;
  };
  const eos::TableGrid grid{.rho_min = optional("--rho-min", units::density, 0.5 * rho0),
                            .rho_max = optional("--rho-max", units::density, 2.0 * rho0),
                            .n_rho = args.n_rho,
                            .t_min = optional("--t-min", units::temperature, 0.0),
                            .t_max = optional("--t-max", units::temperature, 20000.0),
                            .n_t = args.n_t};
  const double cv = quantity(args, "--specific-heat", units::specific_heat);
  const double t0 = optional("--t0", units::temperature, 293.0);
  const eos::SesameTable table = eos::tabulate(model, grid, cv, t0, args.material_id);
  eos::writeSesame(table, args.output);
  fmt::print(
      "{}: {} EOS, material {}, {} x {} grid, rho {:.6g}-{:.6g} kg/m^3, T {:.6g}-{:.6g} K, "
      "e {:.6g}-{:.6g} J/kg\n",
      args.output, eos::modelName(model), args.material_id, grid.n_rho, grid.n_t, grid.rho_min, grid.rho_max,
      grid.t_min, grid.t_max, table.energy.front(), table.energy.back());
}

}  // namespace

void addEosTableCommand(CLI::App& app) {
  auto args = std::make_shared<EosTableArguments>();
  CLI::App* cmd = app.add_subcommand(
      "eos-table", "Write a SESAME table (201 + 301) from an analytic EOS, with e(rho, T) = c_v (T - T0)");
  cmd->add_option("file", args->output, "SESAME file to write")->required();
  cmd->add_option("--eos", args->model, "Model to tabulate")
      ->required()
      ->check([](const std::string& model) -> std::string {
        // Before the list, so that asking for the gas says why it is not one of the choices.
        if (model != "ideal-gas") return "";
        return "the ideal-gas EOS is not tabulated: it is exact and cheap as it stands, and a table's c^2 floor "
               "would give the cold gas a sound speed (docs/eos.md); use it in the deck as "
               "`eos: { model: ideal-gas, gamma: ... }`";
      })
      ->check(CLI::IsMember({"mie-gruneisen", "polynomial", "tillotson"}));
  auto quantityOption = [&](const std::string& name, const std::string& help) {
    cmd->add_option_function<std::string>(
        name, [args, name](const std::string& text) { args->text[name] = text; }, help);
  };
  quantityOption("--density", "Reference density rho0 (required), e.g. '2703 kg/m^3'");
  quantityOption("--specific-heat", "Specific heat c_v (required), e.g. '896 J/(kg*K)'");
  quantityOption("--t0", "Temperature at e = 0 (default 293 K)");
  for (const Parameter& p : parameters())
    quantityOption(p.option, fmt::format("{} [{}]", p.help, fmt::join(p.models, ", ")));
  quantityOption("--rho-min", "Lowest density of the grid (default 0.5 rho0)");
  quantityOption("--rho-max", "Highest density of the grid (default 2 rho0)");
  quantityOption("--t-min", "Lowest temperature (default 0 K)");
  quantityOption("--t-max", "Highest temperature (default 20000 K)");
  cmd->add_option("--nrho", args->n_rho, "Number of densities, spaced geometrically (default 100)")
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--nt", args->n_t, "Number of temperatures, spaced evenly (default 100)")
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--material-id", args->material_id, "SESAME material id (default 1)")->check(CLI::PositiveNumber);
  cmd->callback([args] {
    for (const char* required : {"--density", "--specific-heat"})
      if (!args->text.count(required)) throw InputError(fmt::format("eos-table: {} is required", required));
    runEosTable(*args);
  });
}

}  // namespace kessler::app
