// Mie-Gruneisen EOS against an independent evaluation written in eta = 1 - rho0/rho (Meyers
// 1994, §4: p_H = rho0 c0^2 eta / (1 - s eta)^2), the Al 6061-T6 Hugoniot point at up = 1 km/s
// (Steinberg 1996's constants; docs/eos.md), the compression limit and the parameter checks.
#include "core/error.hpp"
#include "material/eos/mie_gruneisen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kessler::eos {
namespace {

const MieGruneisenParameters al6061{.density = 2703.0, .sound_speed = 5240.0, .slope = 1.40, .gamma0 = 1.97};

struct Reference {
  double p, scale, dp_de, c2;
};

// Written from the textbook form, not from the production code's mu form.
Reference independent(const MieGruneisenParameters& m, double rho, double e) {
  const double rho0 = m.density, c0 = m.sound_speed, s = m.slope, g0 = m.gamma0;
  const double eta = 1.0 - rho0 / rho;  // = 1 - V/V0
  const double deta_drho = rho0 / (rho * rho);
  double ph = 0.0, eh = 0.0, dph = 0.0, deh = 0.0;  // derivatives in eta
  if (eta > 0.0) {
    ph = rho0 * c0 * c0 * eta / ((1.0 - s * eta) * (1.0 - s * eta));
    dph = rho0 * c0 * c0 * (1.0 + s * eta) / std::pow(1.0 - s * eta, 3);
    eh = 0.5 * ph * eta / rho0;  // e_H = p_H (V0 - V) / 2
    deh = 0.5 * (dph * eta + ph) / rho0;
  } else {
    ph = rho0 * c0 * c0 * (rho / rho0 - 1.0);
    dph = rho0 * c0 * c0 / (rho0 * deta_drho);  // d(rho0 c0^2 mu)/d eta
  }
  Reference r;
  r.dp_de = g0 * rho0;
  r.p = ph + g0 * rho0 * (e - eh);
  r.scale = std::abs(ph) + g0 * rho0 * (std::abs(e) + std::abs(eh));
  r.c2 = (dph - g0 * rho0 * deh) * deta_drho + r.p * g0 * rho0 / (rho * rho);
  return r;
}

TEST(EosMieGruneisen, MatchesIndependentFormulaOverWideSweep) {
  const MieGruneisen eos(al6061);
  const double rho0 = al6061.density, limit = al6061.slope / (al6061.slope - 1.0);
  double worst_p = 0.0, worst_c2 = 0.0;
  for (int i = 0; i <= 80; ++i) {
    const double rho = rho0 * 0.5 * std::pow(0.98 * limit / 0.5, i / 80.0);
    for (int k = -1; k <= 70; ++k) {
      const double e = k < 0 ? 0.0 : std::pow(10.0, k / 10.0);  // 0 and 1 J/kg ... 10 MJ/kg
      const State s = eos.evaluate(rho, e);
      const Reference r = independent(al6061, rho, e);
      worst_p = std::max(worst_p, std::abs(s.pressure - r.p) / r.scale);
      EXPECT_EQ(s.dp_de, r.dp_de);
      const double floor = sound_speed2_floor_fraction * rho0 * 5240.0 * 5240.0 / rho;
      worst_c2 = std::max(worst_c2, std::abs(s.sound_speed2 - std::max(r.c2, floor)) / std::max(std::abs(r.c2), floor));
    }
  }
  EXPECT_LT(worst_p, 1e-13);
  EXPECT_LT(worst_c2, 1e-12);
}

TEST(EosMieGruneisen, HugoniotPointOfAl6061At1KmPerSecond) {
  const MieGruneisen eos(al6061);
  const double up = 1000.0, us = al6061.sound_speed + al6061.slope * up;
  const double rho = al6061.density * us / (us - up);
  const double p = eos.evaluate(rho, 0.5 * up * up).pressure;
  EXPECT_NEAR(p / (al6061.density * us * up), 1.0, 1e-10);
  EXPECT_NEAR(p, 17.9e9, 0.05e9);  // rho0 Us up = 17.95 GPa (docs/eos.md)
}

TEST(EosMieGruneisen, SmoothThroughTheReferenceDensity) {
  const MieGruneisen eos(al6061);
  for (double e : {0.0, 1e5, 1e6}) {
    const State below = eos.evaluate(al6061.density * (1.0 - 1e-9), e);
    const State above = eos.evaluate(al6061.density * (1.0 + 1e-9), e);
    EXPECT_NEAR(below.pressure, above.pressure, 1e-7 * al6061.density * 5240.0 * 5240.0);
    EXPECT_NEAR(below.sound_speed2 / above.sound_speed2, 1.0, 1e-7);
  }
}

TEST(EosMieGruneisen, RefusesCompressionAtTheHugoniotLimit) {
  const MieGruneisen eos(al6061);
  const double limit = al6061.density * al6061.slope / (al6061.slope - 1.0);  // mu_max = 1/(s-1)
  EXPECT_NO_THROW(eos.evaluate(0.999 * limit, 1e5));
  for (double rho : {limit, 1.2 * limit}) {
    try {
      eos.evaluate(rho, 1e5);
      ADD_FAILURE() << "no error at rho = " << rho;
    } catch (const NumericalError& e) {
      EXPECT_NE(std::string(e.what()).find("limit"), std::string::npos) << e.what();
    }
  }
  // s <= 1 has no limit.
  const MieGruneisen soft({.density = 1000.0, .sound_speed = 1500.0, .slope = 0.9, .gamma0 = 1.0});
  EXPECT_TRUE(std::isfinite(soft.evaluate(20000.0, 1e5).pressure));
}

TEST(EosMieGruneisen, SoundSpeedIsFlooredInDeepTension) {
  const MieGruneisen eos(al6061);
  const double rho = 0.3 * al6061.density;
  const State s = eos.evaluate(rho, 0.0);
  EXPECT_LT(independent(al6061, rho, 0.0).c2, 0.0);
  EXPECT_DOUBLE_EQ(s.sound_speed2, sound_speed2_floor_fraction * al6061.density * 5240.0 * 5240.0 / rho);
}

TEST(EosMieGruneisen, CheckNamesTheBadParameter) {
  auto message = [](MieGruneisenParameters p) {
    try {
      MieGruneisen eos(p);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  MieGruneisenParameters p = al6061;
  p.sound_speed = -5240.0;
  EXPECT_EQ(message(p), "eos.sound_speed must be positive (got -5240)");
  p = al6061;
  p.density = 0.0;
  EXPECT_EQ(message(p), "eos.density must be positive (got 0)");
  p = al6061;
  p.gamma0 = std::nan("");
  EXPECT_NE(message(p).find("eos.gamma0"), std::string::npos);
  EXPECT_THROW(MieGruneisen(al6061).evaluate(-1.0, 0.0), NumericalError);
}

}  // namespace
}  // namespace kessler::eos
