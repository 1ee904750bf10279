// NASA standard breakup model against hand-computed values (Johnson et al. 2001).
#include "analysis/breakup_model.hpp"
#include "core/error.hpp"

#include <gtest/gtest.h>

namespace kessler::analysis {
namespace {

TEST(BreakupModel, CatastrophicCollision) {
  // 10 g at 10 km/s on 1 kg: E = 0.5 * 0.01 * 1e8 = 5e5 J over 1000 g = 500 J/g >= 40 J/g.
  const BreakupPrediction p = nasaBreakup({0.01, 1.0, 10e3});
  EXPECT_DOUBLE_EQ(p.specific_energy, 500.0);
  EXPECT_TRUE(p.catastrophic);
  EXPECT_DOUBLE_EQ(p.reference_mass, 1.01);
  // N(>1 cm) = 0.1 * 1.01^0.75 * 0.01^-1.71 = 0.1 * 1.0074907 * 2630.2680 = 264.997.
  EXPECT_NEAR(p.count(0.01), 264.997, 1e-3);
}

TEST(BreakupModel, NonCatastrophicCollision) {
  // 1 g at 5 km/s on 100 kg: 12500 J over 1e5 g = 0.125 J/g; M = 0.001 kg * (5 km/s)^2 = 0.025 kg.
  const BreakupPrediction p = nasaBreakup({0.001, 100.0, 5e3});
  EXPECT_DOUBLE_EQ(p.specific_energy, 0.125);
  EXPECT_FALSE(p.catastrophic);
  EXPECT_DOUBLE_EQ(p.reference_mass, 0.025);
  // N(>1 mm) = 0.1 * 0.025^0.75 * 0.001^-1.71 = 0.1 * 0.06287167 * 134896.29 = 848.116.
  EXPECT_NEAR(p.count(1e-3), 848.116, 1e-3);
  EXPECT_NEAR(p.lengthForCount(p.count(3e-3)), 3e-3, 1e-15);
}

TEST(BreakupModel, ThresholdIsCatastrophic) {
  // 40 J/g exactly: 0.5 * 0.008 kg * (1000 m/s)^2 = 4000 J over 100 g.
  EXPECT_TRUE(nasaBreakup({0.008, 0.1, 1000.0}).catastrophic);
  EXPECT_FALSE(nasaBreakup({0.0079, 0.1, 1000.0}).catastrophic);
}

TEST(BreakupModel, FragmentAreaBothBranchesAndContinuity) {
  EXPECT_DOUBLE_EQ(nasaFragmentArea(1e-3), 0.540424e-6);
  // 0.556945 * 0.01^2.0047077 = 0.556945e-4 * 10^-0.0094154 = 5.45001e-5 m^2.
  EXPECT_NEAR(nasaFragmentArea(0.01), 5.45001e-5, 1e-9);
  const double below = nasaFragmentArea(1.67e-3 * (1 - 1e-12));
  const double above = nasaFragmentArea(1.67e-3);
  EXPECT_NEAR(above / below, 1.0, 2e-5);
}

TEST(BreakupModel, RefusesNonPhysicalInput) {
  EXPECT_THROW(nasaBreakup({0.0, 1.0, 1e3}), InputError);
  EXPECT_THROW(nasaBreakup({1.0, -1.0, 1e3}), InputError);
  EXPECT_THROW(nasaBreakup({1.0, 1.0, -1.0}), InputError);
}

}  // namespace
}  // namespace kessler::analysis
