// Failed material and its release as debris (solver/common/release.hpp, docs/theory.md §8): a failed
// point stays in its body while it bears compression and is released once it bears none; a block
// of failed material striking a wall pushes it (the wall takes momentum), where debris would pass
// through; momentum stays exact throughout.
#include "geometry/structured_mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "solver/common/release.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include "momentum.hpp"

#include <gtest/gtest.h>

namespace kessler::otm {
namespace {

constexpr double speed = 1000.0;
constexpr int block_body = 0, wall_body = 1;

// Al 6061-T6 without damage or eigenerosion: nothing fails but what the test fails.
MaterialPtr aluminium() {
  ImpactMaterialParameters p = library::find("Al6061-T6").parameters;
  p.damage.reset();
  p.fracture_energy = 0.0;
  return std::make_shared<ImpactMaterial>("al", p);
}

Model blockOntoWall() {
  auto box = [](const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
    return geometry::discretise(geometry::structuredBoxMesh(geometry::Box{lo, hi}, cells));
  };
  const MaterialPtr al = aluminium();
  Model model;
  addBody(model, "block", al, box(Vec3(-1e-3, -1e-3, 0.3e-3), Vec3(1e-3, 1e-3, 2.3e-3), {4, 4, 4}), Vec3(0, 0, -speed));
  addBody(model, "wall", al, box(Vec3(-4e-3, -4e-3, -2e-3), Vec3(4e-3, 4e-3, 0), {16, 16, 4}), Vec3::Zero());
  return model;
}

struct Hit {
  Model model;
  Vec3 initial_momentum;
};

// The block strikes the wall at 1 km/s for 2 us, its points all failed (or all debris).
Hit strike(bool failed) {
  Hit hit{blockOntoWall(), Vec3::Zero()};
  Model& model = hit.model;
  Settings settings;
  settings.end_time = 2e-6;
  settings.debris_contact = false;  // debris passes through the wall
  Integrator integrator(model, settings);
  integrator.initialise();
  for (LocalIndex p = 0; p < model.points.owned; ++p) {
    if (model.points.body[p] != block_body) continue;
    model.points.fail(p);
    if (!failed) model.points.carrier[p] = -1;  // released already: debris
  }
  hit.initial_momentum = integrator.energies().momentum;
  while (!integrator.finished()) integrator.step();
  return hit;
}

TEST(FailedMaterial, PushesWhatItHitsWhereDebrisWouldPassThrough) {
  const Hit failed = strike(true);
  const Vec3 total = bodyMomentum(failed.model, block_body) + bodyMomentum(failed.model, wall_body);
  EXPECT_LT((total - failed.initial_momentum).norm(), 1e-10 * failed.initial_momentum.norm());
  // The failed block presses on the wall like a fluid jet (crater ~0.7 mm deep after 2 us): the
  // wall has taken a fifth of its momentum (measured 22%), and no point went through the wall.
  EXPECT_LT(bodyMomentum(failed.model, wall_body)[2], 0.1 * failed.initial_momentum[2]);
  for (LocalIndex p = 0; p < failed.model.points.owned; ++p)
    if (failed.model.points.body[p] == block_body) {
      EXPECT_GT(failed.model.points.x[p][2], -1.5e-3) << "point " << failed.model.points.id[p];
    }
  // The same block as debris flies through the wall without loading it (but for round-off: its
  // rows of the first step, built while it was intact, still lumped it onto the wall's nodes).
  const Hit debris = strike(false);
  EXPECT_LT(bodyMomentum(debris.model, wall_body).norm(), 1e-12 * debris.initial_momentum.norm());
}

TEST(DebrisRelease, ReleasesOnlyTheFailedPointsThatBearNothing) {
  Model model = blockOntoWall();
  PointStore& points = model.points;
  const std::vector<IndexRange> ranges = bodyRanges(points.body, points.size(), model.bodies.size());
  const IndexRange& block = ranges[block_body];
  for (LocalIndex p = block.begin; p < block.end; ++p) {
    points.fail(p);
    // Half of them still under pressure, the other half stress-free.
    if ((p - block.begin) % 2 == 0) points.stress[p] = -1e9 * Mat3::Identity();
  }
  Settings settings;
  const LocalIndex released = DebrisRelease(settings.erosion_radius).apply(model);
  EXPECT_EQ(released, (block.end - block.begin) / 2);
  for (LocalIndex p = block.begin; p < block.end; ++p) {
    const bool loaded = (p - block.begin) % 2 == 0;
    EXPECT_EQ(points.failed(p), loaded) << "point " << p;
    EXPECT_EQ(points.debris(p), !loaded) << "point " << p;
    EXPECT_EQ(points.carrier[p], loaded ? block_body : -1);
  }
  // The wall's points are untouched.
  for (LocalIndex p = ranges[wall_body].begin; p < ranges[wall_body].end; ++p) EXPECT_FALSE(points.broken[p]);
}

// A method whose particle velocities are interpolated from its unknowns (RKPM) releases the same
// points without the exchange: no velocity or energy changes, where the exchange changes both.
TEST(DebrisRelease, InterpolatedVelocitiesAreReleasedWithoutTheExchange) {
  Model own = blockOntoWall();
  const std::vector<IndexRange> ranges = bodyRanges(own.points.body, own.points.size(), own.bodies.size());
  const IndexRange& block = ranges[block_body];
  for (LocalIndex p = block.begin; p < block.end; ++p) {
    own.points.fail(p);
    own.points.v[p] = Vec3(0.0, 0.0, -speed * (1.0 + 0.1 * ((p * 7) % 5)));  // rough: the exchange acts
    if ((p - block.begin) % 2 == 0) own.points.stress[p] = -1e9 * Mat3::Identity();
  }
  const Model start = own;
  Model interpolated = own;
  const Settings settings;
  DebrisRelease(settings.erosion_radius).apply(own);
  const LocalIndex released =
      DebrisRelease(settings.erosion_radius, DebrisRelease::Velocities::interpolated).apply(interpolated);
  EXPECT_EQ(released, (block.end - block.begin) / 2);
  LocalIndex changed = 0;
  for (LocalIndex p = 0; p < own.points.size(); ++p) {
    EXPECT_EQ(interpolated.points.debris(p), own.points.debris(p)) << "point " << p;
    EXPECT_EQ(interpolated.points.v[p], start.points.v[p]) << "point " << p;
    EXPECT_EQ(interpolated.points.energy[p], start.points.energy[p]) << "point " << p;
    changed += own.points.v[p] != interpolated.points.v[p] ? 1 : 0;
  }
  EXPECT_GT(changed, 0) << "the exchange changed nothing: the test shows nothing";
}

}  // namespace
}  // namespace kessler::otm
