// Face adjacency of the material points (Discretisation::adjacency), against brute force.
#include "core/error.hpp"
#include "geometry/mesh.hpp"
#include "geometry/structured_mesh.hpp"
#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace kessler::geometry {
namespace {

// Brute force: every pair of tets, adjacent when they have three vertices in common.
std::set<std::array<LocalIndex, 2>> bruteForcePairs(const TetMesh& mesh) {
  std::set<std::array<LocalIndex, 2>> pairs;
  for (std::size_t a = 0; a < mesh.tets.size(); ++a) {
    for (std::size_t b = a + 1; b < mesh.tets.size(); ++b) {
      int common = 0;
      for (const LocalIndex u : mesh.tets[a])
        common += static_cast<int>(std::count(mesh.tets[b].begin(), mesh.tets[b].end(), u));
      if (common == 3) pairs.insert({static_cast<LocalIndex>(a), static_cast<LocalIndex>(b)});
    }
  }
  return pairs;
}

TEST(Adjacency, TwoTetsSharingAFace) {
  const TetMesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)},
                     {{0, 1, 2, 3}, {0, 2, 1, 4}}};
  const Discretisation d = discretise(mesh);
  ASSERT_EQ(d.adjacency.size(), 1u);
  EXPECT_EQ(d.adjacency[0], (std::array<LocalIndex, 2>{0, 1}));
}

TEST(Adjacency, StructuredBoxMatchesBruteForceAndFaceCount) {
  const std::array<int, 3> cells{3, 4, 2};
  const TetMesh mesh = structuredBoxMesh(Box{Vec3(0, 0, 0), Vec3(3, 4, 2)}, cells);
  const Discretisation d = discretise(mesh);
  const std::set<std::array<LocalIndex, 2>> listed(d.adjacency.begin(), d.adjacency.end());
  EXPECT_EQ(listed.size(), d.adjacency.size()) << "a pair is listed twice";
  for (const auto& [i, j] : d.adjacency) EXPECT_LT(i, j);
  EXPECT_EQ(listed, bruteForcePairs(mesh));
  // Interior faces: 4 per tet, minus the boundary triangles (two per boundary square), halved.
  const int tets = 6 * cells[0] * cells[1] * cells[2];
  const int boundary = 4 * (cells[0] * cells[1] + cells[1] * cells[2] + cells[0] * cells[2]);
  EXPECT_EQ(static_cast<int>(d.adjacency.size()), (4 * tets - boundary) / 2);
}

TEST(Adjacency, MeshedSphereMatchesBruteForce) {
  const TetMesh mesh = meshShape(testing::meshRequest(Sphere{Vec3(0, 0, 0), 2e-3}, 1e-3));
  const Discretisation d = discretise(mesh);
  const std::set<std::array<LocalIndex, 2>> listed(d.adjacency.begin(), d.adjacency.end());
  EXPECT_EQ(listed.size(), d.adjacency.size());
  EXPECT_EQ(listed, bruteForcePairs(mesh));
}

TEST(Adjacency, RefusesAFaceSharedByThreeTets) {
  const TetMesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 1, 1)},
                     {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}}};
  EXPECT_THROW(discretise(mesh), InputError);
}

}  // namespace
}  // namespace kessler::geometry
