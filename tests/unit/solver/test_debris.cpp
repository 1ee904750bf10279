// Debris capture (solver/otm/debris.hpp): a block of debris (eroded points) flies at 1 km/s onto
// a wall at rest. A wall the debris may hit catches it: the debris ends inside the wall, carried
// by its nodes, the wall takes the momentum, and the total momentum is exact; the catch itself is
// perfectly inelastic with exact momentum and energy. A wall the debris
// passes through (one its body touched, or capture off) is not touched at all: the debris flies
// exactly ballistically and the wall stays bitwise at rest. A caught point that leaves the
// wall's hull is released with a zero row.
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/debris.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/neighbourhoods.hpp"
#include "solver/otm/setup.hpp"

#include "momentum.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace kessler::otm {
namespace {

constexpr double speed = 1000.0;
constexpr int debris_body = 0, wall_body = 1;

Model debrisOntoWall() {
  NeoHookeanParameters params;
  params.density = 2700.0;
  params.youngs_modulus = 70e9;
  params.poisson_ratio = 0.33;
  const MaterialPtr al = std::make_shared<NeoHookean>("al", params);
  auto box = [](const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
    return geometry::discretise(geometry::structuredBoxMesh(geometry::Box{lo, hi}, cells));
  };
  Model model;
  addBody(model, "debris", al, box(Vec3(-1e-3, -1e-3, 1e-3), Vec3(1e-3, 1e-3, 2e-3), {2, 2, 1}), Vec3(0, 0, -speed));
  addBody(model, "wall", al, box(Vec3(-4e-3, -4e-3, -2e-3), Vec3(4e-3, 4e-3, 0), {8, 8, 2}), Vec3::Zero());
  for (LocalIndex p = 0; p < model.points.owned; ++p) model.points.eroded[p] = model.points.body[p] == debris_body;
  return model;
}

struct Flight {
  Model model;
  Vec3 initial_momentum;
};

// Marks the debris (with the bodies it passes through) and runs 3 us: enough for the debris to
// cross the 1 mm gap and enter the wall.
Flight fly(const Settings& base, bool wall_touched) {
  Flight f{debrisOntoWall(), Vec3::Zero()};
  if (wall_touched) f.model.bodies[debris_body].touched = std::uint64_t{1} << wall_body;
  markNewDebris(f.model);
  Settings settings = base;
  settings.end_time = 3e-6;
  Integrator integrator(f.model, settings);
  integrator.initialise();
  f.initial_momentum = integrator.energies().momentum;
  while (!integrator.finished()) integrator.step();
  return f;
}

TEST(DebrisCapture, AWallTheDebrisMayHitCatchesItAndTakesItsMomentum) {
  const Flight f = fly(Settings{}, false);
  const PointStore& points = f.model.points;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.body[p] != debris_body) continue;
    EXPECT_EQ(points.carrier[p], wall_body) << "debris point " << points.id[p];
    EXPECT_LT(points.x[p][2], 0.0) << "debris point " << points.id[p] << " should be inside the wall";
    // Caught inelastically: it moves with the wall's nodes near the impact (0.26-0.30 of the speed
    // it flew at, 3 us after the catch), far slower than it flew.
    EXPECT_LT(points.v[p].norm(), 0.5 * speed);
  }
  const Vec3 total = bodyMomentum(f.model, debris_body) + bodyMomentum(f.model, wall_body);
  EXPECT_LT((total - f.initial_momentum).norm(), 1e-10 * f.initial_momentum.norm());
  // The wall carries most of the momentum now (the debris is 1/32 of its mass).
  EXPECT_LT(bodyMomentum(f.model, wall_body)[2], 0.5 * f.initial_momentum[2]);
}

