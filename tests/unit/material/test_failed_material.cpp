// Failed material (PointStore::failed, docs/theory.md §8) in ImpactMaterial::update: once a
// point has failed it has no deviator and bears the pressure of its equation of state while it is
// denser than its reference, none once it has expanded; its internal energy takes the p dV work
// of that pressure. A point whose Johnson-Cook damage reaches 1 fails (stays in its body, bearing
// compression) instead of leaving it, and so does one whose pressure falls to minus its spall
// strength. Checked against the EOS evaluated independently.
#include "material/impact_material.hpp"
#include "material/library.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace kessler {
namespace {

constexpr double volume0 = 1e-9;

// Al 6061-T6 from the library without artificial viscosity, so that the stress is the EOS
// pressure alone.
ImpactMaterialParameters aluminium() {
  ImpactMaterialParameters p = library::find("Al6061-T6").parameters;
  p.viscosity.linear = 0.0;
  p.viscosity.quadratic = 0.0;
  return p;
}

struct OnePoint {
  ImpactMaterial material;
  PointStore points;
  explicit OnePoint(ImpactMaterialParameters parameters = aluminium()) : material("al", std::move(parameters)) {
    points.resize(1);
    points.body[0] = 0;
    points.mass[0] = material.referenceDensity() * volume0;
    points.volume[0] = points.volume0[0] = volume0;
    points.spacing0[0] = 1e-3;
    material.initialise(points, 0, 1);
  }
  void step(const Mat3& dF, double dt = 1e-8) {
    points.dF[0] = dF;
    points.F[0] = dF * points.F[0];
    points.volume[0] *= dF.determinant();
    material.update(points, 0, 1, dt);
  }
  double eosPressure() const {
    const double rho = points.mass[0] / points.volume[0];
    return std::visit([&](const auto& eos) { return eos.evaluate(rho, points.energy[0]).pressure; },
                      material.parameters().eos);
  }
};

// Compression with shear: 12% volumetric strain over a few steps, plus a shear that an intact
// point answers with a large deviator.
Mat3 compressAndShear() {
  Mat3 dF = Mat3::Identity();
  dF(2, 2) = std::pow(0.88, 0.25);
  dF(0, 1) = 0.02;
  return dF;
}

TEST(FailedMaterial, BearsTheEosPressureInCompressionAndNoDeviator) {
  OnePoint intact, failed;
  failed.points.fail(0);
  for (int k = 0; k < 4; ++k) {
    intact.step(compressAndShear());
    failed.step(compressAndShear());
  }
  ASSERT_LT(failed.points.volume[0], volume0);
  const Mat3 s = failed.points.stress[0];
  const double p = -s.trace() / 3.0;
  EXPECT_GT(p, 1e9);  // ~10 GPa at 12% compression
  EXPECT_NEAR(p, failed.eosPressure(), 1e-12 * p);
  EXPECT_LT((s + p * Mat3::Identity()).norm(), 1e-12 * p) << "a failed point has no deviator";
  EXPECT_EQ(failed.points.plastic_strain[0], 0.0);
  // The intact point under the same motion carries a deviator of the order of its flow stress.
  const Mat3 si = intact.points.stress[0];
  EXPECT_GT((si - si.trace() / 3.0 * Mat3::Identity()).norm(), 1e8);
  // The shear sound speed is gone: only the bulk wave remains.
  EXPECT_LT(failed.points.sound_speed[0], intact.points.sound_speed[0]);
}

TEST(FailedMaterial, TakesThePdVWorkOfItsPressure) {
  OnePoint failed;
  failed.points.fail(0);
  double work = 0.0;  // -int p dV by the trapezoidal rule over the steps, per unit mass
  double p_old = 0.0, peak = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double v_old = failed.points.volume[0];
    Mat3 dF = Mat3::Identity();
    dF(2, 2) = k < 20 ? 0.995 : 1.0 / 0.995;  // compress by 10%, then back to the reference volume
    failed.step(dF);
    const double p_new = -failed.points.stress[0].trace() / 3.0;
    work -= 0.5 * (p_old + p_new) * (failed.points.volume[0] - v_old) / failed.points.mass[0];
    p_old = p_new;
    if (k == 19) {
      // The update's predictor-corrector and this trapezoidal sum (with the final pressure of
      // each step) differ at second order in the step: 2.5e-4 over these 20 steps.
      peak = failed.points.energy[0];
      EXPECT_NEAR(peak, work, 1e-3 * work) << "the compression work";
    }
  }
  // Back at the reference volume along the same adiabat (no viscosity, no strength): the work
  // comes back but for the trapezoidal rule's second-order error.
  EXPECT_GT(peak, 1e4);
  EXPECT_LT(std::abs(failed.points.energy[0]), 1e-3 * peak);
}

