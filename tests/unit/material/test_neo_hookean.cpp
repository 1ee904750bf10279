#include "core/error.hpp"
#include "material/neo_hookean.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace kessler {
namespace {

// Oracle: the Cauchy stress is the push-forward of the derivative of the stored energy,
// sigma = (1/J) dW/dF F^T, evaluated here by central differences of W.
TEST(NeoHookean, StressIsDerivativeOfEnergy) {
  const NeoHookean law("test", NeoHookeanParameters{.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33});
  Mat3 F;
  F << 1.05, 0.02, -0.01, 0.03, 0.97, 0.04, -0.02, 0.01, 1.10;
  const double step = 1e-7;
  Mat3 P;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3 plus = F, minus = F;
      plus(i, j) += step;
      minus(i, j) -= step;
      P(i, j) = (law.energyDensity(plus) - law.energyDensity(minus)) / (2 * step);
    }
  const Mat3 sigma = P * F.transpose() / F.determinant();
  EXPECT_LT((sigma - law.stress(F)).cwiseAbs().maxCoeff() / law.stress(F).cwiseAbs().maxCoeff(), 1e-6);
}

// Small strain: the law reduces to Hooke's law with the Lame constants of E and nu.
TEST(NeoHookean, LinearisesToHooke) {
  const NeoHookeanParameters p{.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33};
  const NeoHookean law("test", p);
  const double eps = 1e-7;
  Mat3 F = Mat3::Identity();
  F(0, 0) += eps;
  const Mat3 sigma = law.stress(F);
  EXPECT_NEAR(sigma(0, 0), (p.lameLambda() + 2 * p.shearModulus()) * eps, 1e-5 * p.youngs_modulus * eps);
  EXPECT_NEAR(sigma(1, 1), p.lameLambda() * eps, 1e-5 * p.youngs_modulus * eps);
  EXPECT_NEAR(law.referenceSoundSpeed(), std::sqrt((p.bulkModulus() + 4 * p.shearModulus() / 3) / p.density), 1e-9);
}

TEST(NeoHookean, RejectsUnphysicalParameters) {
  EXPECT_THROW(NeoHookeanParameters({.density = -1.0, .youngs_modulus = 1e9, .poisson_ratio = 0.3}).check(), InputError);
  EXPECT_THROW(NeoHookeanParameters({.density = 1.0, .youngs_modulus = 0.0, .poisson_ratio = 0.3}).check(), InputError);
  EXPECT_THROW(NeoHookeanParameters({.density = 1.0, .youngs_modulus = 1e9, .poisson_ratio = 0.5}).check(), InputError);
}

}  // namespace
}  // namespace kessler
