// The parallel layer on several ranks (run by mpirun with 2 and 3 ranks; tests/mpi/CMakeLists.txt):
// collectives, exact sums that do not depend on how the terms are split among ranks, Zoltan's
// subdomains, and the migration of points into them and back.
#include "../wide_terms.hpp"
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/migrate.hpp"
#include "parallel/partition.hpp"
#include "particles/store.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace kessler::parallel {
namespace {

const Communicator& world() {
  return Communicator::world();
}

TEST(Ranks, StartedByMpirunOnSeveralRanks) {
  EXPECT_TRUE(launched());
  EXPECT_GE(world().size(), 2);
  EXPECT_EQ(world().sum(std::int64_t{world().rank()}), world().size() * (world().size() - 1) / 2);
  EXPECT_EQ(world().min(10.0 + world().rank()), 10.0);
  EXPECT_EQ(world().max(10.0 + world().rank()), 10.0 + world().size() - 1);
  EXPECT_TRUE(world().any(world().rank() == world().size() - 1));
  EXPECT_FALSE(world().any(false));
}

// Rank r sends rank s r + s + 1 bytes, each r * 16 + s.
TEST(Ranks, ExchangeDeliversEachPairsBytes) {
  const int n = world().size(), me = world().rank();
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) out[s].assign(static_cast<std::size_t>(me + s + 1), std::byte(me * 16 + s));
  const auto in = world().exchange(out);
  ASSERT_EQ(in.size(), static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r)
    EXPECT_EQ(in[r], std::vector<std::byte>(static_cast<std::size_t>(r + me + 1), std::byte(r * 16 + me)));
  const std::vector<std::byte> mine(static_cast<std::size_t>(me), std::byte(me));
  const auto all = world().allGather(mine);
  for (int r = 0; r < n; ++r) EXPECT_EQ(all[r], std::vector<std::byte>(static_cast<std::size_t>(r), std::byte(r)));
}

// Around a ring, with no collective: rank r sends r + 1 bytes of value r to the next rank only.
TEST(Ranks, MessagesBetweenNeighboursOnly) {
  const int n = world().size(), me = world().rank();
  const int next = (me + 1) % n, previous = (me + n - 1) % n;
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(n)), in(static_cast<std::size_t>(n));
  out[next].assign(static_cast<std::size_t>(me + 1), std::byte(me));
  in[previous].resize(static_cast<std::size_t>(previous + 1));
  const std::vector<int> to{next}, from{previous};
  world().exchangeWith(to, out, from, in);
  EXPECT_EQ(in[previous], std::vector<std::byte>(static_cast<std::size_t>(previous + 1), std::byte(previous)));
}

// The same 30,000 terms over 600 orders of magnitude, split among the ranks two ways (dealt round,
// and in blocks): the global sum has the bits of one process's sum of them all.
TEST(Ranks, ExactSumIndependentOfTheSplit) {
  const std::vector<double> terms = testing::wideRangeTerms(30000, 3);
  ExactSum all;
  for (double t : terms) all.add(t);
  const double reference = all.value();
  const std::size_t n = static_cast<std::size_t>(world().size()), me = static_cast<std::size_t>(world().rank());
  ExactSum dealt, block;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (i % n == me) dealt.add(terms[i]);
    if (i * n / terms.size() == me) block.add(terms[i]);
  }
  EXPECT_EQ(world().sum(dealt), reference);
  EXPECT_EQ(world().sum(block), reference);
}

// A lattice of points, all on rank 0 at first, with more work in one corner (as an impact zone).
PointStore lattice() {
  PointStore points;
  if (!world().root()) return points;
  const int nx = 24, ny = 14, nz = 9;
  resizeFields(points, static_cast<std::size_t>(nx * ny * nz));
  LocalIndex p = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++p) {
        points.id[p] = 1000 + 7 * p;  // sparse, as after erosion
        points.x[p] = Vec3(0.1 * i, 0.1 * j, 0.1 * k) + Vec3(1e-3 * std::sin(p), 1e-3 * std::cos(p), 0.0);
        points.v[p] = Vec3(p, -p, 0.5 * p);
        points.mass[p] = 1.0 + 1e-3 * p;
        points.body[p] = i < nx / 2 ? 0 : 1;
        points.F[p] = Mat3::Identity() * (1.0 + 1e-4 * p);
      }
  return points;
}

double workOf(const Vec3& x) {
  return x[0] < 0.6 && x[1] < 0.6 ? 4.0 : 1.0;
}

std::vector<double> work(const PointStore& points) {
  std::vector<double> w(static_cast<std::size_t>(points.owned));
  for (LocalIndex p = 0; p < points.owned; ++p) w[p] = workOf(points.x[p]);
  return w;
}

