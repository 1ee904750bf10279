// Debris contact (solver/common/debris_contact.hpp): a block of debris (eroded points) flies onto a wall at
// rest. A wall the debris may hit stops it without letting it through: at 1 km/s the debris stays in
// front of the wall, at 4 km/s it craters it; it is left slow (nearly inelastic), the wall takes its
// momentum, the total momentum is exact, and kinetic + internal + stored energy is kept up to the
// time integration, in a number of steps that no light node of the wall sets. Debris is pushed,
// never pulled. A wall the debris passes through (one its body touched, or contact off) is not
// touched at all: the debris flies exactly ballistically and the wall stays bitwise at rest.
#include "geometry/structured_mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "solver/common/debris_contact.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include "momentum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace kessler::otm {
namespace {

constexpr double speed = 1000.0;
constexpr int debris_body = 0, wall_body = 1;

// Al 6061-T6 without damage or eigenerosion (nothing fails but what the test makes debris): a law
// with a thermal state, so that the step's heat is booked and the energy can be checked.
Model debrisOntoWall() {
  ImpactMaterialParameters params = library::find("Al6061-T6").parameters;
  params.damage.reset();
  params.fracture_energy = 0.0;
  const MaterialPtr al = std::make_shared<ImpactMaterial>("al", params);
  auto box = [](const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
    return geometry::discretise(geometry::structuredBoxMesh(geometry::Box{lo, hi}, cells));
  };
  Model model;
  addBody(model, "debris", al, box(Vec3(-1e-3, -1e-3, 2e-3), Vec3(1e-3, 1e-3, 3e-3), {2, 2, 1}), Vec3(0, 0, -speed));
  addBody(model, "wall", al, box(Vec3(-4e-3, -4e-3, -2e-3), Vec3(4e-3, 4e-3, 0), {8, 8, 2}), Vec3::Zero());
  for (LocalIndex p = 0; p < model.points.owned; ++p) model.points.broken[p] = model.points.body[p] == debris_body;
  return model;
}

struct Flight {
  Model model;
  Energies initial;
  Energies final;
  long steps = 0;
};

// Marks the debris (with the bodies it passes through) and runs 3 us: enough for the debris to
// cross the 2 mm gap (more than its contact radius) and strike the wall.
Flight fly(const Settings& base, bool wall_touched, double debris_speed = speed) {
  Flight f{debrisOntoWall(), {}, {}, 0};
  for (LocalIndex p = 0; p < f.model.points.owned; ++p)
    if (f.model.points.body[p] == debris_body) f.model.points.v[p] = Vec3(0, 0, -debris_speed);
  if (wall_touched) f.model.bodies[debris_body].touched = std::uint64_t{1} << wall_body;
  markNewDebris(f.model);
  Settings settings = base;
  settings.end_time = 3e-6;
  Integrator integrator(f.model, settings);
  integrator.initialise();
  f.initial = integrator.energies();
  while (!integrator.finished()) integrator.step();
  f.final = integrator.energies();
  f.steps = integrator.steps();
  return f;
}

TEST(DebrisContact, AWallTheDebrisMayHitStopsItAndTakesItsMomentum) {
  // At 1 km/s the wall's face barely yields: the debris stays in front of it (z = 0, moved by less
  // than 0.1 mm in 3 us). At 4 km/s it craters the wall (the face nodes are driven in, as a shock
  // of about 30 GPa does), but it does not pass through (z = -2 mm, the rear face).
  for (const auto& [v, deepest] : {std::pair{speed, -0.1e-3}, std::pair{4.0 * speed, -2e-3}}) {
    SCOPED_TRACE(v);
    const Flight f = fly(Settings{}, false, v);
    const PointStore& points = f.model.points;
    for (LocalIndex p = 0; p < points.owned; ++p) {
      if (points.body[p] != debris_body) continue;
      EXPECT_EQ(points.lastStruck(p), wall_body) << "debris point " << points.id[p];
      EXPECT_GT(points.x[p][2], deepest) << "debris point " << points.id[p] << " went too deep";
      // Stopped: it moves with the wall it struck, or bounces off slowly.
      EXPECT_LT(std::abs(points.v[p][2]), 0.3 * v) << "debris point " << points.id[p];
    }
    const Vec3 p0 = f.initial.momentum;
    EXPECT_LT((f.final.momentum - p0).norm(), 1e-10 * p0.norm());
    // The wall took nearly all of the debris' momentum, and at most the little more that a bounce
    // gives it.
    const double wall = bodyMomentum(f.model, wall_body)[2];
    EXPECT_LT(wall, 0.9 * p0[2]);
    EXPECT_GT(wall, 1.3 * p0[2]);
    // What the springs store and the dashpots' heat balance the kinetic energy to the time
    // integration's error.
    EXPECT_NEAR(f.final.total(), f.initial.total(), 0.06 * f.initial.total());
    EXPECT_GT(f.final.internal, 0.3 * f.initial.kinetic);  // a nearly inelastic strike heats
    // The strike costs steps, but the wall's nodes do not set them by their own lumped masses
    // (which LME makes uneven at a surface): bounded by those, the 4 km/s strike took 1,266 steps
    // (380 with the body's mass per node; 51 without a strike).
    EXPECT_LT(f.steps, 1000);
  }
}

// The contact only pushes: debris overlapping a wall that moves away from it is pushed off and then
// left behind, never pulled after the wall.
TEST(DebrisContact, DebrisDoesNotStickToAWallMovingAway) {
  Model model = debrisOntoWall();
  PointStore& points = model.points;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.body[p] == debris_body) {
      points.x[p][2] -= 1.1e-3;  // within the contact radius of the wall's face nodes
      points.v[p].setZero();
    } else {
      points.v[p] = Vec3(0, 0, -100.0);
    }
  }
  markNewDebris(model);
  Settings settings;
  settings.end_time = 2e-6;
  Integrator integrator(model, settings);
  integrator.initialise();
  const Vec3 p0 = integrator.energies().momentum;
  while (!integrator.finished()) {
    integrator.step();
    for (LocalIndex p = 0; p < points.owned; ++p) {
      if (points.body[p] == debris_body) {
        ASSERT_GE(points.v[p][2], 0.0) << "debris point " << points.id[p] << " pulled";
      }
    }
  }
  EXPECT_LT((integrator.energies().momentum - p0).norm(), 1e-10 * p0.norm());
}

TEST(DebrisContact, DebrisPassesThroughAWallItsBodyTouchedOrWithContactOff) {
  Settings off;
  off.debris_contact = false;
  for (const auto& [settings, touched] : {std::pair{Settings{}, true}, std::pair{off, false}}) {
    const Model before = debrisOntoWall();
    const Flight f = fly(settings, touched);
    const PointStore& points = f.model.points;
    for (LocalIndex p = 0; p < points.owned; ++p) {
      if (points.body[p] == wall_body) {
        EXPECT_EQ(points.v[p], Vec3::Zero()) << "wall point " << points.id[p] << " moved";
        continue;
      }
      EXPECT_EQ(points.lastStruck(p), -1);
      LocalIndex q = 0;  // the same point before the run (the integrator reorders points)
      while (before.points.id[q] != points.id[p]) ++q;
      const Vec3 ballistic = before.points.x[q] + 3e-6 * before.points.v[q];
      EXPECT_LT((points.x[p] - ballistic).norm(), 1e-12) << "debris point " << points.id[p];
    }
  }
}

}  // namespace
}  // namespace kessler::otm
