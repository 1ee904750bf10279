#include "material/eos/tabulate.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler::eos {

namespace {

void require(bool ok, const char* name, const char* what, double value) {
  if (!ok) throw InputError(fmt::format("eos table: {} must be {} (got {})", name, what, value));
}

// The bulk modulus written as B0 in table 201.
double referenceModulus(const Eos& eos) {
  return std::visit(
      [](const auto& model) {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (std::is_same_v<Model, MieGruneisen>) {
          const MieGruneisenParameters& p = model.parameters();
          return p.density * p.sound_speed * p.sound_speed;
        } else if constexpr (std::is_same_v<Model, Polynomial>) {
          return model.parameters().k1;
        } else if constexpr (std::is_same_v<Model, Tillotson>) {
          return model.parameters().A;
        } else if constexpr (std::is_same_v<Model, Tabular>) {
          return model.table().bulk_modulus;
        } else {
          static_assert(std::is_same_v<Model, IdealGas>, "a model of the Eos variant has no reference modulus");
          return 0.0;  // never written: tabulate() refuses the ideal gas
        }
      },
      eos);
}

}  // namespace

void TableGrid::check() const {
  require(std::isfinite(rho_min) && rho_min > 0.0, "rho_min", "positive", rho_min);
  require(std::isfinite(rho_max) && rho_max > rho_min, "rho_max", fmt::format("above rho_min = {}", rho_min).c_str(),
          rho_max);
  require(n_rho >= 2, "n_rho", "at least 2", n_rho);
  require(std::isfinite(t_min) && t_min >= 0.0, "t_min", "non-negative", t_min);
  require(std::isfinite(t_max) && t_max > t_min, "t_max", fmt::format("above t_min = {}", t_min).c_str(), t_max);
  require(n_t >= 2, "n_t", "at least 2", n_t);
  // The word count of table 301 must fit the I6 field of its SESAME header.
  const double words = 2.0 + n_rho + n_t + 2.0 * n_rho * n_t;
  require(words <= 999999.0, "n_rho x n_t", "at most about 5e5 (the 301 word count must fit in I6)",
          double(n_rho) * n_t);
}

SesameTable tabulate(const Eos& eos, const TableGrid& grid, double specific_heat, double temperature0,
                     int material_id) {
  grid.check();
  require(std::isfinite(specific_heat) && specific_heat > 0.0, "specific_heat", "positive", specific_heat);
  require(std::isfinite(temperature0) && temperature0 >= 0.0, "T0", "non-negative", temperature0);
  require(material_id > 0 && material_id <= 999999, "material_id", "between 1 and 999999", material_id);
  // A table read back floors c^2 against B0 or its largest |P| (docs/eos.md, "Floors"): the cold
  // gas, whose c^2 is exactly 0 at e = 0 (the Noh problem's p0 = 0), would gain a sound speed. The
  // analytic law is exact and cheap, so there is nothing a table would add.
  if (std::holds_alternative<IdealGas>(eos))
    throw InputError(
        "eos table: the ideal-gas EOS is not tabulated (a table's c^2 floor would give the cold gas a sound "
        "speed it does not have); use it directly as `eos: { model: ideal-gas, gamma: ... }`");

  SesameTable t;
  t.material_id = material_id;
  t.density = referenceDensity(eos);
  t.bulk_modulus = referenceModulus(eos);
  t.temperature0 = temperature0;
  const auto nr = static_cast<std::size_t>(grid.n_rho), nt = static_cast<std::size_t>(grid.n_t);
  const double ratio = grid.rho_max / grid.rho_min;
  for (std::size_t i = 0; i < nr; ++i)
    t.rho.push_back(i + 1 == nr ? grid.rho_max : grid.rho_min * std::pow(ratio, double(i) / double(nr - 1)));
  for (std::size_t j = 0; j < nt; ++j)
    t.temperature.push_back(j + 1 == nt ? grid.t_max
                                        : grid.t_min + (grid.t_max - grid.t_min) * double(j) / double(nt - 1));
  t.pressure.resize(nr * nt);
  t.energy.resize(nr * nt);
  std::visit(
      [&](const auto& model) {
        for (std::size_t j = 0; j < nt; ++j) {
          const double e = specific_heat * (t.temperature[j] - temperature0);
          for (std::size_t i = 0; i < nr; ++i) {
            t.energy[j * nr + i] = e;
            try {
              t.pressure[j * nr + i] = model.evaluate(t.rho[i], e).pressure;
            } catch (const NumericalError& error) {
              throw NumericalError(fmt::format("eos table: grid point rho = {:.6g} kg/m^3, T = {:.6g} K: {}", t.rho[i],
                                               t.temperature[j], error.what()));
            }
          }
        }
      },
      eos);
  return t;
}

}  // namespace kessler::eos