// Every rank's values, in rank order, on every rank.
template <class T>
std::vector<std::vector<T>> gather(const std::vector<T>& mine) {
  std::vector<std::byte> bytes(mine.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
  std::vector<std::vector<T>> all;
  for (const auto& theirs : world().allGather(bytes)) {
    all.emplace_back(theirs.size() / sizeof(T));
    if (!theirs.empty()) std::memcpy(static_cast<void*>(all.back().data()), theirs.data(), theirs.size());
  }
  return all;
}

// Each point on exactly one rank, the rank whose subdomain holds it; the work shared evenly.
void expectDistributed(const Partition& partition, const PointStore& points, Index total) {
  const int me = world().rank();
  double mine = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    EXPECT_EQ(partition.owner(points.x[p]), me) << "point " << points.id[p] << " at " << points.x[p].transpose();
    EXPECT_TRUE(partition.subdomain(me).contains(points.x[p]));
    const std::vector<int> meeting = partition.ranksMeeting(points.x[p], points.x[p]);
    EXPECT_NE(std::find(meeting.begin(), meeting.end(), me), meeting.end());
    mine += workOf(points.x[p]);
  }
  EXPECT_EQ(world().sum(std::int64_t{points.owned}), total);
  std::vector<Index> all;
  for (const auto& ids : gather(points.id)) all.insert(all.end(), ids.begin(), ids.end());
  std::sort(all.begin(), all.end());
  EXPECT_EQ(std::adjacent_find(all.begin(), all.end()), all.end()) << "a point on two ranks";
  EXPECT_EQ(static_cast<Index>(all.size()), total);
  // RCB cuts the work to within a point's share or so.
  EXPECT_LT(imbalance(world(), mine), 1.05);
}

TEST(Ranks, PointsMigrateIntoTheirSubdomainsAndBackBitwise) {
  const PointStore original = lattice();
  const Index total = world().sum(std::int64_t{original.owned});
  PointStore points = original;
  Partition partition(world());
  std::vector<int> owner = partition.balance(points.x, points.id, work(points));
  migrate(points, owner, world());
  expectDistributed(partition, points, total);
  EXPECT_GT(points.owned, 0);

  // Neighbouring subdomains meet: a box around the cut between them names both.
  const Box mine = partition.subdomain(world().rank());
  const Vec3 centre = 0.5 * (mine.lo + mine.hi);
  const std::vector<int> all_ranks =
      partition.ranksMeeting(centre - Vec3::Constant(10.0), centre + Vec3::Constant(10.0));
  EXPECT_EQ(static_cast<int>(all_ranks.size()), world().size());

  // The points move (as in a run) and are balanced again.
  for (LocalIndex p = 0; p < points.owned; ++p) points.x[p] += Vec3(0.3 * points.x[p][1], 0.0, -0.2);
  owner = partition.balance(points.x, points.id, work(points));
  migrate(points, owner, world());
  expectDistributed(partition, points, total);

  // Everything back to rank 0 (migrate leaves it in id order) and undone: bitwise the original.
  migrate(points, std::vector<int>(static_cast<std::size_t>(points.owned), 0), world());
  if (!world().root()) {
    EXPECT_EQ(points.owned, 0);
    return;
  }
  ASSERT_EQ(points.owned, original.owned);
  for (LocalIndex p = 0; p < points.owned; ++p) points.x[p] -= Vec3(0.3 * original.x[p][1], 0.0, -0.2);
  EXPECT_EQ(points.id, original.id);
  EXPECT_EQ(points.v, original.v);
  EXPECT_EQ(points.mass, original.mass);
  EXPECT_EQ(points.body, original.body);
  EXPECT_EQ(points.F, original.F);
  for (LocalIndex p = 0; p < points.owned; ++p) EXPECT_NEAR((points.x[p] - original.x[p]).norm(), 0.0, 1e-15);
}

