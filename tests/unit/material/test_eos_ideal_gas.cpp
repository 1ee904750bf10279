// Ideal-gas EOS against p = (gamma - 1) rho e written out here, its c^2 against finite differences
// along an isentrope and against the identity c^2 = dp/drho|_e + p/rho^2 dp/de, the cold state
// e = 0 (p = c = 0, Noh 1987), and its parameter and state checks.
#include "core/error.hpp"
#include "material/eos/eos.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

namespace kessler::eos {
namespace {

const IdealGasParameters noh{.density = 1.0, .gamma = 5.0 / 3.0};

std::string message(const IdealGasParameters& p) {
  try {
    IdealGas eos(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Fourth-order central difference, as in test_eos_consistency.cpp.
template <class F>
double centralDifference(const F& f, double x, double h) {
  return (8.0 * (f(x + h) - f(x - h)) - (f(x + 2.0 * h) - f(x - 2.0 * h))) / (12.0 * h);
}

TEST(EosIdealGas, MatchesTheFormulaOverWideSweep) {
  for (double gamma : {1.001, 1.4, 5.0 / 3.0, 3.0}) {
    SCOPED_TRACE(gamma);
    const IdealGas eos({.density = 1.2, .gamma = gamma});
    for (int i = 0; i <= 60; ++i) {
      const double rho = 1.2 * std::pow(10.0, -3.0 + i / 10.0);  // 1e-3 to 1e3 rho0
      for (int k = -1; k <= 70; ++k) {
        const double e = k < 0 ? 0.0 : std::pow(10.0, k / 10.0);  // 0, then 1 J/kg to 10 MJ/kg
        const double p = (gamma - 1.0) * rho * e;
        const State s = eos.evaluate(rho, e);
        EXPECT_NEAR(s.pressure, p, 1e-15 * p);
        EXPECT_NEAR(s.dp_de, (gamma - 1.0) * rho, 1e-15 * (gamma - 1.0) * rho);
        EXPECT_NEAR(s.sound_speed2, gamma * (gamma - 1.0) * e, 1e-15 * gamma * (gamma - 1.0) * e);
        EXPECT_NEAR(s.sound_speed2, gamma * p / rho, 1e-15 * gamma * p / rho);
      }
    }
  }
}

TEST(EosIdealGas, SoundSpeedIsTheSlopeOfTheIsentrope) {
  // Along an isentrope p rho^-gamma is constant, so e = e1 (rho/rho1)^(gamma - 1), and
  // c^2 = dp/drho|_s (e.g. Zel'dovich & Raizer 1966, ch. I).
  const IdealGas eos(noh);
  const double gamma = noh.gamma;
  double worst = 0.0;
  for (double rho1 : {1e-2, 1.0, 4.0, 1e3}) {
    for (double e1 : {1.0, 5e2, 1e5, 1e7}) {
      auto isentrope = [&](double rho) { return eos.evaluate(rho, e1 * std::pow(rho / rho1, gamma - 1.0)).pressure; };
      const double slope = centralDifference(isentrope, rho1, 1e-3 * rho1);
      worst = std::max(worst, std::abs(eos.evaluate(rho1, e1).sound_speed2 - slope) / slope);
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(EosIdealGas, SoundSpeedSatisfiesTheThermodynamicIdentity) {
  const IdealGas eos({.density = 1.0, .gamma = 1.4});
  double worst = 0.0;
  for (double rho : {1e-3, 0.3, 1.0, 7.0, 1e3}) {
    for (double e : {1.0, 3e3, 2e5, 1e7}) {
      const double dp_drho = centralDifference([&](double r) { return eos.evaluate(r, e).pressure; }, rho, 1e-4 * rho);
      const double dp_de = centralDifference([&](double x) { return eos.evaluate(rho, x).pressure; }, e, 1e-3 * e);
      const double identity = dp_drho + eos.evaluate(rho, e).pressure / (rho * rho) * dp_de;
      worst = std::max(worst, std::abs(eos.evaluate(rho, e).sound_speed2 - identity) / identity);
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(EosIdealGas, ColdGasHasNoPressureAndNoSoundSpeed) {
  // Noh's gas starts at p0 = 0: no floor lifts c^2 above 0, there being no reference modulus.
  const IdealGas eos(noh);
  for (double rho : {1e-6, 1.0, 64.0}) {
    const State s = eos.evaluate(rho, 0.0);
    EXPECT_EQ(s.pressure, 0.0);
    EXPECT_EQ(s.sound_speed2, 0.0);
    EXPECT_DOUBLE_EQ(s.dp_de, 2.0 / 3.0 * rho);
    // The round-off of the energy update below e = 0 counts as the cold gas, not as tension.
    const State below = eos.evaluate(rho, -1e-12);
    EXPECT_EQ(below.pressure, 0.0);
    EXPECT_EQ(below.sound_speed2, 0.0);
  }
}

TEST(EosIdealGas, StrongShockIntoTheColdGasHasNohsCompression) {
  // Rankine-Hugoniot for a shock driven at speed u into the gas at rest with p0 = e0 = 0:
  // rho/rho0 = (gamma + 1)/(gamma - 1) = 4 for gamma = 5/3, e = u^2/2, p = rho0 Us u with
  // Us = u rho/(rho - rho0) (Noh 1987, J. Comput. Phys. 72:78, the planar problem: p = 4/3).
  const IdealGas eos(noh);
  const double u = 1.0, rho = 4.0 * noh.density, shock = u * rho / (rho - noh.density);
  EXPECT_NEAR(eos.evaluate(rho, 0.5 * u * u).pressure, noh.density * shock * u, 1e-15);
  EXPECT_NEAR(eos.evaluate(rho, 0.5 * u * u).pressure, 4.0 / 3.0, 1e-15);
}

TEST(EosIdealGas, CheckNamesTheBadParameter) {
  IdealGasParameters p = noh;
  p.gamma = 1.0;
  EXPECT_EQ(message(p), "eos.gamma must be greater than 1 (got 1)");
  p.gamma = 0.5;
  EXPECT_EQ(message(p), "eos.gamma must be greater than 1 (got 0.5)");
  p.gamma = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message(p), "eos.gamma must be greater than 1 (got inf)");
  p.gamma = std::nan("");
  EXPECT_EQ(message(p), "eos.gamma must be greater than 1 (got nan)");
  p = noh;
  p.density = 0.0;
  EXPECT_EQ(message(p), "eos.density must be positive (got 0)");
  p.density = -1.0;
  EXPECT_EQ(message(p), "eos.density must be positive (got -1)");
  EXPECT_EQ(message(noh), "no error");
}

TEST(EosIdealGas, RefusesAnInvalidState) {
  const IdealGas eos(noh);
  EXPECT_THROW(eos.evaluate(0.0, 1.0), NumericalError);
  EXPECT_THROW(eos.evaluate(-1.0, 1.0), NumericalError);
  EXPECT_THROW(eos.evaluate(std::nan(""), 1.0), NumericalError);
  EXPECT_THROW(eos.evaluate(std::numeric_limits<double>::infinity(), 1.0), NumericalError);
  EXPECT_THROW(eos.evaluate(1.0, std::nan("")), NumericalError);
  EXPECT_THROW(eos.evaluate(1.0, std::numeric_limits<double>::infinity()), NumericalError);
}

TEST(EosIdealGas, IsTheLastModelOfTheVariantAndNamedAsInDecks) {
  const Eos eos = IdealGas(noh);
  EXPECT_EQ(eos.index(), std::variant_size_v<Eos> - 1);
  EXPECT_STREQ(modelName(eos), "ideal-gas");
  EXPECT_EQ(referenceDensity(eos), 1.0);
}

}  // namespace
}  // namespace kessler::eos
