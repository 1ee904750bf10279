// Polynomial EOS against an independent evaluation of p = K1 mu + K2 mu^2 + K3 mu^3 +
// Gamma0 E (1 + mu) with E = rho0 e (K2, K3 dropped in tension), and its parameter checks.
#include "core/error.hpp"
#include "material/eos/polynomial.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kessler::eos {
namespace {

// Aluminium-like coefficients with all three terms present (K2 < 0 exercises the sign).
const PolynomialParameters al{.density = 2785.0, .k1 = 74.2e9, .k2 = -60.5e9, .k3 = 36.5e9, .gamma0 = 1.96};

TEST(EosPolynomial, MatchesIndependentFormulaOverWideSweep) {
  const Polynomial eos(al);
  double worst_p = 0.0, worst_c2 = 0.0;
  for (int i = 0; i <= 80; ++i) {
    const double eta = 0.5 * std::pow(4.0, i / 80.0);  // rho/rho0 from 0.5 to 2
    const double rho = al.density * eta, mu = eta - 1.0;
    for (int k = -1; k <= 70; ++k) {
      const double e = k < 0 ? 0.0 : std::pow(10.0, k / 10.0);
      const double energy_per_volume = al.density * e;
      const double k2 = mu > 0.0 ? al.k2 : 0.0, k3 = mu > 0.0 ? al.k3 : 0.0;
      const double p = ((k3 * mu + k2) * mu + al.k1) * mu + al.gamma0 * energy_per_volume * (1.0 + mu);
      const double scale = std::abs(al.k1 * mu) + std::abs(k2 * mu * mu) + std::abs(k3 * mu * mu * mu) +
                           al.gamma0 * energy_per_volume * eta;
      // dp/drho|_e = (dp/dmu|_E) / rho0, with the energy term Gamma0 E (1 + mu) = Gamma0 rho e.
      const double dp_drho = (al.k1 + 2.0 * k2 * mu + 3.0 * k3 * mu * mu + al.gamma0 * energy_per_volume) / al.density;
      const double c2 =
          std::max(dp_drho + p / (rho * rho) * al.gamma0 * rho, sound_speed2_floor_fraction * al.k1 / rho);
      const State s = eos.evaluate(rho, e);
      worst_p = std::max(worst_p, std::abs(s.pressure - p) / scale);
      worst_c2 = std::max(worst_c2, std::abs(s.sound_speed2 - c2) / c2);
      EXPECT_NEAR(s.dp_de, al.gamma0 * rho, 1e-15 * al.gamma0 * rho);
    }
  }
  EXPECT_LT(worst_p, 1e-13);
  EXPECT_LT(worst_c2, 1e-12);
}

TEST(EosPolynomial, LinearSteelHasTheBulkSoundSpeed) {
  // Zhao & Song 2010 steel (Explosion and Shock Waves 30(4); docs/materials.md): K1 = 149 GPa, K2 = K3 = 0.
  const Polynomial steel({.density = 7800.0, .k1 = 149e9, .k2 = 0.0, .k3 = 0.0, .gamma0 = 0.0});
  const State s = steel.evaluate(7800.0, 0.0);
  EXPECT_EQ(s.pressure, 0.0);
  EXPECT_NEAR(s.sound_speed2, 149e9 / 7800.0, 1e-6);
}

TEST(EosPolynomial, CheckNamesTheBadParameter) {
  auto message = [](PolynomialParameters p) {
    try {
      Polynomial eos(p);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  PolynomialParameters p = al;
  p.k1 = -1e9;
  EXPECT_EQ(message(p), "eos.k1 must be positive (got -1000000000)");
  p = al;
  p.k3 = INFINITY;
  EXPECT_EQ(message(p), "eos.k3 must be finite (got inf)");
  p = al;
  p.gamma0 = -0.5;
  EXPECT_EQ(message(p), "eos.gamma0 must be non-negative (got -0.5)");
}

}  // namespace
}  // namespace kessler::eos