TEST(FailedMaterial, BearsNothingOnceExpanded) {
  OnePoint failed;
  failed.points.fail(0);
  failed.points.energy[0] = 2e6;  // hot: its EOS pressure at the reference density is positive
  Mat3 dF = Mat3::Identity();
  dF(2, 2) = 1.01;
  failed.step(dF);
  ASSERT_GT(failed.eosPressure(), 1e9);
  EXPECT_TRUE(failed.points.stress[0].isZero(0.0)) << failed.points.stress[0];
}

TEST(FailedMaterial, DamageFailsThePointInsteadOfReleasingIt) {
  OnePoint point;
  ASSERT_TRUE(point.material.parameters().damage.has_value());  // the library set, on here
  point.points.damage[0] = 1.0 - 1e-12;
  Mat3 dF = Mat3::Identity();
  dF(2, 2) = 0.97;
  dF(0, 1) = 0.05;
  point.step(dF);
  EXPECT_TRUE(point.points.failed(0));
  EXPECT_FALSE(point.points.debris(0));
  const double pressure = -point.points.stress[0].trace() / 3.0;
  EXPECT_GT(pressure, 0.0);
  EXPECT_LT((point.points.stress[0] + pressure * Mat3::Identity()).norm(), 1e-12 * pressure);
}

// Uniaxial stretch in small steps: the point stays intact while its EOS pressure is above minus the
// spall strength and fails in the step where it reaches it; from then on it bears no tension.
TEST(FailedMaterial, SpallFailsThePointAtItsSpallStrength) {
  ImpactMaterialParameters p = aluminium();
  p.damage.reset();  // as a deck has it: JC damage would fail the stretched point first
  OnePoint point(p);
  const double spall = point.material.parameters().spall_strength;
  ASSERT_GT(spall, 1e9);  // the library's 1.4 GPa
  Mat3 dF = Mat3::Identity();
  dF(2, 2) = 1.0005;  // about 37 MPa of tension a step
  int steps = 0;
  double last_intact = 0.0;
  while (!point.points.failed(0) && steps < 200) {
    point.step(dF);
    ++steps;
    if (!point.points.failed(0)) last_intact = point.eosPressure();
  }
  ASSERT_TRUE(point.points.failed(0)) << "no spall after " << steps << " steps";
  EXPECT_GT(last_intact, -spall);
  EXPECT_LE(point.eosPressure(), -spall);
  EXPECT_GT(point.eosPressure(), -spall - 0.1e9) << "failed in the step that crossed, not later";
  EXPECT_TRUE(point.points.stress[0].isZero(0.0)) << point.points.stress[0];
  point.step(dF);
  EXPECT_TRUE(point.points.stress[0].isZero(0.0)) << "a spalled point bears no tension";
}

TEST(FailedMaterial, NoSpallStrengthNoSpall) {
  ImpactMaterialParameters p = aluminium();
  p.damage.reset();
  p.spall_strength = 0.0;
  OnePoint point(p);
  Mat3 dF = Mat3::Identity();
  dF(2, 2) = 1.0005;
  for (int k = 0; k < 100; ++k) point.step(dF);
  EXPECT_LT(point.eosPressure(), -2e9);
  EXPECT_FALSE(point.points.failed(0));
}

}  // namespace
}  // namespace kessler
