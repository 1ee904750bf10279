// Failure diagnosis: each kind of numerical failure, forced on a small synthetic model, stops with a
// NumericalError naming the step, time, body, point (or node) id, position, quantity and value.
#include "core/error.hpp"
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/diagnostics.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>

namespace kessler::otm {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

class DiagnosticsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    NeoHookeanParameters p;
    p.density = 2700.0;
    p.youngs_modulus = 70e9;
    p.poisson_ratio = 0.33;
    const geometry::Discretisation disc = geometry::discretise(
        geometry::structuredBoxMesh(geometry::Box{Vec3(0, 0, 0), Vec3(3e-3, 2e-3, 2e-3)}, {3, 2, 2}));
    addBody(model_, "cube", std::make_shared<NeoHookean>("al", p), disc, Vec3(0, 0, -100.0));
    settings_.end_time = 1e-5;
    integrator_ = std::make_unique<Integrator>(model_, settings_);
    integrator_->initialise();
    integrator_->step();
    integrator_->step();
    integrator_->step();
    reference_ = integrator_->energies().total();
  }

  StepInfo at() const {
    return {integrator_->steps(), integrator_->time(), integrator_->nextStep(), integrator_->initialStep()};
  }

  // The message of the check, "" if it passes.
  std::string failure(const Settings& settings) {
    Diagnostics diagnostics(settings);
    try {
      diagnostics.check(model_, at(), reference_);
    } catch (const NumericalError& e) {
      return e.what();
    }
    return "";
  }
  std::string failure() { return failure(settings_); }

  std::string pointPrefix(LocalIndex p) const {
    const Vec3& x = model_.points.x[p];
    return fmt::format("step 3, t = {:.6g} s: material point {} of body 'cube' at ({:.6g}, {:.6g}, {:.6g}) m: ",
                       integrator_->time(), model_.points.id[p], x[0], x[1], x[2]);
  }

  Model model_;
  Settings settings_;
  std::unique_ptr<Integrator> integrator_;
  double reference_ = 0.0;
};

TEST_F(DiagnosticsTest, AHealthyModelPasses) {
  EXPECT_EQ(failure(), "");
  Diagnostics diagnostics(settings_);
  diagnostics.check(model_, at(), reference_);
  EXPECT_NEAR(diagnostics.lastEnergy(), integrator_->energies().total(), 1e-12 * reference_);
}

TEST_F(DiagnosticsTest, NamesANonFinitePointVelocity) {
  model_.points.v[7] = Vec3(0, nan, 0);
  const std::string m = failure();
  EXPECT_EQ(m.rfind(pointPrefix(7), 0), 0u) << m;
  EXPECT_NE(m.find("non-finite velocity v = (0, nan, 0) m/s"), std::string::npos) << m;
}

TEST_F(DiagnosticsTest, NamesTheLowestFailingPointForAnyThreadCount) {
  model_.points.stress[9](1, 1) = inf;
  model_.points.energy[4] = nan;
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    const std::string m = failure();
    EXPECT_EQ(m.rfind(pointPrefix(4), 0), 0u) << m;
    EXPECT_NE(m.find("non-finite specific internal energy e = nan J/kg"), std::string::npos) << m;
  }
  model_.points.energy[4] = 0.0;
  const std::string m = failure();
  EXPECT_EQ(m.rfind(pointPrefix(9), 0), 0u) << m;
  EXPECT_NE(m.find("non-finite stress (diagonal"), std::string::npos) << m;
}

TEST_F(DiagnosticsTest, NamesACollapsedVolume) {
  model_.points.volume[2] = 0.0;
  const std::string m = failure();
  EXPECT_EQ(m.rfind(pointPrefix(2), 0), 0u) << m;
  EXPECT_NE(m.find("volume collapsed or non-finite: V = 0 m^3"), std::string::npos) << m;
}

TEST_F(DiagnosticsTest, NamesANonFiniteNode) {
  model_.nodes.x[5] = Vec3(inf, 0, 0);
  const std::string m = failure();
  EXPECT_EQ(m.rfind(fmt::format("step 3, t = {:.6g} s: node {} of body 'cube' at (inf, 0, 0) m: non-finite position",
                                integrator_->time(), model_.nodes.id[5]),
                    0),
            0u)
      << m;
}

