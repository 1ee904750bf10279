// The velocity transfer's heat (docs/theory.md §4 step 4): the kinetic energy the points lose when
// they take the nodes' velocity increments (FLIP) is exactly half their mass times the spread of
// those increments over their nodes, and it is handed to the material as heat, so that the points'
// kinetic energy plus that heat changes as the nodes' kinetic energy does.
#include "geometry/structured_mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace kessler::otm {
namespace {

// A law that bears no stress and keeps its energy, but takes the heat it is given: what the step
// adds to the points' energy is then the transfer's heat alone.
class HeatOnly final : public Material {
 public:
  const std::string& name() const override { return name_; }
  double referenceDensity() const override { return 2700.0; }
  double poissonRatio() const override { return 0.3; }
  double referenceSoundSpeed() const override { return 5000.0; }
  void update(PointStore& points, LocalIndex begin, LocalIndex end, double /*dt*/) const override {
    for (LocalIndex p = begin; p < end; ++p) {
      points.stress[p].setZero();
      points.sound_speed[p] = referenceSoundSpeed();
    }
  }
  void heat(PointStore& points, LocalIndex begin, LocalIndex end, std::span<const double> heat) const override {
    for (LocalIndex p = begin; p < end; ++p)
      points.energy[p] += heat[static_cast<std::size_t>(p - begin)] / points.mass[p];
  }

 private:
  std::string name_ = "heat-only";
};

double pointKinetic(const PointStore& points) {
  double k = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) k += 0.5 * points.mass[p] * points.v[p].squaredNorm();
  return k;
}

double pointInternal(const PointStore& points) {
  double u = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) u += points.mass[p] * points.energy[p];
  return u;
}

TEST(TransferHeat, IsWhatThePointsLoseToTheNodes) {
  // Rough point velocities (what a shock or a contact leaves) and a roller plane that stops the
  // nodes on it: with no stress, the nodes' increments come from the rollers alone, and they differ
  // across each point's support.
  Model model;
  addBody(
      model, "block", std::make_shared<HeatOnly>(),
      geometry::discretise(geometry::structuredBoxMesh(geometry::Box{Vec3::Zero(), Vec3(4e-3, 4e-3, 4e-3)}, {4, 4, 4})),
      Vec3::Zero());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> speed(-100.0, 100.0);
  for (LocalIndex p = 0; p < model.points.size(); ++p)
    model.points.v[p] = Vec3(speed(random), speed(random), speed(random)) + Vec3(-200.0, 0.0, 0.0);
  constrainPlane(model, 0, 0.0, 1e-9);
  Settings settings;
  settings.end_time = 1.0;
  settings.volume_averaging = false;
  Integrator integrator(model, settings);
  integrator.initialise();
  const double kinetic0 = pointKinetic(model.points), internal0 = pointInternal(model.points);
  integrator.step();
  // The nodes' kinetic energy before the step is that of the gathered momentum, l^2 / 2m (the
  // assembly keeps l and m), and after it that of their new velocity.
  const NodeStore& nodes = model.nodes;
  double nodal0 = 0.0, nodal1 = 0.0;
  for (LocalIndex a = 0; a < nodes.owned; ++a) {
    if (!(nodes.mass[a] > 0.0)) continue;
    nodal0 += 0.5 * nodes.momentum[a].squaredNorm() / nodes.mass[a];
    nodal1 += 0.5 * nodes.mass[a] * nodes.v[a].squaredNorm();
  }
  const double heat = pointInternal(model.points) - internal0;
  const double kinetic = pointKinetic(model.points) - kinetic0;
  EXPECT_GT(heat, 1e-3 * (nodal0 - nodal1));  // not trivially zero: the rollers took energy
  EXPECT_NEAR(kinetic + heat, nodal1 - nodal0, 1e-12 * kinetic0);
}

TEST(TransferHeat, AnImpactMaterialTakesItIntoEnergyAndTemperature) {
  const ImpactMaterial al("al", library::find("Al6061-T6").parameters);
  PointStore points;
  points.resize(3);
  for (LocalIndex p = 0; p < 3; ++p) {
    points.mass[p] = 2.0e-6;
    points.energy[p] = 1.0e3;
    points.temperature[p] = 300.0;
  }
  points.fail(2);
  points.carrier[2] = -1;  // released: debris takes no part
  ASSERT_TRUE(points.debris(2));
  const std::vector<double> heat{0.5, 0.0, 0.5};
  al.heat(points, 0, 3, heat);
  EXPECT_DOUBLE_EQ(points.energy[0], 1.0e3 + 0.5 / 2.0e-6);
  EXPECT_DOUBLE_EQ(points.temperature[0], 300.0 + 0.5 / (2.0e-6 * 896.0));
  EXPECT_DOUBLE_EQ(points.energy[1], 1.0e3);
  EXPECT_DOUBLE_EQ(points.energy[2], 1.0e3);
  EXPECT_DOUBLE_EQ(points.temperature[2], 300.0);
}

}  // namespace
}  // namespace kessler::otm
