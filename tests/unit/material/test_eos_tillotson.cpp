// Tillotson EOS (iSALE aluminium, Tillotson 1962; docs/materials.md) against an independent evaluation of
// Melosh 1989, appendix II, and continuity across the boundaries of its regions.
#include "core/error.hpp"
#include "material/eos/tillotson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kessler::eos {
namespace {

const TillotsonParameters al{.density = 2700.0,
                             .a = 0.5,
                             .b = 1.63,
                             .A = 75.2e9,
                             .B = 65e9,
                             .E0 = 5.0e6,
                             .alpha = 5.0,
                             .beta = 5.0,
                             .E_iv = 3.0e6,
                             .E_cv = 13.9e6};

struct Reference {
  double p, scale;
};

// Written out from Melosh (1989), appendix II, independently of the production code.
Reference independent(const TillotsonParameters& t, double rho, double e) {
  const double eta = rho / t.density, mu = eta - 1.0;
  const double omega = e / (t.E0 * eta * eta) + 1.0;
  const double pc = (t.a + t.b / omega) * rho * e + t.A * mu + t.B * mu * mu;
  const double sc = (t.a + t.b / omega) * rho * std::abs(e) + std::abs(t.A * mu) + std::abs(t.B) * mu * mu;
  const double z = t.density / rho - 1.0;
  const double damp = std::exp(-t.alpha * z * z);
  const double pe = t.a * rho * e + (t.b * rho * e / omega + t.A * mu * std::exp(-t.beta * z)) * damp;
  const double se =
      t.a * rho * std::abs(e) + (t.b * rho * std::abs(e) / omega + std::abs(t.A * mu) * std::exp(-t.beta * z)) * damp;
  if (rho >= t.density || e <= t.E_iv) return {pc, sc};
  if (e >= t.E_cv) return {pe, se};
  const double f = (e - t.E_iv) / (t.E_cv - t.E_iv);
  return {f * pe + (1.0 - f) * pc, f * se + (1.0 - f) * sc};
}

TEST(EosTillotson, MatchesIndependentFormulaOverWideSweep) {
  const Tillotson eos(al);
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const double rho = al.density * 0.05 * std::pow(60.0, i / 100.0);  // 0.05 rho0 ... 3 rho0
    for (int k = -1; k <= 75; ++k) {
      const double e = k < 0 ? 0.0 : std::pow(10.0, k / 10.0);  // 0, 1 J/kg ... 32 MJ/kg
      const Reference r = independent(al, rho, e);
      const State s = eos.evaluate(rho, e);
      if (r.scale > 0.0) worst = std::max(worst, std::abs(s.pressure - r.p) / r.scale);
      EXPECT_GT(s.sound_speed2, 0.0);
      EXPECT_TRUE(std::isfinite(s.dp_de));
    }
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(EosTillotson, ContinuousAcrossRegionBoundaries) {
  const Tillotson eos(al);
  const double rho0 = al.density, tiny = 1e-10;
  auto close = [](const State& a, const State& b) {
    return std::abs(a.pressure - b.pressure) <= 1e-6 * (std::abs(a.pressure) + 1e3);
  };
  // Across rho = rho0 at energies in every expanded region.
  for (double e : {1e6, 5e6, 10e6, 20e6})
    EXPECT_TRUE(close(eos.evaluate(rho0 * (1 - tiny), e), eos.evaluate(rho0 * (1 + tiny), e))) << e;
  // Across E_iv and E_cv at expanded densities.
  for (double eta : {0.95, 0.7, 0.3, 0.1}) {
    const double rho = eta * rho0;
    for (double boundary : {al.E_iv, al.E_cv})
      EXPECT_TRUE(close(eos.evaluate(rho, boundary * (1 - tiny)), eos.evaluate(rho, boundary * (1 + tiny))))
          << eta << " " << boundary;
  }
}

TEST(EosTillotson, ColdExpandedStatesUseTheCompressedFormula) {
  const Tillotson eos(al);
  const double rho = 0.8 * al.density, e = 1e6, mu = -0.2;
  const double omega = 1.0 + e / (al.E0 * 0.64);
  EXPECT_NEAR(eos.evaluate(rho, e).pressure, (al.a + al.b / omega) * rho * e + al.A * mu + al.B * mu * mu, 1.0);
}

TEST(EosTillotson, CheckNamesTheBadParameter) {
  auto message = [](TillotsonParameters p) {
    try {
      Tillotson eos(p);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  TillotsonParameters p = al;
  p.E_cv = 2e6;
  EXPECT_EQ(message(p), "eos.E_cv must be greater than E_iv = 3000000 (got 2000000)");
  p = al;
  p.A = 0.0;
  EXPECT_EQ(message(p), "eos.A must be positive (got 0)");
  EXPECT_THROW(Tillotson(al).evaluate(2700.0, -6e6), NumericalError);  // omega <= 0
}

}  // namespace
}  // namespace kessler::eos
