// Flow-stress laws against independent evaluations of the published formulas (docs/strength.md),
// their slopes against central differences, melting, and the parameter checks.
#include "core/error.hpp"
#include "material/strength/yield.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kessler::strength {
namespace {

// Liao et al. 2022, Table 2: Al 6061-T6.
PowerLawParameters aluminium6061() {
  PowerLawParameters p;
  p.sigma0 = 270e6;
  p.eps0 = 0.0025;
  p.rate0 = 1.0;
  p.n = 0.148;
  p.m = 0.01389;
  p.l = 1.0;
  p.melt_temperature = 1200.0;
  return p;
}

// Liao et al. 2022, Table 2: OFHC copper, with its m = 1 rate term.
PowerLawParameters copperPowerLaw() {
  PowerLawParameters p;
  p.sigma0 = 120e6;
  p.eps0 = 0.0278;
  p.rate0 = 1.0;
  p.n = 0.45;
  p.m = 1.0;
  p.l = 1.0;
  p.melt_temperature = 1790.0;
  return p;
}

// Johnson & Cook 1983: OFHC copper and 4340 steel.
JohnsonCookParameters copperJc() {
  return {.A = 90e6,
          .B = 292e6,
          .n = 0.31,
          .C = 0.025,
          .m = 1.09,
          .rate0 = 1.0,
          .room_temperature = 293.0,
          .melt_temperature = 1356.0};
}
JohnsonCookParameters steelJc() {
  return {.A = 792e6,
          .B = 510e6,
          .n = 0.26,
          .C = 0.014,
          .m = 1.03,
          .rate0 = 1.0,
          .room_temperature = 293.0,
          .melt_temperature = 1793.0};
}

struct State {
  double eps_p, rate, T;
};
const State states[] = {{0.0, 0.0, 293.0}, {0.01, 1e-3, 293.0}, {0.1, 1e3, 400.0},
                        {0.5, 1e5, 800.0}, {1.3, 3e6, 1100.0},  {0.2, 5.0, 150.0}};

TEST(StrengthYield, PowerLawAluminiumMatchesFormula) {
  const PowerLaw law(aluminium6061());
  for (const State& s : states) {
    const double theta = s.T <= 293.0 ? 1.0 : 1.0 - (s.T - 293.0) / (1200.0 - 293.0);
    const double expected = 270e6 * std::pow(1.0 + s.eps_p / 0.0025, 0.148) * (1.0 + std::pow(s.rate, 0.01389)) * theta;
    EXPECT_NEAR(law.flowStress(s.eps_p, s.rate, s.T, 1200.0), expected, 1e-13 * expected) << s.eps_p << " " << s.T;
  }
}

TEST(StrengthYield, JohnsonCookMatchesFormula) {
  for (const JohnsonCookParameters& p : {copperJc(), steelJc()}) {
    const JohnsonCook law(p);
    for (const State& s : states) {
      const double t_star = s.T <= 293.0 ? 0.0 : (s.T - 293.0) / (p.melt_temperature - 293.0);
      const double rate_term = s.rate > 1.0 ? 1.0 + p.C * std::log(s.rate) : 1.0;
      const double expected = (p.A + p.B * std::pow(s.eps_p, p.n)) * rate_term * (1.0 - std::pow(t_star, p.m));
      EXPECT_NEAR(law.flowStress(s.eps_p, s.rate, s.T, p.melt_temperature), expected, 1e-13 * expected);
    }
  }
}

TEST(StrengthYield, LinearHardeningAndNoStrength) {
  const LinearHardening law({.sigma0 = 300e6, .H = 1e9, .melt_temperature = 1e300});
  EXPECT_DOUBLE_EQ(law.flowStress(0.2, 1e5, 900.0, 1e300), 500e6);
  EXPECT_DOUBLE_EQ(law.hardening(0.2, 1e5, 900.0, 1e300, 1e-7), 1e9);
  EXPECT_EQ(NoStrength{}.flowStress(0.3, 1e4, 300.0, 1e300), 0.0);
}

TEST(StrengthYield, PowerLawRateCapLimitsCopper) {
  PowerLawParameters p = copperPowerLaw();
  const PowerLaw uncapped(p);
  p.rate_factor_cap = 3.0;
  const PowerLaw capped(p);
  // At 1e6 /s the published set multiplies sigma_y by 1e6 + 1 (Liao et al. 2022, Table 2, taken
  // literally; docs/strength.md).
  EXPECT_NEAR(uncapped.flowStress(0.0, 1e6, 293.0, 1790.0), 120e6 * (1.0 + 1e6), 1.0);
  EXPECT_DOUBLE_EQ(capped.flowStress(0.0, 1e6, 293.0, 1790.0), 3.0 * 120e6);
  EXPECT_DOUBLE_EQ(capped.flowStress(0.0, 0.5, 293.0, 1790.0), 1.5 * 120e6);  // below the cap
  EXPECT_EQ(capped.hardening(0.0, 1e6, 293.0, 1790.0, 1e-6),
            capped.hardening(0.0, 1e6, 293.0, 1790.0, 0.0));  // capped: no rate slope
}

TEST(StrengthYield, PowerLawSubUnitExponentAtZeroStrain) {
  const PowerLaw law(aluminium6061());
  EXPECT_DOUBLE_EQ(law.flowStress(0.0, 0.0, 293.0, 1200.0), 270e6);
  const double slope = law.hardening(0.0, 0.0, 293.0, 1200.0, 0.0);
  EXPECT_NEAR(slope, 270e6 * 0.148 / 0.0025, 1e-6 * slope);
  // The rate slope at rate 0 (m < 1) is floored: large, finite.
  EXPECT_TRUE(std::isfinite(law.hardening(0.0, 0.0, 293.0, 1200.0, 1e-7)));
  const JohnsonCook jc(copperJc());
  EXPECT_TRUE(std::isfinite(jc.hardening(0.0, 0.0, 293.0, 1356.0, 1e-7)));
  EXPECT_GT(jc.hardening(0.0, 0.0, 293.0, 1356.0, 1e-7), 0.0);
}

// d sigma_y / d(delta eps_p) with eps_p = eps_n + delta and rate = delta/dt, by central differences.
template <typename Law>
void checkSlope(const Law& law, double eps_n, double delta, double dt, double T, double T_melt) {
  const auto sigma = [&](double d) { return law.flowStress(eps_n + d, dt > 0.0 ? d / dt : 0.0, T, T_melt); };
  const double h = 1e-5 * delta;
  const double fd = (sigma(delta + h) - sigma(delta - h)) / (2.0 * h);
  const double slope = law.hardening(eps_n + delta, dt > 0.0 ? delta / dt : 0.0, T, T_melt, dt);
  EXPECT_NEAR(slope, fd, 1e-6 * std::abs(fd)) << "eps_n " << eps_n << " delta " << delta << " dt " << dt;
}

TEST(StrengthYield, HardeningMatchesFiniteDifferences) {
  const PowerLaw al(aluminium6061());
  PowerLawParameters capped_copper = copperPowerLaw();
  capped_copper.rate_factor_cap = 5.0;
  const PowerLaw cu_pl(capped_copper);
  const JohnsonCook cu(copperJc()), steel(steelJc());
  for (double dt : {0.0, 1e-7, 1e-3}) {
    for (double eps_n : {0.0, 0.05, 0.8}) {
      for (double delta : {2e-4, 3e-3}) {
        checkSlope(al, eps_n, delta, dt, 500.0, 1200.0);
        checkSlope(cu, eps_n, delta, dt, 700.0, 1356.0);
        checkSlope(steel, eps_n, delta, dt, 293.0, 1793.0);
      }
    }
  }
  // Copper power law below its cap (rate 2 /s) and far above it (rate 3e4 /s).
  checkSlope(cu_pl, 0.1, 2e-3, 1e-3, 400.0, 1790.0);
  checkSlope(cu_pl, 0.1, 3e-3, 1e-7, 400.0, 1790.0);
}

TEST(StrengthYield, MeltingGivesZeroStrength) {
  const PowerLaw al(aluminium6061());
  const JohnsonCook cu(copperJc());
  const LinearHardening lin({.sigma0 = 300e6, .H = 1e9, .melt_temperature = 1000.0});
  for (double T : {1200.0, 1500.0}) {
    EXPECT_EQ(al.flowStress(0.3, 1e4, T, 1200.0), 0.0);
    EXPECT_EQ(al.hardening(0.3, 1e4, T, 1200.0, 1e-7), 0.0);
  }
  EXPECT_EQ(cu.flowStress(0.3, 1e4, 1356.0, 1356.0), 0.0);
  EXPECT_EQ(cu.hardening(0.3, 1e4, 1400.0, 1356.0, 1e-7), 0.0);
  EXPECT_EQ(lin.flowStress(0.3, 0.0, 1000.0, lin.meltingTemperature(1.0)), 0.0);
  // Just below melting the strength is small and positive (continuous softening).
  EXPECT_GT(al.flowStress(0.3, 1e4, 1199.0, 1200.0), 0.0);
  EXPECT_LT(al.flowStress(0.3, 1e4, 1199.0, 1200.0), 0.01 * al.flowStress(0.3, 1e4, 293.0, 1200.0));
}

TEST(StrengthYield, CompressionRaisesMeltingPoint) {
  // Fan et al. 2019, LY12: Tm0 = 925 K, a = 1.5, Gamma0 = 1.97.
  PowerLawParameters p;
  p.sigma0 = 276e6;
  p.eps0 = 5e-4;
  p.rate0 = 1000.0;
  p.n = 0.075;
  p.m = 0.08;
  p.l = 0.5;
  p.melt_temperature = 925.0;
  p.melt_a = 1.5;
  p.melt_gamma0 = 1.97;
  const PowerLaw law(p);
  EXPECT_DOUBLE_EQ(law.meltingTemperature(1.0), 925.0);
  for (double J : {0.6, 0.8, 0.95, 1.1}) {
    const double expected = 925.0 * std::exp(3.0 * (1.0 - J)) * std::pow(J, 2.0 * (1.0 / 3.0 + 1.5 - 1.97));
    EXPECT_NEAR(law.meltingTemperature(J), expected, 1e-12 * expected);
  }
  EXPECT_GT(law.meltingTemperature(0.8), 925.0);
  EXPECT_DOUBLE_EQ(PowerLaw(aluminium6061()).meltingTemperature(0.7), 1200.0);
}

template <typename Parameters>
void expectRejected(const Parameters& p, const std::string& name) {
  try {
    p.check();
    ADD_FAILURE() << "accepted bad " << name;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

TEST(StrengthYield, ChecksNameTheParameter) {
  EXPECT_NO_THROW(aluminium6061().check());
  PowerLawParameters p = aluminium6061();
  p.sigma0 = -1e6;
  expectRejected(p, "strength.sigma0");
  p = aluminium6061();
  p.eps0 = 0.0;
  expectRejected(p, "strength.eps0");
  p = aluminium6061();
  p.n = -0.1;
  expectRejected(p, "strength.n");
  p = aluminium6061();
  p.melt_temperature = 200.0;
  expectRejected(p, "strength.melt_temperature");
  p = aluminium6061();
  p.rate_factor_cap = 0.5;
  expectRejected(p, "strength.rate_factor_cap");
  p = aluminium6061();
  p.m = std::nan("");
  expectRejected(p, "strength.m");

  JohnsonCookParameters j = copperJc();
  j.B = -1.0;
  expectRejected(j, "strength.B");
  j = copperJc();
  j.m = 0.0;
  expectRejected(j, "strength.m");
  j = copperJc();
  j.C = -0.01;
  expectRejected(j, "strength.C");
  expectRejected(LinearHardeningParameters{.sigma0 = 0.0, .H = 1e9, .melt_temperature = 1e300}, "strength.sigma0");
  expectRejected(LinearHardeningParameters{.sigma0 = 1e8, .H = -1.0, .melt_temperature = 1e300}, "strength.H");
  EXPECT_THROW(PowerLaw{PowerLawParameters{}}, InputError);  // constructors check too
}

TEST(StrengthYield, ModelNames) {
  EXPECT_STREQ(modelName(Yield{NoStrength{}}), "none");
  EXPECT_STREQ(modelName(Yield{PowerLaw(aluminium6061())}), "power-law");
  EXPECT_STREQ(modelName(Yield{JohnsonCook(steelJc())}), "johnson-cook");
  EXPECT_STREQ(modelName(Yield{LinearHardening({.sigma0 = 1e8, .H = 0.0, .melt_temperature = 1e300})}),
               "linear-hardening");
}

}  // namespace
}  // namespace kessler::strength
