// Tabular EOS: an Al 6061-T6 Mie-Gruneisen EOS tabulated on a 100 x 100 grid, written and read
// back as SESAME, then evaluated off the grid against the analytic EOS; states outside the table.
#include "core/error.hpp"
#include "material/eos/tabulate.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace kessler::eos {
namespace {

const MieGruneisenParameters al6061{.density = 2703.0, .sound_speed = 5240.0, .slope = 1.40, .gamma0 = 1.97};
const TableGrid grid{.rho_min = 1351.5, .rho_max = 5406.0, .n_rho = 100, .t_min = 0.0, .t_max = 20000.0, .n_t = 100};
constexpr double cv = 896.0, t0 = 293.0;

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class EosTabular : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("kessler_eos_tabular_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(EosTabular, WriteReadRoundTripKeepsE15Point8Precision) {
  const SesameTable t = tabulate(MieGruneisen(al6061), grid, cv, t0, 3720);
  writeSesame(t, dir_ / "a.ses");
  const SesameTable r = readSesame(dir_ / "a.ses");
  EXPECT_EQ(r.material_id, 3720);
  EXPECT_NEAR(r.density, t.density, 5e-9 * t.density);
  EXPECT_NEAR(r.bulk_modulus, t.bulk_modulus, 5e-9 * t.bulk_modulus);
  EXPECT_EQ(r.temperature0, t0);
  ASSERT_EQ(r.rho.size(), t.rho.size());
  ASSERT_EQ(r.pressure.size(), t.pressure.size());
  for (std::size_t i = 0; i < t.rho.size(); ++i) EXPECT_NEAR(r.rho[i], t.rho[i], 5e-9 * t.rho[i]);
  for (std::size_t j = 0; j < t.temperature.size(); ++j)
    EXPECT_NEAR(r.temperature[j], t.temperature[j], 5e-9 * t.temperature[j]);
  for (std::size_t k = 0; k < t.pressure.size(); ++k) {
    EXPECT_NEAR(r.pressure[k], t.pressure[k], 5e-9 * std::abs(t.pressure[k]));
    EXPECT_NEAR(r.energy[k], t.energy[k], 5e-9 * std::abs(t.energy[k]));
  }
  // What was read writes back to the same text.
  writeSesame(r, dir_ / "b.ses");
  EXPECT_EQ(slurp(dir_ / "a.ses"), slurp(dir_ / "b.ses"));
  const std::string first_line = slurp(dir_ / "a.ses").substr(0, 81);
  EXPECT_EQ(first_line, std::string(" 0  3720   201     5") + std::string(55, ' ') + "    1\n");
}

TEST_F(EosTabular, MatchesTheAnalyticEosOffTheGrid) {
  const MieGruneisen analytic(al6061);
  writeSesame(tabulate(analytic, grid, cv, t0), dir_ / "mg.ses");
  const Tabular table(TabularParameters{.file = (dir_ / "mg.ses").string(), .material_id = 0});
  EXPECT_NEAR(table.referenceDensity(), 2703.0, 1e-5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double k0 = al6061.density * al6061.sound_speed * al6061.sound_speed;
  double worst = 0.0;
  for (int n = 0; n < 2000; ++n) {
    const double rho = grid.rho_min * std::pow(grid.rho_max / grid.rho_min, unit(rng));
    const double e = cv * (grid.t_min - t0) + cv * (grid.t_max - grid.t_min) * unit(rng);
    const double p_table = table.evaluate(rho, e).pressure, p = analytic.evaluate(rho, e).pressure;
    // Relative to |p|, with 5% of rho0 c0^2 (3.7 GPa) as the scale near p = 0.
    worst = std::max(worst, std::abs(p_table - p) / std::max(std::abs(p), 5e-2 * k0));
  }
  // Linear interpolation across drho/rho = 4^(1/99) - 1 = 1.4%: (drho)^2/8 |p''| with
  // p'' = 3.6 rho0 c0^2/rho0^2 at the kink of the Hugoniot reference at rho0 bounds this by 2e-3.
  EXPECT_LT(worst, 2e-3);
}

TEST_F(EosTabular, RefusesStatesOutsideTheTable) {
  const Tabular table(std::make_shared<const SesameTable>(tabulate(MieGruneisen(al6061), grid, cv, t0)));
  auto message = [&](double rho, double e) {
    try {
      table.evaluate(rho, e);
    } catch (const NumericalError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(1000.0, 1e5).find("rho = 1000 kg/m^3, e = 100000 J/kg lies outside the table"), std::string::npos);
  EXPECT_NE(message(6000.0, 1e5).find("rho in [1351.5, 5406] kg/m^3"), std::string::npos);
  EXPECT_NE(message(2703.0, 1e9).find("outside the table"), std::string::npos);
  EXPECT_NE(message(2703.0, -cv * t0 - 1.0).find("outside the table"), std::string::npos);
  EXPECT_THROW(Tabular().evaluate(2703.0, 0.0), NumericalError);
}

TEST_F(EosTabular, RefusesATableWhoseEnergyDoesNotIncreaseWithTemperature) {
  SesameTable t = tabulate(MieGruneisen(al6061), grid, cv, t0);
  t.energy[5 * t.rho.size() + 7] = t.energy[4 * t.rho.size() + 7];
  EXPECT_THROW(Tabular(std::make_shared<const SesameTable>(t)), InputError);
}

TEST_F(EosTabular, TabulateChecksItsGrid) {
  TableGrid bad = grid;
  bad.rho_max = 1000.0;
  try {
    tabulate(MieGruneisen(al6061), bad, cv, t0);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "eos table: rho_max must be above rho_min = 1351.5 (got 1000)");
  }
  EXPECT_THROW(tabulate(MieGruneisen(al6061), grid, -1.0, t0), InputError);
  bad = grid;
  bad.rho_max = 5.0 * al6061.density;  // beyond the Hugoniot limit s/(s-1) = 3.5
  EXPECT_THROW(tabulate(MieGruneisen(al6061), bad, cv, t0), NumericalError);
}

TEST_F(EosTabular, TabulateRefusesTheIdealGas) {
  // Read back, a table floors c^2 (docs/eos.md): the cold gas would gain a sound speed it lacks.
  try {
    tabulate(IdealGas({.density = 1.0, .gamma = 5.0 / 3.0}), grid, 3116.0, 0.0);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("eos table: the ideal-gas EOS is not tabulated")) << e.what();
  }
}

}  // namespace
}  // namespace kessler::eos
