#include "search/cell_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace kessler {
namespace {

std::vector<Vec3> randomCloud(int n, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<Vec3> x(n);
  for (Vec3& v : x) v = Vec3(u(rng), u(rng), 0.3 * u(rng));
  return x;
}

// Oracle: the cell list returns exactly the brute-force neighbours, for radii smaller and
// larger than the cell size, and in a fixed order: cell by cell (x fastest, then y, then z) and
// by slot within a cell, which is what keeps the rows, and so the runs, identical for any thread
// count. The order's reference walks the cells one by one; the query scans whole rows of cells
// and filters them through a bit mask (runs longer than its 64-position chunks, and of every
// length modulo 4, occur at the larger radii).
TEST(CellList, MatchesBruteForceInCellThenSlotOrder) {
  const std::vector<Vec3> x = randomCloud(3000, 7, 1.0);
  const std::vector<Vec3> queries = randomCloud(200, 11, 1.2);
  CellList cells;
  cells.build(x, static_cast<LocalIndex>(x.size()), 0.1);
  for (double radius : {0.03, 0.1, 0.27, 0.9}) {
    for (const Vec3& q : queries) {
      std::vector<LocalIndex> found;
      cells.forEachWithin(q, radius, [&](LocalIndex a, double d2) {
        EXPECT_NEAR(d2, (x[a] - q).squaredNorm(), 1e-15);
        found.push_back(a);
      });
      std::vector<LocalIndex> in_order;
      cells.forEachCellNear(q, radius, [&](long cell) {
        for (LocalIndex slot = cells.cellBegin(cell); slot < cells.cellEnd(cell); ++slot)
          if ((x[cells.indexAt(slot)] - q).squaredNorm() <= radius * radius) in_order.push_back(cells.indexAt(slot));
      });
      ASSERT_EQ(found, in_order) << "radius " << radius;
      std::vector<LocalIndex> expected;
      for (LocalIndex a = 0; a < static_cast<LocalIndex>(x.size()); ++a)
        if ((x[a] - q).norm() <= radius) expected.push_back(a);
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, expected) << "radius " << radius;
    }
  }
}

// A rank of a distributed run holds a subset of the positions, in the same relative order, with a
// different bounding box. Its cells lie on the same lattice (given the cell size), so a query meets
// its candidates in the same order as over the whole set: the sums over them agree bitwise. With
// cells anchored at each set's own corner (as before 2026-11-27) this test fails.
TEST(CellList, ASubsetMeetsItsCandidatesInTheWholeSetsOrder) {
  const std::vector<Vec3> x = randomCloud(3000, 5, 1.0);
  std::vector<Vec3> subset;
  std::vector<LocalIndex> whole_index;  // of each subset entry
  for (LocalIndex a = 0; a < static_cast<LocalIndex>(x.size()); ++a)
    if (x[a][0] > -0.37 && x[a][1] < 0.61) {
      subset.push_back(x[a]);
      whole_index.push_back(a);
    }
  CellList whole, part;
  whole.build(x, static_cast<LocalIndex>(x.size()), 0.113);
  part.build(subset, static_cast<LocalIndex>(subset.size()), 0.113);
  const double radius = 0.19;
  int compared = 0;
  for (const Vec3& q : randomCloud(300, 13, 1.0)) {
    if (q[0] - radius <= -0.37 || q[1] + radius >= 0.61) continue;  // every candidate in the subset
    std::vector<LocalIndex> from_whole, from_part;
    whole.forEachWithin(q, radius, [&](LocalIndex a, double) { from_whole.push_back(a); });
    part.forEachWithin(q, radius, [&](LocalIndex k, double) { from_part.push_back(whole_index[k]); });
    ASSERT_EQ(from_part, from_whole);
    ++compared;
  }
  EXPECT_GT(compared, 50);
}

// A few far-away positions must not blow the grid up; queries stay correct.
TEST(CellList, SparseOutliersStayCorrect) {
  std::vector<Vec3> x = randomCloud(500, 3, 1.0);
  x.push_back(Vec3(1e4, 0, 0));
  x.push_back(Vec3(-1e4, 5e3, 2e3));
  CellList cells;
  cells.build(x, static_cast<LocalIndex>(x.size()), 0.01);
  EXPECT_GT(cells.cellSize(), 0.01);
  int hits = 0;
  cells.forEachWithin(Vec3(1e4, 0, 0), 1.0, [&](LocalIndex a, double) { hits += a == 500; });
  EXPECT_EQ(hits, 1);
}

}  // namespace
}  // namespace kessler
