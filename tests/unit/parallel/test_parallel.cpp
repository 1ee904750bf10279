// The parallel layer on one process (parallel/communicator.hpp, partition.hpp, migrate.hpp): every
// collective is the identity and every point stays. The same code on 2 and 3 ranks is tested by
// tests/mpi under mpirun.
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/migrate.hpp"
#include "parallel/partition.hpp"
#include "particles/store.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace kessler::parallel {
namespace {

TEST(Communicator, OneProcessWithoutMpirun) {
  // The unit tests are not started by mpirun, so no Session starts MPI: one process.
  ASSERT_FALSE(launched());
  const Communicator& world = Communicator::world();
  EXPECT_EQ(world.size(), 1);
  EXPECT_EQ(world.rank(), 0);
  EXPECT_TRUE(world.root());
  EXPECT_EQ(world.sum(std::int64_t{42}), 42);
  EXPECT_EQ(world.min(2.5), 2.5);
  EXPECT_TRUE(world.any(true));
  EXPECT_FALSE(world.any(false));
  ExactSum sum;
  sum.add(1e16);
  sum.add(1.0);
  sum.add(-1e16);
  EXPECT_EQ(world.sum(sum), 1.0);
  const std::vector<std::vector<std::byte>> out{{std::byte{1}, std::byte{2}}};
  EXPECT_EQ(world.exchange(out), out);
  EXPECT_THROW(world.exchange({{}, {}}), Error);
  EXPECT_EQ(world.allGather(out[0]), out);
}

TEST(Partition, OneProcessOwnsEverything) {
  const std::vector<Vec3> x{Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-1, 0, 5)};
  const std::vector<Index> ids{0, 1, 2};
  const std::vector<double> work{1, 1, 1};
  Partition partition(Communicator::world());
  EXPECT_THROW(partition.owner(x[0]), Error);
  EXPECT_EQ(partition.balance(x, ids, work), std::vector<int>(3, 0));
  EXPECT_EQ(partition.owner(Vec3(100, 0, 0)), 0);
  EXPECT_EQ(partition.ranksMeeting(Vec3(-1, -1, -1), Vec3(1, 1, 1)), std::vector<int>{0});
  const Box box = partition.subdomain(0);
  EXPECT_EQ(box.lo, Vec3(-1, 0, 0));
  EXPECT_EQ(box.hi, Vec3(1, 2, 5));
  EXPECT_DOUBLE_EQ(imbalance(Communicator::world(), 3.0), 1.0);
  EXPECT_THROW(partition.balance(x, ids, std::vector<double>{1.0}), Error);
}

TEST(Migrate, OneProcessKeepsEveryEntryInOrder) {
  PointStore points;
  resizeFields(points, 4);
  for (LocalIndex p = 0; p < 4; ++p) {
    points.id[p] = 10 + p;
    points.x[p] = Vec3(p, 2.0 * p, -p);
    points.mass[p] = 0.5 + p;
  }
  const PointStore before = points;
  migrate(points, std::vector<int>(4, 0), Communicator::world());
  EXPECT_EQ(points.owned, 4);
  EXPECT_EQ(points.id, before.id);
  EXPECT_EQ(points.x, before.x);
  EXPECT_EQ(points.mass, before.mass);
  EXPECT_THROW(migrate(points, std::vector<int>{0, 0, 1, 0}, Communicator::world()), Error);
  EXPECT_THROW(migrate(points, std::vector<int>{0}, Communicator::world()), Error);
}

TEST(Halo, OneProcessHasNoGhosts) {
  PointStore points;
  resizeFields(points, 3);
  for (LocalIndex p = 0; p < 3; ++p) {
    points.x[p] = Vec3(p, 0, 0);
    points.id[p] = 5 + p;
  }
  Partition partition(Communicator::world());
  partition.balance(points.x, points.id, std::vector<double>(3, 1.0));
  Halo halo;
  std::vector<double> values{1, 2, 3};
  EXPECT_THROW(halo.refresh(values), Error);
  halo.build(points, partition, std::vector<double>(3, 10.0), Communicator::world());
  EXPECT_EQ(halo.ghosts(), 0);
  EXPECT_EQ(halo.sent(), 0u);
  EXPECT_EQ(points.x.size(), 3u);
  halo.refresh(values);
  EXPECT_EQ(values, (std::vector<double>{1, 2, 3}));
  std::vector<double> too_many(4, 0.0);
  EXPECT_THROW(halo.refresh(too_many), Error);
  halo.dropGhosts(points);
  EXPECT_EQ(points.owned, 3);
  std::swap(points.id[0], points.id[2]);  // out of id order: refused
  EXPECT_THROW(halo.build(points, partition, std::vector<double>(3, 10.0), Communicator::world()), Error);
}

TEST(Migrate, LeavesTheStoreInIdOrder) {
  PointStore points;
  resizeFields(points, 3);
  const Index ids[] = {7, 2, 5};
  for (LocalIndex p = 0; p < 3; ++p) {
    points.id[p] = ids[p];
    points.mass[p] = static_cast<double>(ids[p]);
  }
  migrate(points, std::vector<int>(3, 0), Communicator::world());
  EXPECT_EQ(points.id, (std::vector<Index>{2, 5, 7}));
  EXPECT_EQ(points.mass, (std::vector<double>{2, 5, 7}));
}

}  // namespace
}  // namespace kessler::parallel
