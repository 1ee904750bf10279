// Mesh -> OTM nodes and material points, and the selection of fixed boundary nodes.
#include "core/error.hpp"
#include "geometry/mesh.hpp"
#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kessler::geometry {
namespace {

using testing::meshRequest;

constexpr double mm = 1e-3;

TEST(Discretise, OneTetByHand) {
  const TetMesh mesh{{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 2)}, {{0, 1, 2, 3}}};
  const Discretisation d = discretise(mesh);
  ASSERT_EQ(d.points.size(), 1u);
  EXPECT_EQ(d.nodes, mesh.vertices);
  EXPECT_TRUE(d.points[0].isApprox(Vec3(0.5, 0.5, 0.5)));
  EXPECT_DOUBLE_EQ(d.volumes[0], 8.0 / 6.0);
  // Three edges of length 2 and three of 2 sqrt(2).
  EXPECT_DOUBLE_EQ(d.spacings[0], (3 * 2.0 + 3 * 2.0 * std::sqrt(2.0)) / 6.0);
}

TEST(Discretise, RefusesInvertedOrFlatTets) {
  const std::vector<Vec3> corners{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0)};
  EXPECT_THROW(discretise(TetMesh{corners, {{0, 1, 2, 3}, {0, 2, 1, 3}}}), InputError);
  EXPECT_THROW(discretise(TetMesh{corners, {{0, 1, 2, 4}}}), InputError);
}

TEST(Discretise, MeshedSphereConservesVolume) {
  const TetMesh mesh = meshShape(meshRequest(Sphere{Vec3(0, 0, 0), 3 * mm}, 1 * mm));
  const Discretisation d = discretise(mesh);
  ASSERT_EQ(d.points.size(), mesh.tets.size());
  EXPECT_EQ(d.nodes.size(), mesh.vertices.size());
  const double sum = std::accumulate(d.volumes.begin(), d.volumes.end(), 0.0);
  EXPECT_NEAR(sum, testing::totalVolume(mesh), 1e-12 * sum);
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    EXPECT_GT(d.volumes[p], 0.0);
    EXPECT_GT(d.spacings[p], 0.1 * mm);
    EXPECT_LT(d.spacings[p], 2 * mm);
  }
}

// Independent classification: on a face x_i = min_i or max_i for an axis i other than `normal`.
bool onLateralFace(const Box& box, int normal, const Vec3& x, double tol) {
  for (int i = 0; i < 3; ++i) {
    if (i != normal && (std::abs(x[i] - box.min[i]) < tol || std::abs(x[i] - box.max[i]) < tol)) return true;
  }
  return false;
}

void expectLateralSelection(const Box& box, int normal) {
  const TetMesh mesh = meshShape(meshRequest(box, 1.5 * mm));
  const std::vector<LocalIndex> fixed = selectNodes(box, mesh.vertices, FixedNodes::lateral_faces);
  std::vector<LocalIndex> expected;
  std::array<int, 6> per_face{};
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& x = mesh.vertices[v];
    if (onLateralFace(box, normal, x, 1e-12)) expected.push_back(static_cast<LocalIndex>(v));
    for (int i = 0; i < 3; ++i) {
      per_face[2 * i] += std::abs(x[i] - box.min[i]) < 1e-12;
      per_face[2 * i + 1] += std::abs(x[i] - box.max[i]) < 1e-12;
    }
  }
  EXPECT_EQ(fixed, expected);
  EXPECT_TRUE(std::is_sorted(fixed.begin(), fixed.end()));
  // Every face holds mesh nodes exactly on it, so the selection is not vacuous; nodes only on
  // the two faces normal to the thin direction are not selected.
  for (const int count : per_face) EXPECT_GT(count, 4);
  EXPECT_LT(fixed.size(), mesh.vertices.size());
  for (const LocalIndex v : fixed) EXPECT_TRUE(onLateralFace(box, normal, mesh.vertices[v], 1e-12));
}

TEST(SelectNodes, PlateLateralFacesAreTheFourAroundTheThinDirection) {
  expectLateralSelection(Box{Vec3(-6 * mm, -5 * mm, -2 * mm), Vec3(6 * mm, 5 * mm, 0)}, 2);
  // A plate standing in the yz-plane: thin along x.
  expectLateralSelection(Box{Vec3(0, -5 * mm, -4 * mm), Vec3(2 * mm, 5 * mm, 4 * mm)}, 0);
}

TEST(SelectNodes, CylinderSideSurface) {
  const Cylinder rod{Vec3(1 * mm, 2 * mm, -3 * mm), Vec3(3 * mm, 4 * mm, 12 * mm), 2 * mm};
  const TetMesh mesh = meshShape(meshRequest(rod, 1 * mm));
  const std::vector<LocalIndex> fixed = selectNodes(rod, mesh.vertices, FixedNodes::lateral_faces);
  const Vec3 n = rod.axis.normalized();
  std::vector<LocalIndex> expected;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3 d = mesh.vertices[v] - rod.base;
    if (std::abs((d - d.dot(n) * n).norm() - rod.radius) < 1e-9 * mm) {
      expected.push_back(static_cast<LocalIndex>(v));
    }
  }
  EXPECT_EQ(fixed, expected);
  // The side holds roughly (2 pi r L) / (h^2 sqrt(3)/4) / 2 nodes; cap centres are not on it.
  EXPECT_GT(fixed.size(), 150u);
  EXPECT_LT(fixed.size(), mesh.vertices.size());
}

TEST(SelectNodes, NoneAndInapplicableShapes) {
  const std::vector<Vec3> nodes{Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_TRUE(selectNodes(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}, nodes, FixedNodes::none).empty());
  EXPECT_TRUE(selectNodes(Sphere{Vec3(0, 0, 0), 1.0}, nodes, FixedNodes::none).empty());
  EXPECT_THROW(selectNodes(Sphere{Vec3(0, 0, 0), 1.0}, nodes, FixedNodes::lateral_faces), InputError);
  EXPECT_THROW(selectNodes(MeshFile{"a.msh", 1.0}, nodes, FixedNodes::lateral_faces), InputError);
}

}  // namespace
}  // namespace kessler::geometry
