// Thermodynamic consistency of every EOS: the returned c^2 = dp/drho|_e + (p/rho^2) dp/de|_rho
// and dp/de against central finite differences of the model's own p(rho, e), over wide sweeps.
// States where c^2 is floored, and finite-difference stencils across a region boundary (where
// the derivatives jump), are left out.
#include "material/eos/eos.hpp"
#include "material/eos/tabulate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace kessler::eos {
namespace {

struct Worst {
  double c2 = 0.0, dp_de = 0.0;
  int checked = 0;
};

// Fourth-order central difference: truncation O(h^4), so steps can be large enough that the
// rounding of p (up to ~1e4 rho0 c0^2 near the Mie-Gruneisen limit) stays small.
template <class F>
double centralDifference(const F& f, double x, double h) {
  return (8.0 * (f(x + h) - f(x - h)) - (f(x + 2.0 * h) - f(x - 2.0 * h))) / (12.0 * h);
}

template <class Model>
Worst fdCheck(const Model& eos, double k0, const std::vector<double>& rhos, const std::vector<double>& energies,
              double energy_scale, const std::function<bool(double, double, double, double)>& crosses_boundary) {
  Worst w;
  for (double rho : rhos) {
    for (double e : energies) {
      const double h = 1e-4 * rho, k = 1e-3 * std::max(std::abs(e), energy_scale);
      if (crosses_boundary(rho, e, h, k)) continue;
      const State s = eos.evaluate(rho, e);
      if (s.sound_speed2 <= 1.01 * sound_speed2_floor_fraction * k0 / rho) continue;
      const double dp_drho = centralDifference([&](double r) { return eos.evaluate(r, e).pressure; }, rho, h);
      const double dp_de = centralDifference([&](double x) { return eos.evaluate(rho, x).pressure; }, e, k);
      const double term = s.pressure / (rho * rho) * dp_de;
      w.c2 = std::max(w.c2, std::abs(s.sound_speed2 - (dp_drho + term)) / (std::abs(dp_drho) + std::abs(term)));
      w.dp_de = std::max(w.dp_de, std::abs(s.dp_de - dp_de) / std::max(std::abs(dp_de), 1e-3 * rho));
      ++w.checked;
    }
  }
  return w;
}

std::vector<double> logRange(double from, double to, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from * std::pow(to / from, i / double(n - 1)));
  return v;
}

bool near(double x, double boundary, double step) {
  return std::abs(x - boundary) <= 3.0 * step;
}

TEST(EosConsistency, MieGruneisen) {
  const MieGruneisen eos({.density = 2703.0, .sound_speed = 5240.0, .slope = 1.40, .gamma0 = 1.97});
  const Worst w =
      fdCheck(eos, 2703.0 * 5240.0 * 5240.0, logRange(0.5 * 2703.0, 3.3 * 2703.0, 60), logRange(1.0, 1e7, 50), 1e6,
              [](double rho, double, double h, double) { return near(rho, 2703.0, h); });
  EXPECT_GT(w.checked, 2400);
  EXPECT_LT(w.c2, 1e-6);
  EXPECT_LT(w.dp_de, 1e-6);
}

TEST(EosConsistency, Polynomial) {
  const Polynomial eos({.density = 2785.0, .k1 = 74.2e9, .k2 = -60.5e9, .k3 = 36.5e9, .gamma0 = 1.96});
  const Worst w = fdCheck(eos, 74.2e9, logRange(0.5 * 2785.0, 2.0 * 2785.0, 60), logRange(1.0, 1e7, 50), 1e6,
                          [](double rho, double, double h, double) { return near(rho, 2785.0, h); });
  EXPECT_GT(w.checked, 2400);
  EXPECT_LT(w.c2, 1e-6);
  EXPECT_LT(w.dp_de, 1e-6);
}

TEST(EosConsistency, Tillotson) {
  const TillotsonParameters p{.density = 2700.0,
                              .a = 0.5,
                              .b = 1.63,
                              .A = 75.2e9,
                              .B = 65e9,
                              .E0 = 5e6,
                              .alpha = 5.0,
                              .beta = 5.0,
                              .E_iv = 3e6,
                              .E_cv = 13.9e6};
  const Tillotson eos(p);
  const Worst w = fdCheck(eos, p.A, logRange(0.05 * 2700.0, 3.0 * 2700.0, 70), logRange(1.0, 3e7, 60), 1e3,
                          [&](double rho, double e, double h, double k) {
                            return near(rho, p.density, h) || near(e, p.E_iv, k) || near(e, p.E_cv, k);
                          });
  EXPECT_GT(w.checked, 1600);  // cold expanded states below ~0.8 rho0 have c^2 < 0: floored
  EXPECT_LT(w.c2, 1e-6);
  EXPECT_LT(w.dp_de, 1e-6);
}

TEST(EosConsistency, IdealGas) {
  // No floor (K0 = 0): only e = 0, where c^2 = 0, is left out. With energy_scale 1 J/kg the energy
  // stencil stays above 0, where the law clamps e.
  const IdealGas eos({.density = 1.0, .gamma = 5.0 / 3.0});
  std::vector<double> energies = logRange(1.0, 1e7, 50);
  energies.insert(energies.begin(), 0.0);
  const Worst w =
      fdCheck(eos, 0.0, logRange(1e-3, 1e3, 60), energies, 1.0, [](double, double, double, double) { return false; });
  EXPECT_EQ(w.checked, 60 * 50);
  EXPECT_LT(w.c2, 1e-6);
  EXPECT_LT(w.dp_de, 1e-6);
}

TEST(EosConsistency, TabularInsideItsCells) {
  // Cell interiors only: the interpolant's derivatives jump on grid lines. With the caloric
  // mapping e = c_v (T - T0) the temperature cell of a given e is the same at every density.
  const TableGrid grid{.rho_min = 1351.5, .rho_max = 5406.0, .n_rho = 40, .t_min = 0.0, .t_max = 20000.0, .n_t = 30};
  const double cv = 896.0, t0 = 293.0;
  const SesameTable table = tabulate(Tillotson({.density = 2700.0,
                                                .a = 0.5,
                                                .b = 1.63,
                                                .A = 75.2e9,
                                                .B = 65e9,
                                                .E0 = 5e6,
                                                .alpha = 5.0,
                                                .beta = 5.0,
                                                .E_iv = 3e6,
                                                .E_cv = 13.9e6}),
                                     grid, cv, t0);
  const Tabular eos(std::make_shared<const SesameTable>(table));
  std::vector<double> rhos, energies;
  for (std::size_t i = 0; i + 1 < table.rho.size(); ++i)
    for (double f : {0.23, 0.61}) rhos.push_back(table.rho[i] * std::pow(table.rho[i + 1] / table.rho[i], f));
  for (std::size_t j = 0; j + 1 < table.temperature.size(); ++j)
    for (double f : {0.31, 0.77})
      energies.push_back(table.energy[j * table.rho.size()] * (1.0 - f) + table.energy[(j + 1) * table.rho.size()] * f);
  const Worst w = fdCheck(eos, 75.2e9, rhos, energies, 1e3, [](double, double, double, double) { return false; });
  EXPECT_GT(w.checked, 3000);
  EXPECT_LT(w.c2, 1e-6);
  EXPECT_LT(w.dp_de, 1e-6);
}

}  // namespace
}  // namespace kessler::eos