// The impact itself, on its own: debris points inside a moving wall, caught in one search, take
// the velocity of the nodes; momentum and energy (kinetic + internal) are exact.
TEST(DebrisCapture, TheCatchIsInelasticWithExactMomentumAndEnergy) {
  Model model = debrisOntoWall();
  for (LocalIndex p = 0; p < model.points.owned; ++p)
    if (model.points.body[p] == debris_body) model.points.x[p] += Vec3(0.3e-3, 0.2e-3, -2.5e-3);
  markNewDebris(model);
  // Nodes with mass (as after an assembly) and a non-uniform velocity; wall points moving with it.
  NodeStore& nodes = model.nodes;
  for (LocalIndex a = 0; a < nodes.owned; ++a) {
    nodes.mass[a] = 1e-6;
    nodes.v[a] = Vec3(30.0 * nodes.x[a][1] / 1e-3, 0.0, -50.0 - 20.0 * nodes.x[a][0] / 1e-3);
  }
  PointStore& points = model.points;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (points.body[p] == wall_body) points.v[p] = Vec3(30.0 * points.x[p][1] / 1e-3, 0.0, -50.0);
  Neighbourhoods neighbourhoods{Settings{}};
  neighbourhoods.update(model);
  const auto debris = std::count(points.body.begin(), points.body.end(), debris_body);
  ASSERT_EQ(static_cast<long>(neighbourhoods.caught().size()), debris);  // the whole block: inside the wall

  auto energy = [&] {
    double sum = 0.0;
    for (LocalIndex p = 0; p < points.owned; ++p)
      sum += points.mass[p] * (0.5 * points.v[p].squaredNorm() + points.energy[p]);
    return sum;
  };
  const Vec3 p_before = bodyMomentum(model, debris_body) + bodyMomentum(model, wall_body);
  const double e_before = energy();
  const double heat = catchDebris(model, neighbourhoods.caught());
  EXPECT_LT((bodyMomentum(model, debris_body) + bodyMomentum(model, wall_body) - p_before).norm(),
            1e-12 * p_before.norm());
  EXPECT_NEAR(energy(), e_before, 1e-12 * e_before);
  EXPECT_GT(heat, 0.1 * e_before);  // 1 km/s onto ~50 m/s: most of the debris' kinetic energy
  const Connectivity& conn = model.connectivity;
  for (const LocalIndex d : neighbourhoods.caught()) {
    Vec3 v_nodes = Vec3::Zero();
    for (Index e = conn.offset[d]; e < conn.offset[d + 1]; ++e) v_nodes += conn.N[e] * nodes.v[conn.node[e]];
    EXPECT_LT((points.v[d] - v_nodes).norm(), 1e-9 * v_nodes.norm()) << "debris point " << points.id[d];
  }
}

TEST(DebrisCapture, DebrisPassesThroughAWallItsBodyTouchedOrWithCaptureOff) {
  Settings off;
  off.debris_capture = false;
  for (const auto& [settings, touched] : {std::pair{Settings{}, true}, std::pair{off, false}}) {
    const Model before = debrisOntoWall();
    const Flight f = fly(settings, touched);
    const PointStore& points = f.model.points;
    for (LocalIndex p = 0; p < points.owned; ++p) {
      if (points.body[p] == wall_body) {
        EXPECT_EQ(points.v[p], Vec3::Zero()) << "wall point " << points.id[p] << " moved";
        continue;
      }
      EXPECT_EQ(points.carrier[p], -1);
      LocalIndex q = 0;  // the same point before the run (the integrator reorders points)
      while (before.points.id[q] != points.id[p]) ++q;
      const Vec3 ballistic = before.points.x[q] + 3e-6 * before.points.v[q];
      EXPECT_LT((points.x[p] - ballistic).norm(), 1e-12) << "debris point " << points.id[p];
    }
  }
}

TEST(DebrisCapture, ACaughtPointLeavingTheWallIsReleasedWithAZeroRow) {
  Flight f = fly(Settings{}, false);
  PointStore& points = f.model.points;
  LocalIndex d = 0;
  while (points.body[d] != debris_body) ++d;
  ASSERT_EQ(points.carrier[d], wall_body);
  // Just behind the wall's rear face (z = -2 mm): nodes within reach, but outside their hull.
  points.x[d] = Vec3(0.2e-3, 0.1e-3, -2.3e-3);
  Neighbourhoods(Settings{}).update(f.model);
  EXPECT_EQ(points.carrier[d], -1);
  const Connectivity& conn = f.model.connectivity;
  for (Index e = conn.offset[d]; e < conn.offset[d + 1]; ++e) EXPECT_EQ(conn.N[e], 0.0);
}

}  // namespace
}  // namespace kessler::otm
