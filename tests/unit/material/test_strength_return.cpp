// The log-strain radial return (Simo 1992): exact elasticity below yield, objectivity, the
// consistency condition after a plastic step, plastic incompressibility, melting, and a robust
// scalar solve over hard cases (n < 1 at eps_p = 0, huge steps, tiny and huge rates).
#include "material/strength/radial_return.hpp"

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <cstdio>

namespace kessler::strength {
namespace {

constexpr double G = 26e9;  // Pa, aluminium-like

Mat3 dev(const Mat3& a) {
  return a - a.trace() / 3.0 * Mat3::Identity();
}
double equivalent(const Mat3& s) {
  return std::sqrt(1.5) * s.norm();
}

Mat3 rotation(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A general deformation increment: stretch and shear, then a rotation.
Mat3 generalIncrement(double size) {
  Mat3 U;
  U << 1.0 + 0.8 * size, 0.3 * size, -0.2 * size,  //
      0.3 * size, 1.0 - 0.5 * size, 0.6 * size,    //
      -0.2 * size, 0.6 * size, 1.0 - 0.1 * size;
  return rotation(0.3, Vec3(1.0, 2.0, -0.5)) * U;
}

ReturnInput input(const Mat3& dF, double dt, double T = 293.0, double T_melt = 1e300) {
  ReturnInput in;
  in.dF = dF;
  in.dt = dt;
  in.shear_modulus = G;
  in.temperature = T;
  in.melt_temperature = T_melt;
  return in;
}

// Counts the law's evaluations, to report the cost of the scalar solve.
template <typename Law>
struct Counting {
  const Law& law;
  mutable int flow_calls = 0;
  mutable int slope_calls = 0;
  double flowStress(double e, double r, double T, double Tm) const {
    ++flow_calls;
    return law.flowStress(e, r, T, Tm);
  }
  double hardening(double e, double r, double T, double Tm, double dt) const {
    ++slope_calls;
    return law.hardening(e, r, T, Tm, dt);
  }
  double meltingTemperature(double J) const { return law.meltingTemperature(J); }
};

PowerLaw aluminium() {
  PowerLawParameters p;
  p.sigma0 = 270e6;
  p.eps0 = 0.0025;
  p.n = 0.148;
  p.m = 0.01389;
  p.melt_temperature = 1200.0;
  return PowerLaw(p);
}
PowerLaw copperUncapped() {
  PowerLawParameters p;
  p.sigma0 = 120e6;
  p.eps0 = 0.0278;
  p.n = 0.45;
  p.m = 1.0;
  p.melt_temperature = 1790.0;
  return PowerLaw(p);
}
JohnsonCook copper() {
  return JohnsonCook({.A = 90e6,
                      .B = 292e6,
                      .n = 0.31,
                      .C = 0.025,
                      .m = 1.09,
                      .rate0 = 1.0,
                      .room_temperature = 293.0,
                      .melt_temperature = 1356.0});
}
JohnsonCook steel() {
  return JohnsonCook({.A = 792e6,
                      .B = 510e6,
                      .n = 0.26,
                      .C = 0.014,
                      .m = 1.03,
                      .rate0 = 1.0,
                      .room_temperature = 293.0,
                      .melt_temperature = 1793.0});
}
LinearHardening linear() {
  return LinearHardening({.sigma0 = 300e6, .H = 2e9, .melt_temperature = 1e300});
}

TEST(StrengthReturn, ElasticStepIsExactlyElastic) {
  const Mat3 be0 = Mat3::Identity();
  for (const Mat3& dF : {Mat3(Vec3(1.0, 1.0, 1.0 + 1e-4).asDiagonal()), generalIncrement(2e-4)}) {
    Mat3 be = be0;
    double eps_p = 0.0;
    const ReturnResult r = radialReturnWith(linear(), input(dF, 1e-7), be, eps_p);
    // Independent: matrix logarithm of b_e = dF dF^T (Eigen's MatrixFunctions), s = 2G dev eps / J.
    const Mat3 b = dF * dF.transpose();
    const Mat3 eps = 0.5 * b.log();
    const Mat3 expected = 2.0 * G * dev(eps) / dF.determinant();
    // The strain is ~1e-4, so the round-off of log(b) near I (~1e-16 absolute) is ~1e-12 of it:
    // measured 1.25e-12 with fused multiply-adds (x86-64-v3, -O2). A wrong return is off by O(1).
    EXPECT_LT((r.deviatoric_stress - expected).norm(), 1e-10 * expected.norm());
    EXPECT_EQ(r.plastic_increment, 0.0);
    EXPECT_EQ(r.plastic_work, 0.0);
    EXPECT_EQ(eps_p, 0.0);
    EXPECT_LT((be - b).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(r.flow_stress, 300e6);
  }
}

// Rotating a stressed point by 90 degrees in 10 increments dF = R without stretch: the stress
// turns with the body, s_k = R_k s_0 R_k^T, and its invariants do not change.
template <typename Law>
void checkRotation(const Law& law, const Mat3& load) {
  Mat3 be = Mat3::Identity();
  double eps_p = 0.0;
  const ReturnResult r0 = radialReturnWith(law, input(load, 0.0), be, eps_p);
  const Mat3 s0 = r0.deviatoric_stress;
  const double eps_p0 = eps_p;
  const double scale = s0.norm();
  ASSERT_GT(scale, 1e6);
  const Vec3 axis(0.2, -1.0, 0.7);
  const Mat3 step = rotation(M_PI / 20.0, axis);
  for (int k = 1; k <= 10; ++k) {
    const ReturnResult r = radialReturnWith(law, input(step, 0.0), be, eps_p);
    const Mat3 Rk = rotation(k * M_PI / 20.0, axis);
    const Mat3& s = r.deviatoric_stress;
    EXPECT_LT((s - Rk * s0 * Rk.transpose()).norm(), 1e-12 * scale) << "step " << k;
    EXPECT_NEAR(s.norm(), scale, 1e-12 * scale);
    EXPECT_NEAR(s.determinant(), s0.determinant(), 1e-12 * std::pow(scale, 3));
    EXPECT_NEAR(s.trace(), 0.0, 1e-12 * scale);
    EXPECT_NEAR(eps_p, eps_p0, 1e-12);
  }
}

TEST(StrengthReturn, ObjectiveUnderPureRotation) {
  checkRotation(linear(), generalIncrement(1e-3));  // elastic prestress
  checkRotation(steel(), generalIncrement(3e-2));   // on the yield surface after a plastic step
}

// One large plastic step from a given state: the returned Kirchhoff stress lies on the yield
// surface, the deviator keeps the trial direction, and det b_e is untouched.
template <typename Law>
void checkPlasticStep(const Law& law, const Mat3& be0, double eps_p0, const Mat3& dF, double dt, double T,
                      double T_melt, const char* label) {
  const Counting<Law> counted{law};
  Mat3 be = be0;
  double eps_p = eps_p0;
  const Mat3 be_trial = dF * be0 * dF.transpose();
  const ReturnResult r = radialReturnWith(counted, input(dF, dt, T, T_melt), be, eps_p);
  ASSERT_GT(r.plastic_increment, 0.0) << label;
  ASSERT_TRUE(std::isfinite(r.plastic_increment) && r.deviatoric_stress.allFinite()) << label;
  const double J = std::sqrt(be_trial.determinant());
  const double rate = dt > 0.0 ? r.plastic_increment / dt : 0.0;
  const double sigma_y = law.flowStress(eps_p, rate, T, T_melt);
  EXPECT_NEAR(equivalent(r.deviatoric_stress * J), sigma_y, 1e-10 * sigma_y) << label;
  EXPECT_NEAR(r.flow_stress, sigma_y, 1e-10 * sigma_y) << label;
  EXPECT_DOUBLE_EQ(eps_p, eps_p0 + r.plastic_increment) << label;
  EXPECT_NEAR(be.determinant(), be_trial.determinant(), 1e-13 * be_trial.determinant()) << label;
  EXPECT_NEAR(r.plastic_work, sigma_y * r.plastic_increment / J, 1e-10 * r.plastic_work) << label;
  // Radial: s is parallel to the trial deviator 2G dev(1/2 ln b_e^trial).
  const Mat3 trial = dev(be_trial.log());
  const double cosine = r.deviatoric_stress.cwiseProduct(trial).sum() / (r.deviatoric_stress.norm() * trial.norm());
  EXPECT_NEAR(cosine, 1.0, 1e-12) << label;
  std::printf("[ newton   ] %-34s d_eps_p %.3e  slope evaluations %d, flow-stress evaluations %d\n", label,
              r.plastic_increment, counted.slope_calls, counted.flow_calls);
  EXPECT_LE(counted.slope_calls, 30) << label;
}

TEST(StrengthReturn, PlasticStepIsConsistentAndIsochoric) {
  const Mat3 I = Mat3::Identity();
  const Mat3 shear = generalIncrement(0.05);
  const Mat3 prestretched = generalIncrement(0.01) * generalIncrement(0.01).transpose();
  checkPlasticStep(linear(), I, 0.0, shear, 1e-7, 293.0, 1e300, "linear");
  checkPlasticStep(aluminium(), I, 0.0, shear, 1e-7, 293.0, 1200.0, "Al 6061 power law, 1e-7 s");
  checkPlasticStep(aluminium(), prestretched, 0.2, shear, 0.0, 700.0, 1200.0, "Al 6061 power law, dt 0");
  checkPlasticStep(copper(), I, 0.0, shear, 1e-7, 293.0, 1356.0, "Cu JC, eps_p 0, 1e-7 s");
  checkPlasticStep(copper(), prestretched, 0.5, shear, 1e-3, 900.0, 1356.0, "Cu JC, eps_p 0.5, 1e-3 s");
  checkPlasticStep(steel(), I, 0.0, shear, 1e-8, 293.0, 1793.0, "4340 JC, eps_p 0, 1e-8 s");
  checkPlasticStep(steel(), I, 1.0, shear, 0.0, 1500.0, 1793.0, "4340 JC, eps_p 1, dt 0");
}

TEST(StrengthReturn, ScalarSolveIsRobust) {
  const Mat3 I = Mat3::Identity();
  const Mat3 just_above = Mat3(Vec3(1.0, 1.0, 1.0 - 0.00525).asDiagonal());  // q_trial ~ 1.05 sigma0 (Cu)
  const Mat3 huge = generalIncrement(0.6);                                   // q_trial ~ 400 sigma_y
  checkPlasticStep(copper(), I, 0.0, Mat3(Vec3(1.0, 1.0, 1.0 - 0.0018).asDiagonal()), 1e-7, 293.0, 1356.0,
                   "Cu JC, barely plastic");
  checkPlasticStep(copper(), I, 0.0, huge, 1e-7, 293.0, 1356.0, "Cu JC, huge step");
  checkPlasticStep(aluminium(), I, 0.0, huge, 1e6, 293.0, 1200.0, "Al power law, rate ~1e-7 /s");
  checkPlasticStep(aluminium(), I, 0.0, just_above, 1e-9, 293.0, 1200.0, "Al power law, barely, 1e-9 s");
  checkPlasticStep(copperUncapped(), I, 0.0, huge, 1e-9, 293.0, 1790.0, "Cu power law m=1 uncapped");
  checkPlasticStep(steel(), I, 0.0, huge, 1e-12, 1792.9, 1793.0, "4340 JC, 0.1 K below melt");
}

TEST(StrengthReturn, NoStrengthWipesTheDeviator) {
  Mat3 be = Mat3::Identity();
  double eps_p = 0.0;
  const Mat3 dF = generalIncrement(0.1);
  const ReturnResult r = radialReturnWith(NoStrength{}, input(dF, 1e-7), be, eps_p);
  EXPECT_LT(r.deviatoric_stress.norm(), 1e-6);
  EXPECT_EQ(r.flow_stress, 0.0);
  EXPECT_NEAR(be.determinant(), std::pow(dF.determinant(), 2), 1e-13);
}

TEST(StrengthReturn, MeltedPointHasNoDeviatorAndRelaxes) {
  Mat3 be = generalIncrement(0.004) * generalIncrement(0.004).transpose();
  double eps_p = 0.3;
  const Mat3 dF = generalIncrement(0.05);
  const double J = std::sqrt((dF * be * dF.transpose()).determinant());
  const ReturnResult r = radialReturnWith(aluminium(), input(dF, 1e-7, 1250.0, 1200.0), be, eps_p);
  EXPECT_EQ(r.deviatoric_stress.norm(), 0.0);
  EXPECT_EQ(r.plastic_increment, 0.0);
  EXPECT_EQ(r.plastic_work, 0.0);
  EXPECT_EQ(r.flow_stress, 0.0);
  EXPECT_EQ(eps_p, 0.3);
  EXPECT_LT((be - std::pow(J, 2.0 / 3.0) * Mat3::Identity()).norm(), 1e-14);
  // Resolidified, the point starts from a stress-free state.
  const ReturnResult cold = radialReturnWith(aluminium(), input(Mat3::Identity(), 1e-7, 293.0, 1200.0), be, eps_p);
  EXPECT_LT(cold.deviatoric_stress.norm(), 1e-3);
}

TEST(StrengthReturn, VariantDispatchMatchesTemplate) {
  const Yield yield = steel();
  Mat3 be_a = Mat3::Identity(), be_b = Mat3::Identity();
  double eps_a = 0.1, eps_b = 0.1;
  const ReturnInput in = input(generalIncrement(0.03), 1e-6, 400.0, 1793.0);
  const ReturnResult a = radialReturn(yield, in, be_a, eps_a);
  const ReturnResult b = radialReturnWith(steel(), in, be_b, eps_b);
  EXPECT_EQ(a.deviatoric_stress, b.deviatoric_stress);
  EXPECT_EQ(eps_a, eps_b);
  EXPECT_EQ(be_a, be_b);
}

}  // namespace
}  // namespace kessler::strength
