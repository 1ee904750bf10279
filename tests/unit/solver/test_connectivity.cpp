#include "solver/otm/connectivity.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>

namespace kessler::otm {
namespace {

// `points` rows of between `fewest` and `most` entries, each a random one of `nodes` nodes.
Connectivity randomRows(unsigned seed, int points, int fewest, int most, int nodes) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> count(fewest, most), node(0, nodes - 1);
  Connectivity c;
  c.offset.push_back(0);
  for (int p = 0; p < points; ++p) {
    const int n = count(rng);
    for (int k = 0; k < n; ++k) c.node.push_back(node(rng));
    c.offset.push_back(static_cast<Index>(c.node.size()));
  }
  return c;
}

// The transpose lists, for every node, exactly the entries that reference it, in increasing
// point order (the order the deterministic nodal gathers rely on).
TEST(Connectivity, TransposeListsEveryEntryInPointOrder) {
  Connectivity c = randomRows(5, 200, 1, 9, 50);
  c.buildTranspose(50);
  ASSERT_EQ(c.node_offset.back(), static_cast<Index>(c.node.size()));
  std::vector<int> seen(c.node.size(), 0);
  for (LocalIndex a = 0; a < 50; ++a) {
    LocalIndex previous = -1;
    for (Index k = c.node_offset[a]; k < c.node_offset[a + 1]; ++k) {
      const Index e = c.node_slot[k].entry;
      EXPECT_EQ(c.node[e], a);
      EXPECT_GE(c.node_slot[k].point, previous);
      EXPECT_GE(e, c.offset[c.node_slot[k].point]);
      EXPECT_LT(e, c.offset[c.node_slot[k].point + 1]);
      previous = c.node_slot[k].point;
      ++seen[e];
    }
  }
  for (int s : seen) EXPECT_EQ(s, 1);
}

// The transpose is built in parallel: any thread count gives the same arrays.
TEST(Connectivity, TransposeDoesNotDependOnTheThreadCount) {
  Connectivity c = randomRows(7, 1000, 0, 12, 100);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  c.buildTranspose(100);
  const Connectivity one = c;
  for (int t : {2, 3, 5}) {
    omp_set_num_threads(t);
    c.buildTranspose(100);
    EXPECT_EQ(c.node_offset, one.node_offset) << t << " threads";
    EXPECT_TRUE(c.node_slot == one.node_slot) << t << " threads";
  }
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace kessler::otm
