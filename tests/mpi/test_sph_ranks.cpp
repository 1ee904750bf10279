// The distributed SPH step (docs/parallel.md, "SPH across ranks") on 2 and 3 ranks against one
// process: a block strikes a plate, elastic or fracturing, and after every step each rank's own
// particles must be bitwise what one process holds for them, and the energies, time steps and
// counts of distorted elements the same bits.
#include "../unit/blocks.hpp"
#include "bitwise.hpp"
#include "parallel/communicator.hpp"
#include "solver/sph/distribution.hpp"
#include "solver/sph/integrator.hpp"
#include "solver/sph/setup.hpp"
#include "solver/sph/sph_method.hpp"

#include <gtest/gtest.h>

namespace kessler::sph {
namespace {

const parallel::Communicator& world() {
  return parallel::Communicator::world();
}

// A 4 mm cube onto a 12 x 12 mm plate 3 mm thick, or (a shield, on the symmetry plane x = 0) a
// 2 mm plate with a rear wall as thick 2 mm behind it, both 18 mm wide (so that three ranks' halos,
// four rings of elements deep, do not each hold the whole); 0.5 mm lattice elements.
Problem impact(const MaterialPtr& material, const Vec3& velocity, bool shield) {
  Problem problem;
  problem.method = "sph";
  problem.settings.solver.end_time = 1.0;
  const double x0 = shield ? 0.0 : -6e-3, px0 = shield ? 0.0 : -2e-3;
  auto body = [&](const std::string& name, const Vec3& lo, const Vec3& hi, const Vec3& v) {
    BodySetup b;
    b.name = name;
    b.material = material;
    b.mesh = geometry::MeshRequest{geometry::Box{lo, hi}, 0.5e-3};
    b.velocity = v;
    problem.bodies.push_back(b);
  };
  const double thickness = shield ? 1e-3 : 3e-3, half_width = shield ? 9e-3 : 6e-3;
  body("plate", Vec3(x0, -half_width, -thickness), Vec3(6e-3, half_width, 0.0), Vec3::Zero());
  body("projectile", Vec3(px0, -2e-3, 0.3e-3), Vec3(2e-3, 2e-3, 4.3e-3), velocity);
  if (shield) {
    body("wall", Vec3(x0, -half_width, -4e-3), Vec3(6e-3, half_width, -3e-3), Vec3::Zero());
    problem.symmetry_axes = {0};
  }
  return problem;
}

using testing::differing;
using testing::fracturing;
using testing::same;

struct Outcome {
  LocalIndex debris = 0, struck = 0, distorted = 0, loose = 0;
};

// Steps one process and this rank's part side by side; returns what happened in the one process.
Outcome compareEveryStep(const Problem& problem, int steps) {
  EXPECT_GT(world().size(), 1);
  Model whole = buildModel(problem), mine = buildModel(problem);
  Integrator one(whole, settingsFor(problem));
  Distribution distribution(world(), mirrorBox(problem));
  Integrator part(mine, settingsFor(problem), &distribution);
  one.initialise();
  part.initialise();

  // Every particle is some rank's own, once; each rank holds a part and a halo, not the whole.
  const Share share = distribution.share();
  std::int64_t own = 0;
  for (LocalIndex p = 0; p < mine.points.owned; ++p) own += share.own(p) ? 1 : 0;
  EXPECT_EQ(world().sum(own), whole.points.owned);
  EXPECT_LT(mine.points.owned, whole.points.owned) << "the halo holds every particle: the test would test nothing";
  EXPECT_GT(mine.points.owned, own) << "no ghosts";

  for (int step = 0; step <= steps; ++step) {
    if (step > 0) {
      try {
        one.step();
      } catch (const std::exception& e) {
        ADD_FAILURE() << "step " << step << ", one process: " << e.what();
        return {};
      }
      try {
        part.step();
      } catch (const std::exception& e) {
        ADD_FAILURE() << "step " << step << ", rank " << world().rank() << ": " << e.what();
        return {};
      }
    }
    const Energies a = one.energies(), b = part.energies();
    const Clock c = one.clock(), d = part.clock();
    const bool scalars = same(c.time, d.time) && same(c.dt_next, d.dt_next) && same(a.kinetic, b.kinetic) &&
                         same(a.internal, b.internal) && same(a.momentum, b.momentum) &&
                         one.distorted() == part.distorted() && one.uncorrected() == part.uncorrected() &&
                         same(one.meanNeighbours(), part.meanNeighbours());
    const PointStore &p = mine.points, &q = whole.points;
    const int differ = differing(p, distribution.share().ghost, q, [&](LocalIndex i, LocalIndex j) {
      return same(p.x[i], q.x[j]) && same(p.v[i], q.v[j]) && same(p.F[i], q.F[j]) && same(p.stress[i], q.stress[j]) &&
             same(p.energy[i], q.energy[j]) && same(p.volume[i], q.volume[j]) && p.broken[i] == q.broken[j] &&
             p.loose[i] == q.loose[j] && p.carrier[i] == q.carrier[j] && same(mine.viscosity[i], whole.viscosity[j]);
    });
    if (world().any(!scalars || differ > 0)) {
      ADD_FAILURE() << "step " << step << ": scalars " << (scalars ? "agree" : "differ") << ", " << differ
                    << " own particles differ on rank " << world().rank();
      return {};
    }
  }
  Outcome out;
  out.distorted = one.distorted();
  for (LocalIndex i = 0; i < whole.points.owned; ++i) {
    out.debris += whole.points.debris(i) ? 1 : 0;
    out.struck += whole.points.lastStruck(i) >= 0 ? 1 : 0;
    out.loose += whole.points.loose[i] ? 1 : 0;
  }
  return out;
}

TEST(DistributedSph, ElasticImpactBitwiseAsOneProcess) {
  compareEveryStep(impact(testing::aluminium(), Vec3(0.0, 0.0, -800.0), false), 40);
}

// A block sheared by its initial velocity (v_x = 1e6/s z, up to 3 km/s): its elements fail by
// their distortion at a strict threshold (a quality of 0.97, corner angles some 14 degrees off
// square), so that the reconstruction's nodes are judged across ranks.
TEST(DistributedSph, ShearedElementsFailBitwiseAsOneProcess) {
  Problem problem;
  problem.method = "sph";
  problem.settings.solver.end_time = 1.0;
  problem.settings.sph.element_min_quality = 0.97;
  BodySetup block;
  block.name = "block";
  block.material = testing::aluminium();
  block.mesh = geometry::MeshRequest{geometry::Box{Vec3(-6e-3, -6e-3, -3e-3), Vec3(6e-3, 6e-3, 0.0)}, 0.5e-3};
  block.velocity_field = [](const Vec3& x) { return Vec3(1e6 * x[2], 0.0, 0.0); };
  problem.bodies = {block};
  const Outcome out = compareEveryStep(problem, 60);
  EXPECT_GT(out.distorted, 20) << "too few elements failed by their distortion for the test to test it";
}

// Eigenerosion, the release of failed particles as debris, debris striking a rear wall, and a
// symmetry plane.
TEST(DistributedSph, FracturingImpactBitwiseAsOneProcess) {
  const Outcome out = compareEveryStep(impact(fracturing(), Vec3(0.0, 0.0, -4000.0), true), 120);
  EXPECT_GT(out.debris, 20) << "too little failed and was released for the test to test it";
  EXPECT_GT(out.struck, 0) << "no debris struck a body";
}

// A gathered method holds the whole run on rank 0, as one process does.
TEST(DistributedSph, GatheredMethodIsTheWholeRun) {
  const Problem problem = impact(testing::aluminium(), Vec3(0.0, 0.0, -800.0), false);
  SphMethod one(buildModel(problem), problem), part(buildModel(problem), problem, &world());
  one.initialise();
  part.initialise();
  for (int step = 0; step < 10; ++step) {
    one.step();
    part.step();
  }
  const std::unique_ptr<Method> gathered = part.gathered(false);
  ASSERT_EQ(gathered != nullptr, world().root());
  if (!gathered) return;
  const PointStore &p = gathered->state().points, &q = one.state().points;
  ASSERT_EQ(p.owned, q.owned);
  int differ = 0;
  for (LocalIndex i = 0; i < p.owned; ++i)
    differ += p.id[i] == q.id[i] && same(p.x[i], q.x[i]) && same(p.v[i], q.v[i]) ? 0 : 1;
  EXPECT_EQ(differ, 0);
  const NodeCloud a = gathered->nodes(), b = one.nodes();
  ASSERT_EQ(a.x.size(), b.x.size());
  for (std::size_t k = 0; k < a.x.size(); ++k) ASSERT_TRUE(same(a.x[k], b.x[k]) && same(a.v[k], b.v[k])) << k;
  EXPECT_EQ(gathered->clock().steps, 10);
}

}  // namespace
}  // namespace kessler::sph
