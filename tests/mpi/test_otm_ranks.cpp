// The distributed OTM step (docs/parallel.md, "The distributed step") on 2 and 3 ranks against one
// process: a block strikes a plate, elastic or fracturing, and after every step each rank's own
// points and nodes must be bitwise what one process holds for them, and the energies and time steps
// the same bits.
#include "../unit/blocks.hpp"
#include "bitwise.hpp"
#include "parallel/communicator.hpp"
#include "solver/otm/distribution.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/morton_order.hpp"

#include <gtest/gtest.h>

namespace kessler::otm {
namespace {

const parallel::Communicator& world() {
  return parallel::Communicator::world();
}

// A 4 mm cube onto a 12 x 12 mm plate 3 mm thick, or (a shield) 2 mm thick with a rear wall as thick
// 2 mm behind it; 1 mm cells (six tets each). Built, sorted and numbered as otm::buildModel does.
Model impact(const MaterialPtr& material, double speed, bool shield = false) {
  Model model;
  const double thickness = shield ? 2e-3 : 3e-3;
  const int cells = shield ? 2 : 3;
  testing::addBlock(model, "plate", {Vec3(-6e-3, -6e-3, -thickness), Vec3(6e-3, 6e-3, 0.0)}, {12, 12, cells}, material);
  testing::addBlock(model, "projectile", {Vec3(-2e-3, -2e-3, 0.3e-3), Vec3(2e-3, 2e-3, 4.3e-3)}, {4, 4, 4}, material,
                    Vec3(0.0, 0.0, -speed));
  if (shield)
    testing::addBlock(model, "wall", {Vec3(-6e-3, -6e-3, -6e-3), Vec3(6e-3, 6e-3, -4e-3)}, {12, 12, 2}, material);
  sortForLocality(model);
  numberInOrder(model);
  return model;
}

using testing::differing;
using testing::fracturing;
using testing::same;

// Steps one process and this rank's part side by side; returns the one process's model at the end.
void compareEveryStep(const MaterialPtr& material, double speed, bool shield, int steps, Model& whole) {
  ASSERT_GT(world().size(), 1);
  Settings settings;
  settings.end_time = 1.0;
  whole = impact(material, speed, shield);
  Model mine = impact(material, speed, shield);
  Integrator one(whole, settings);
  Distribution distribution(world());
  Integrator part(mine, settings, &distribution);
  one.initialise();
  part.initialise();

  // Every point and node is some rank's own, once; each rank holds a part and a halo, not the whole.
  auto ownCount = [](std::span<const std::uint8_t> ghost, LocalIndex n) {
    std::int64_t own = 0;
    for (LocalIndex i = 0; i < n; ++i) own += ghost[static_cast<std::size_t>(i)] ? 0 : 1;
    return own;
  };
  const std::int64_t own_points = ownCount(distribution.ghostPoints(), mine.points.owned);
  EXPECT_EQ(world().sum(own_points), whole.points.owned);
  EXPECT_EQ(world().sum(ownCount(distribution.ghostNodes(), mine.nodes.owned)), whole.nodes.owned);
  EXPECT_LT(mine.points.owned, whole.points.owned) << "the halo holds every point: the test would test nothing";
  EXPECT_GT(mine.points.owned, own_points) << "no ghosts";

  for (int step = 0; step <= steps; ++step) {
    if (step > 0) {
      try {
        one.step();
      } catch (const std::exception& e) {
        FAIL() << "step " << step << ", one process: " << e.what();
      }
      try {
        part.step();
      } catch (const std::exception& e) {
        FAIL() << "step " << step << ", rank " << world().rank() << ": " << e.what();
      }
    }
    const Energies a = one.energies(), b = part.energies();
    const bool scalars = same(one.time(), part.time()) && same(one.nextStep(), part.nextStep()) &&
                         same(a.kinetic, b.kinetic) && same(a.internal, b.internal) &&
                         same(a.stabilisation, b.stabilisation) && same(a.momentum, b.momentum) &&
                         world().sum(part.erodedPoints()) == one.erodedPoints();
    const PointStore &p = mine.points, &q = whole.points;
    const int points = differing(p, distribution.ghostPoints(), q, [&](LocalIndex i, LocalIndex j) {
      return same(p.x[i], q.x[j]) && same(p.v[i], q.v[j]) && same(p.F[i], q.F[j]) && same(p.stress[i], q.stress[j]) &&
             same(p.energy[i], q.energy[j]) && same(p.volume[i], q.volume[j]) &&
             same(p.volume_defect[i], q.volume_defect[j]) && p.broken[i] == q.broken[j] &&
             p.carrier[i] == q.carrier[j] && p.passes_through[i] == q.passes_through[j];
    });
    const NodeStore &m = mine.nodes, &n = whole.nodes;
    const int nodes = differing(m, distribution.ghostNodes(), n, [&](LocalIndex i, LocalIndex j) {
      return same(m.x[i], n.x[j]) && same(m.v[i], n.v[j]);
    });
    if (world().any(!scalars || points > 0 || nodes > 0)) {
      ADD_FAILURE() << "step " << step << ": scalars " << (scalars ? "agree" : "differ") << ", " << points
                    << " own points and " << nodes << " own nodes differ";
      return;
    }
  }
}

TEST(DistributedStep, ElasticImpactBitwiseAsOneProcess) {
  Model whole;
  compareEveryStep(testing::aluminium(), 800.0, false, 60, whole);
  // The impact happened: the bodies deform.
  Energies e = pointEnergies(whole.points, 0.0);
  EXPECT_GT(e.internal, 0.1 * e.kinetic);
}

// Eigenerosion, the release of failed points as debris, and debris striking a rear wall.
TEST(DistributedStep, FracturingImpactBitwiseAsOneProcess) {
  Model whole;
  compareEveryStep(fracturing(), 4000.0, true, 100, whole);
  LocalIndex debris = 0, struck = 0;
  for (LocalIndex p = 0; p < whole.points.owned; ++p) {
    debris += whole.points.debris(p) ? 1 : 0;
    struck += whole.points.lastStruck(p) >= 0 ? 1 : 0;
  }
  EXPECT_GT(debris, 20) << "too little failed and was released for the test to test it";
  EXPECT_GT(struck, 0) << "no debris struck a body";
}

// A cell list over a sparse set (a debris cloud) is enlarged by the set's extent and count: ranks
// that each hold a part and some of the others' (ghosts) must agree on the whole set's size, or their
// searches meet their candidates in another order. The whole set here needs the enlargement, and no
// rank's part does on its own.
TEST(DistributedStep, CellSizeAgreedAsForTheWholeSet) {
  const int ranks = world().size(), me = world().rank();
  std::vector<Vec3> whole;
  for (int i = 0; i < 400; ++i)  // a dense block, and a few points far out
    whole.emplace_back(1e-3 * (i % 8), 1e-3 * ((i / 8) % 8), 1e-3 * (i / 64));
  for (int i = 0; i < 12; ++i) whole.emplace_back(0.05 * i, -0.03 * i, 0.02 * (i % 3));
  const double cell = 1.2e-3;
  const double expected =
      CellList::enlargedSize(CellList::boundsOf(whole, static_cast<LocalIndex>(whole.size())), whole.size(), cell);
  ASSERT_GT(expected, cell) << "the whole set must need enlarging";
  // Rank r owns every ranks-th point from r, and holds the next rank's first ten as ghosts.
  std::vector<Vec3> mine;
  std::int64_t own = 0;
  for (std::size_t i = static_cast<std::size_t>(me); i < whole.size(); i += static_cast<std::size_t>(ranks), ++own)
    mine.push_back(whole[i]);
  for (std::size_t i = static_cast<std::size_t>((me + 1) % ranks), k = 0; k < 10;
       i += static_cast<std::size_t>(ranks), ++k)
    mine.push_back(whole[i]);
  const Share share{{}, &world()};
  const double agreed = agreedCellSize(mine, static_cast<LocalIndex>(mine.size()), own, cell, share);
  EXPECT_EQ(agreed, expected);
  // What each rank's part alone would choose differs from the whole's somewhere.
  const double alone = CellList::enlargedSize(CellList::boundsOf(mine, static_cast<LocalIndex>(mine.size())),
                                              static_cast<std::int64_t>(mine.size()), cell);
  EXPECT_TRUE(world().any(alone != expected)) << "the test needs a part that would choose another size";
  // A part as spread as the whole, with fewer positions, is built with the agreed size as it is; left
  // to enlarge it again, some rank's cells would differ.
  CellList cells;
  cells.build(mine, static_cast<LocalIndex>(mine.size()), agreed, /*enlarge=*/false);
  EXPECT_EQ(cells.cellSize(), expected);
  cells.build(mine, static_cast<LocalIndex>(mine.size()), agreed);
  EXPECT_TRUE(world().any(cells.cellSize() != expected)) << "the test needs a part that would be enlarged further";
}

}  // namespace
}  // namespace kessler::otm
