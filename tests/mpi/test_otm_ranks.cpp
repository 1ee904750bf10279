// The distributed OTM step (docs/parallel.md, "The distributed step") on 2 and 3 ranks against one
// process: an elastic block strikes a plate, and after every step each rank's own points and nodes
// must be bitwise what one process holds for them, and the energies and time steps the same bits.
#include "../unit/blocks.hpp"
#include "parallel/communicator.hpp"
#include "solver/otm/distribution.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/morton_order.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <unordered_map>

namespace kessler::otm {
namespace {

const parallel::Communicator& world() {
  return parallel::Communicator::world();
}

// A 4 mm cube at 800 m/s onto a 12 x 12 x 3 mm plate, 1 mm cells (six tets each); built, sorted and
// numbered as otm::buildModel does.
Model impact() {
  Model model;
  testing::addBlock(model, "plate", {Vec3(-6e-3, -6e-3, -3e-3), Vec3(6e-3, 6e-3, 0.0)}, {12, 12, 3});
  testing::addBlock(model, "projectile", {Vec3(-2e-3, -2e-3, 0.3e-3), Vec3(2e-3, 2e-3, 4.3e-3)}, {4, 4, 4},
                    testing::aluminium(), Vec3(0.0, 0.0, -800.0));
  sortForLocality(model);
  numberInOrder(model);
  return model;
}

bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
template <class M>
bool same(const M& a, const M& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// Entries of `mine` that are this rank's own and differ from the entry of `whole` with the same id.
template <class Store, class Compare>
int differing(const Store& mine, std::span<const std::uint8_t> ghost, const Store& whole, Compare&& compare) {
  std::unordered_map<Index, LocalIndex> index;
  for (LocalIndex i = 0; i < whole.owned; ++i) index[whole.id[i]] = i;
  int differ = 0;
  for (LocalIndex i = 0; i < mine.owned; ++i) {
    if (!ghost.empty() && ghost[static_cast<std::size_t>(i)]) continue;
    const auto found = index.find(mine.id[i]);
    if (found == index.end() || !compare(i, found->second)) ++differ;
  }
  return differ;
}

TEST(DistributedStep, EveryStepBitwiseAsOneProcess) {
  ASSERT_GT(world().size(), 1);
  Settings settings;
  settings.end_time = 1.0;
  Model whole = impact(), mine = impact();
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

  const int steps = 60;
  int first_bad_step = -1;
  for (int step = 0; step <= steps && first_bad_step < 0; ++step) {
    if (step > 0) {
      one.step();
      part.step();
    }
    const Energies a = one.energies(), b = part.energies();
    const bool scalars = same(one.time(), part.time()) && same(one.nextStep(), part.nextStep()) &&
                         same(a.kinetic, b.kinetic) && same(a.internal, b.internal) &&
                         same(a.stabilisation, b.stabilisation) && same(a.momentum, b.momentum);
    const PointStore &p = mine.points, &q = whole.points;
    const int points = differing(p, distribution.ghostPoints(), q, [&](LocalIndex i, LocalIndex j) {
      return same(p.x[i], q.x[j]) && same(p.v[i], q.v[j]) && same(p.F[i], q.F[j]) && same(p.stress[i], q.stress[j]) &&
             same(p.energy[i], q.energy[j]) && same(p.volume[i], q.volume[j]) &&
             same(p.volume_defect[i], q.volume_defect[j]);
    });
    const NodeStore &m = mine.nodes, &n = whole.nodes;
    const int nodes = differing(m, distribution.ghostNodes(), n, [&](LocalIndex i, LocalIndex j) {
      return same(m.x[i], n.x[j]) && same(m.v[i], n.v[j]);
    });
    if (world().any(!scalars || points > 0 || nodes > 0)) {
      first_bad_step = step;
      ADD_FAILURE() << "step " << step << ": scalars " << (scalars ? "agree" : "differ") << ", " << points
                    << " own points and " << nodes << " own nodes differ";
    }
  }
  // The impact happened: the plate moves, and the step is not trivial.
  EXPECT_GT(one.energies().internal, 1e-3 * one.energies().kinetic);
}

}  // namespace
}  // namespace kessler::otm
