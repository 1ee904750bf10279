#include "geometry/structured_mesh.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace kessler::geometry {

TetMesh structuredBoxMesh(const Box& box, const std::array<int, 3>& cells) {
  KESSLER_VERIFY(cells[0] > 0 && cells[1] > 0 && cells[2] > 0, "structured mesh needs at least one cell per direction");
  const Vec3 size = box.max - box.min;
  KESSLER_VERIFY((size.array() > 0.0).all(), "structured mesh of an empty box");
  const std::array<int, 3> n{cells[0] + 1, cells[1] + 1, cells[2] + 1};
  auto vertex = [&](int i, int j, int k) { return static_cast<LocalIndex>((k * n[1] + j) * n[0] + i); };

  TetMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        mesh.vertices.push_back(box.min + Vec3(size[0] * i / cells[0], size[1] * j / cells[1], size[2] * k / cells[2]));

  // The six paths from corner (0,0,0) to (1,1,1) along the axes, one tet each.
  std::array<int, 3> order{0, 1, 2};
  std::vector<std::array<int, 3>> permutations;
  do permutations.push_back(order);
  while (std::next_permutation(order.begin(), order.end()));

  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
        for (const auto& perm : permutations) {
          std::array<int, 3> c{i, j, k};
          std::array<LocalIndex, 4> tet{};
          tet[0] = vertex(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[perm[s]];
            tet[s + 1] = vertex(c[0], c[1], c[2]);
          }
          const Vec3& x0 = mesh.vertices[tet[0]];
          Mat3 edges;
          for (int s = 0; s < 3; ++s) edges.col(s) = mesh.vertices[tet[s + 1]] - x0;
          if (edges.determinant() < 0.0) std::swap(tet[2], tet[3]);
          mesh.tets.push_back(tet);
        }
  return mesh;
}

}  // namespace kessler::geometry
