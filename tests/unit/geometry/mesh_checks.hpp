#pragma once
// Independent checks on tetrahedral meshes shared by the geometry tests.
#include "geometry/mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>  // cross products; core/types.hpp has only Core and LU

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace kessler::geometry::testing {

// GCC 12 flags designated initialisers that leave members out (-Wmissing-field-initializers),
// so the tests build their requests here.
inline MeshRequest meshRequest(Shape shape, double mesh_size, std::vector<int> symmetry_axes = {},
                               std::optional<Refinement> refine = std::nullopt) {
  MeshRequest request;
  request.shape = std::move(shape);
  request.mesh_size = mesh_size;
  request.refine = std::move(refine);
  request.symmetry_axes = std::move(symmetry_axes);
  return request;
}

inline double signedVolume(const TetMesh& mesh, const std::array<LocalIndex, 4>& t) {
  const Vec3& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).dot((mesh.vertices[t[2]] - a).cross(mesh.vertices[t[3]] - a)) / 6.0;
}

inline double totalVolume(const TetMesh& mesh) {
  double sum = 0.0;
  for (const auto& t : mesh.tets) sum += signedVolume(mesh, t);
  return sum;
}

// Every tet positively oriented, every index in range, every vertex used by some tet.
inline void expectWellFormed(const TetMesh& mesh) {
  ASSERT_FALSE(mesh.tets.empty());
  std::vector<char> used(mesh.vertices.size(), 0);
  int non_positive = 0;
  int out_of_range = 0;
  for (const auto& t : mesh.tets) {
    for (const LocalIndex v : t) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
        ++out_of_range;
      } else {
        used[v] = 1;
      }
    }
    if (out_of_range == 0 && !(signedVolume(mesh, t) > 0.0)) ++non_positive;
  }
  EXPECT_EQ(out_of_range, 0);
  EXPECT_EQ(non_positive, 0);
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "unused vertices";
}

}  // namespace kessler::geometry::testing