TEST_F(DiagnosticsTest, NamesThePointThatCollapsesTheTimeStep) {
  // The step falls below 1e-3 of the initial one because one point's sound speed exploded.
  model_.points.sound_speed[11] *= 1e4;
  StepInfo collapsed = at();
  collapsed.dt_next = 1e-4 * collapsed.dt_initial;
  Diagnostics diagnostics(settings_);
  try {
    diagnostics.check(model_, collapsed, reference_);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(pointPrefix(11), 0), 0u) << m;
    EXPECT_NE(m.find(fmt::format("time step collapsed: dt = {:.6g} s is below min_dt_fraction 0.001 of the initial "
                                 "{:.6g} s",
                                 collapsed.dt_next, collapsed.dt_initial)),
              std::string::npos)
        << m;
  }
  // min_dt_fraction 0 switches the check off.
  Settings off = settings_;
  off.min_dt_fraction = 0.0;
  EXPECT_NO_THROW(Diagnostics(off).check(model_, collapsed, reference_));
}

TEST_F(DiagnosticsTest, NamesTheFlattenedPointThatSetsTheStep) {
  // Isochoric flattening: the volume (and so the spacing) is unchanged, the smallest stretch is
  // 0.6, and that is what sets the step (Integrator::stableStep; below half the spacing the spread of
  // the point's support would decide, and its nodes here are as meshed).
  model_.points.F[7] = Vec3(1.0 / std::sqrt(0.6), 1.0 / std::sqrt(0.6), 0.6).asDiagonal();
  StepInfo collapsed = at();
  collapsed.dt_next = 1e-4 * collapsed.dt_initial;
  try {
    Diagnostics(settings_).check(model_, collapsed, reference_);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(pointPrefix(7), 0), 0u) << m;
    EXPECT_NE(m.find("smallest principal stretch lambda_min = 0.6 "), std::string::npos) << m;
  }
}

TEST_F(DiagnosticsTest, NamesThePointWhereEnergyAppearsFromNowhere) {
  model_.points.v[3] *= 3.0;  // about 9x the kinetic energy of one point: well over 10% overall
  const std::string m = failure();
  EXPECT_EQ(m.rfind(pointPrefix(3), 0), 0u) << m;
  EXPECT_NE(m.find("energy grew without a source: total energy = "), std::string::npos) << m;
  EXPECT_NE(m.find("(max_energy_growth 10%)"), std::string::npos) << m;
  Settings lenient = settings_;
  lenient.max_energy_growth = 100.0;
  EXPECT_EQ(failure(lenient), "");
  // A piston does work the check does not account: then it stays silent.
  constrainNode(model_, 0, 2, -100.0);
  EXPECT_EQ(failure(), "");
}

TEST_F(DiagnosticsTest, CountsInternalEnergyBelowZeroAsASource) {
  // The compatible energy update (docs/theory.md §4 step 5) books the work a point's forces do on
  // its nodes against its own internal energy, so a spurious kick balances: the kinetic energy it
  // gives shows as a point cooled below zero. The check counts each point's internal energy by its
  // size, so that the source still shows. The kick of the test above, balanced:
  const double kick = 4.0 * 0.5 * model_.points.mass[3] * model_.points.v[3].squaredNorm();
  model_.points.v[3] *= 3.0;
  model_.points.energy[3] -= kick / model_.points.mass[3];
  const std::string m = failure();
  EXPECT_EQ(m.rfind(pointPrefix(3), 0), 0u) << m;
  EXPECT_NE(m.find("energy grew without a source"), std::string::npos) << m;
}

TEST_F(DiagnosticsTest, AnInvertedPointStopsTheStepWithTheSameKindOfMessage) {
  // The point nearest the middle, thrown upwards at a huge speed, drags its nodes through the
  // points above them within one step.
  LocalIndex middle = 0;
  const Vec3 centre(1.5e-3, 1e-3, 1e-3);
  for (LocalIndex p = 1; p < model_.points.owned; ++p)
    if ((model_.points.x[p] - centre).norm() < (model_.points.x[middle] - centre).norm()) middle = p;
  model_.points.v[middle] = Vec3(0, 0, 1e9);
  try {
    integrator_->step();
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("step 4, t = ", 0), 0u) << m;
    EXPECT_NE(m.find("of body 'cube' at ("), std::string::npos) << m;
    EXPECT_NE(m.find("det(dF) = "), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace kessler::otm
