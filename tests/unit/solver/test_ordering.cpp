// Morton ordering of points and nodes (solver/otm/morton_order.hpp): a permutation within
// each body's ranges, keys in increasing order, the mesh adjacency (by point id) left as it was, the
// ids then numbered in that order, and the transpose built in parallel identical for any thread count.
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/morton_order.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <map>
#include <utility>

namespace kessler::otm {
namespace {

Model twoBodies() {
  NeoHookeanParameters p;
  p.density = 2700.0;
  p.youngs_modulus = 70e9;
  p.poisson_ratio = 0.33;
  auto material = std::make_shared<NeoHookean>("al", p);
  Model model;
  addBody(model, "a", material,
          geometry::discretise(
              geometry::structuredBoxMesh(geometry::Box{Vec3(0, 0, 0), Vec3(4e-3, 3e-3, 2e-3)}, {4, 3, 2})),
          Vec3::Zero());
  addBody(model, "b", material,
          geometry::discretise(
              geometry::structuredBoxMesh(geometry::Box{Vec3(0, 0, 3e-3), Vec3(2e-3, 2e-3, 5e-3)}, {2, 2, 2})),
          Vec3(0, 0, -10.0));
  return model;
}

TEST(Ordering, PermutesWithinBodiesAlongTheMortonCurve) {
  Model model = twoBodies();
  const Model before = model;
  sortForLocality(model);
  ASSERT_EQ(model.points.size(), before.points.size());
  ASSERT_EQ(model.nodes.size(), before.nodes.size());
  Vec3 lo = model.nodes.x[0], hi = model.nodes.x[0];
  for (const Vec3& x : model.nodes.x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::map<Index, LocalIndex> old_point;
  for (LocalIndex p = 0; p < before.points.size(); ++p) old_point[before.points.id[p]] = p;
  const std::vector<IndexRange> node_ranges = bodyRanges(model.nodes.body, model.nodes.size(), model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const IndexRange body = bodyRanges(before.points.body, before.points.size(), model.bodies.size())[b];
    EXPECT_EQ(bodyRanges(model.points.body, model.points.size(), model.bodies.size())[b].begin, body.begin);
    for (LocalIndex p = body.begin; p < body.end; ++p) {
      const LocalIndex q = old_point.at(model.points.id[p]);
      EXPECT_GE(q, body.begin);
      EXPECT_LT(q, body.end);
      EXPECT_EQ(model.points.x[p], before.points.x[q]);
      EXPECT_EQ(model.points.mass[p], before.points.mass[q]);
      if (p > body.begin) {
        EXPECT_LE(mortonKey(model.points.x[p - 1], lo, hi), mortonKey(model.points.x[p], lo, hi));
      }
    }
    for (LocalIndex a = node_ranges[b].begin + 1; a < node_ranges[b].end; ++a)
      EXPECT_LE(mortonKey(model.nodes.x[a - 1], lo, hi), mortonKey(model.nodes.x[a], lo, hi));
  }
  // The adjacency links points by id: the sort leaves it as it was.
  EXPECT_EQ(model.adjacency, before.adjacency);

  // Numbered in that order: ids 0, 1, ... and each link still joins the same two points.
  const Model sorted = model;
  numberInOrder(model);
  for (LocalIndex p = 0; p < model.points.size(); ++p) EXPECT_EQ(model.points.id[p], p);
  for (LocalIndex a = 0; a < model.nodes.size(); ++a) EXPECT_EQ(model.nodes.id[a], a);
  ASSERT_EQ(model.adjacency.size(), sorted.adjacency.size());
  const IdIndex old_index(sorted.points.id);
  for (std::size_t k = 0; k < model.adjacency.size(); ++k) {
    const auto [i, j] = model.adjacency[k];
    EXPECT_LT(i, j);
    const Vec3 a = sorted.points.x[old_index.find(sorted.adjacency[k][0])];
    const Vec3 b = sorted.points.x[old_index.find(sorted.adjacency[k][1])];
    EXPECT_TRUE((model.points.x[i] == a && model.points.x[j] == b) ||
                (model.points.x[i] == b && model.points.x[j] == a));
  }
}

TEST(Ordering, MortonKeyInterleavesTheAxes) {
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Ones();
  EXPECT_EQ(mortonKey(Vec3(0, 0, 0), lo, hi), 0u);
  EXPECT_EQ(mortonKey(Vec3(1, 0, 0), lo, hi), 0x1249249249249249ULL);
  EXPECT_EQ(mortonKey(Vec3(0, 1, 0), lo, hi), 0x1249249249249249ULL << 1);
  EXPECT_EQ(mortonKey(Vec3(0, 0, 1), lo, hi), 0x1249249249249249ULL << 2);
}

}  // namespace
}  // namespace kessler::otm