// Ghosts: on each rank exactly the other ranks' points whose box x +- (1 + skin) reach meets its
// subdomain (found here by brute force over every point), in the order of the rank they come from;
// a refresh brings their owners' values. A build again keeps them while they hold every entry
// needed, and fetches afresh once they do not.
TEST(Ranks, HaloHoldsExactlyTheEntriesThatReachTheSubdomain) {
  PointStore points = lattice();
  Partition partition(world());
  migrate(points, partition.balance(points.x, points.id, work(points)), world());
  for (LocalIndex p = 1; p < points.owned; ++p) ASSERT_LT(points.id[p - 1], points.id[p]) << "migrate: id order";
  const LocalIndex own = points.owned;
  std::vector<double> reach(static_cast<std::size_t>(own));
  for (LocalIndex p = 0; p < own; ++p) reach[p] = points.id[p] % 3 == 0 ? 0.1851 : 0.1234;

  // The brute-force answer, from every rank's own points.
  const Box mine = partition.subdomain(world().rank());
  const auto ids = gather(points.id);
  const auto positions = gather(points.x);
  auto within = [&](double scale) {
    const auto reaches = gather(reach);
    std::vector<Index> found;
    for (int r = 0; r < world().size(); ++r) {
      if (r == world().rank()) continue;
      for (std::size_t i = 0; i < positions[r].size(); ++i) {
        const Vec3 lo = positions[r][i] - Vec3::Constant(scale * reaches[r][i]),
                   hi = positions[r][i] + Vec3::Constant(scale * reaches[r][i]);
        if ((lo.array() <= mine.hi.array()).all() && (hi.array() >= mine.lo.array()).all()) found.push_back(ids[r][i]);
      }
    }
    std::sort(found.begin(), found.end());
    return found;
  };
  const std::vector<Index> expected = within(1.0 + Halo::skin);

  Halo halo;
  halo.build(points, partition, reach, world());
  ASSERT_EQ(halo.ghosts(), static_cast<LocalIndex>(expected.size()));
  EXPECT_GT(halo.ghosts(), 0);
  EXPECT_EQ(points.owned, own + halo.ghosts());
  // Ghosts among the own entries, the whole store in id order.
  std::vector<Index> ghost_ids;
  LocalIndex own_count = 0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (p > 0) {
      EXPECT_LT(points.id[p - 1], points.id[p]);
    }
    if (halo.ghost(p))
      ghost_ids.push_back(points.id[p]);
    else
      ++own_count;
  }
  EXPECT_EQ(ghost_ids, expected);
  EXPECT_EQ(own_count, own);
  EXPECT_EQ(world().sum(static_cast<std::int64_t>(halo.sent())), world().sum(std::int64_t{halo.ghosts()}));
  EXPECT_GE(halo.neighbours(), 1);

  std::vector<double> value(points.x.size(), -1.0);
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (!halo.ghost(p)) value[p] = 0.5 + 2.0 * static_cast<double>(points.id[p]);
  halo.refresh(value);
  for (LocalIndex p = 0; p < points.owned; ++p) EXPECT_EQ(value[p], 0.5 + 2.0 * static_cast<double>(points.id[p]));

  // Built again over the ghosts (as a step does): they hold all that is needed, so they stay in
  // their slots and take their owners' values afresh.
  const std::vector<Index> held = points.id;
  const std::vector<double> mass = points.mass;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (halo.ghost(p)) points.mass[p] = -2.0;  // stale: the new build fetches the owner's value
  ASSERT_EQ(halo.ownEntries(points).size(), static_cast<std::size_t>(own));
  halo.build(points, partition, reach, world());
  EXPECT_EQ(halo.fetches(), 1);
  EXPECT_EQ(halo.keeps(), 1);
  EXPECT_EQ(points.id, held);
  EXPECT_EQ(points.mass, mass);
  EXPECT_EQ(halo.ghosts(), static_cast<LocalIndex>(expected.size()));
  // Reaches grown past the skin: the ghosts no longer hold all that is needed, and are fetched
  // afresh (on every rank) within the new reaches and their skin.
  for (double& r : reach) r *= 3.0;
  const std::vector<Index> wider = within(1.0 + Halo::skin);
  EXPECT_GT(wider.size(), expected.size());
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (halo.ghost(p)) points.mass[p] = -2.0;
  halo.build(points, partition, reach, world());
  EXPECT_EQ(halo.fetches(), 2);
  EXPECT_EQ(halo.ghosts(), static_cast<LocalIndex>(wider.size()));
  std::vector<Index> ghost_ids_now;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (halo.ghost(p)) {
      ghost_ids_now.push_back(points.id[p]);
      EXPECT_GT(points.mass[p], 0.0);
    }
  EXPECT_EQ(ghost_ids_now, wider);
  for (double& r : reach) r /= 3.0;
  // Dropped (before a migration): the own entries stay, in order.
  halo.dropGhosts(points);
  EXPECT_EQ(points.owned, own);
  EXPECT_EQ(points.id, ids[static_cast<std::size_t>(world().rank())]);
  halo.build(points, partition, reach, world());
  EXPECT_EQ(halo.ghosts(), static_cast<LocalIndex>(expected.size()));
  // Reaches for another count of own entries than the store holds: refused before any message.
  EXPECT_THROW(halo.build(points, partition, std::vector<double>(reach.size() + 1, 0.1), world()), Error);
}

}  // namespace
}  // namespace kessler::parallel
