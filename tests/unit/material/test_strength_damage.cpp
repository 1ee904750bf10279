// Johnson-Cook damage (Johnson & Cook 1985) against an independent evaluation of eq. 2 with the
// paper's OFHC copper and 4340 steel constants (docs/materials.md), accumulation to failure, the
// floors and the parameter checks.
#include "core/error.hpp"
#include "material/strength/damage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kessler::strength {
namespace {

JohnsonCookDamageParameters copper() {
  return {.D1 = 0.54,
          .D2 = 4.89,
          .D3 = -3.03,
          .D4 = 0.014,
          .D5 = 1.12,
          .rate0 = 1.0,
          .room_temperature = 293.0,
          .melt_temperature = 1356.0,
          .min_failure_strain = 0.0};
}
JohnsonCookDamageParameters steel() {
  return {.D1 = 0.05,
          .D2 = 3.44,
          .D3 = -2.12,
          .D4 = 0.002,
          .D5 = 0.61,
          .rate0 = 1.0,
          .room_temperature = 293.0,
          .melt_temperature = 1793.0,
          .min_failure_strain = 0.0};
}

double independentFailureStrain(const JohnsonCookDamageParameters& p, double triaxiality, double rate, double T) {
  const double rate_term = rate > p.rate0 ? 1.0 + p.D4 * std::log(rate / p.rate0) : 1.0;
  double t_star = (T - p.room_temperature) / (p.melt_temperature - p.room_temperature);
  t_star = t_star < 0.0 ? 0.0 : (t_star > 1.0 ? 1.0 : t_star);
  return (p.D1 + p.D2 * std::exp(p.D3 * triaxiality)) * rate_term * (1.0 + p.D5 * t_star);
}

TEST(StrengthDamage, FailureStrainMatchesFormula) {
  for (const JohnsonCookDamageParameters& p : {copper(), steel()}) {
    const JohnsonCookDamage damage(p);
    for (double triaxiality : {-1.0 / 3.0, 0.0, 1.0 / 3.0, 0.7, 2.0}) {
      for (double rate : {0.0, 0.5, 1.0, 1e3, 1e6}) {
        for (double T : {200.0, 293.0, 700.0, 1300.0, 2500.0}) {
          const double expected = independentFailureStrain(p, triaxiality, rate, T);
          EXPECT_NEAR(damage.failureStrain(triaxiality, rate, T), expected, 1e-14 * expected)
              << triaxiality << " " << rate << " " << T;
        }
      }
    }
  }
  // A hand-checked value: 4340 steel, uniaxial tension (1/3), 1e3 /s, room temperature:
  // (0.05 + 3.44 e^(-0.706667)) (1 + 0.002 ln 1000) = 1.746903 * 1.013816 = 1.771037
  const double eps_f = JohnsonCookDamage(steel()).failureStrain(1.0 / 3.0, 1e3, 293.0);
  EXPECT_NEAR(eps_f, (0.05 + 3.44 * std::exp(-2.12 / 3.0)) * (1.0 + 0.002 * std::log(1e3)), 1e-14);
  EXPECT_NEAR(eps_f, 1.771037, 1e-6);
}

TEST(StrengthDamage, AccumulatesToFailureAtTheFailureStrain) {
  const JohnsonCookDamage damage(copper());
  const double triaxiality = 0.5, rate = 2e4, T = 500.0;
  const double eps_f = independentFailureStrain(copper(), triaxiality, rate, T);
  const double d_eps_p = 1e-4;
  double D = 0.0, eps_p = 0.0;
  while (D < 1.0) {
    D += damage.increment(d_eps_p, triaxiality, rate, T);
    eps_p += d_eps_p;
  }
  EXPECT_GE(eps_p, eps_f - 1e-9);
  EXPECT_LT(eps_p, eps_f + d_eps_p + 1e-9);
  EXPECT_EQ(damage.increment(0.0, triaxiality, rate, T), 0.0);
  EXPECT_EQ(damage.increment(-1e-3, triaxiality, rate, T), 0.0);
}

TEST(StrengthDamage, FailureStrainIsFloored) {
  // 6061-T6 (commonly cited set, not checked against a primary source; docs/materials.md): D1 = -0.77 makes
  // eps_f negative at high triaxiality.
  JohnsonCookDamageParameters p{.D1 = -0.77,
                                .D2 = 1.45,
                                .D3 = -0.47,
                                .D4 = 0.0,
                                .D5 = 1.6,
                                .rate0 = 1.0,
                                .room_temperature = 293.0,
                                .melt_temperature = 925.0,
                                .min_failure_strain = 0.0};
  const JohnsonCookDamage unfloored(p);
  EXPECT_GT(unfloored.failureStrain(2.0, 1.0, 293.0), 0.0);
  EXPECT_LT(unfloored.failureStrain(2.0, 1.0, 293.0), 1e-6);
  EXPECT_TRUE(std::isfinite(unfloored.increment(1e-3, 2.0, 1.0, 293.0)));
  p.min_failure_strain = 0.05;
  const JohnsonCookDamage floored(p);
  EXPECT_DOUBLE_EQ(floored.failureStrain(2.0, 1.0, 293.0), 0.05);
  EXPECT_DOUBLE_EQ(floored.failureStrain(-1.0 / 3.0, 1.0, 293.0), independentFailureStrain(p, -1.0 / 3.0, 1.0, 293.0));
  // A NaN triaxiality (sigma_eq = 0 upstream) fails the point rather than never failing it.
  EXPECT_DOUBLE_EQ(floored.failureStrain(std::nan(""), 1.0, 293.0), 0.05);
}

TEST(StrengthDamage, ChecksNameTheParameter) {
  EXPECT_NO_THROW(copper().check());
  const auto expectRejected = [](const JohnsonCookDamageParameters& p, const std::string& name) {
    try {
      p.check();
      ADD_FAILURE() << "accepted bad " << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  JohnsonCookDamageParameters p = copper();
  p.rate0 = 0.0;
  expectRejected(p, "failure.rate0");
  p = copper();
  p.melt_temperature = 100.0;
  expectRejected(p, "failure.melt_temperature");
  p = copper();
  p.min_failure_strain = -0.1;
  expectRejected(p, "failure.min_failure_strain");
  p = copper();
  p.D3 = std::nan("");
  expectRejected(p, "failure.D3");
  EXPECT_THROW(JohnsonCookDamage(JohnsonCookDamageParameters{}), InputError);
}

}  // namespace
}  // namespace kessler::strength
