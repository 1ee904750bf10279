#pragma once
// A structured tetrahedral mesh of a box: n[0] x n[1] x n[2] cubes, each split into six
// tetrahedra around its main diagonal (Kuhn / Freudenthal triangulation). Deterministic and
// free of mesh-generator noise, for verification problems with controlled resolution.
#include "geometry/mesh.hpp"

namespace kessler::geometry {

TetMesh structuredBoxMesh(const Box& box, const std::array<int, 3>& cells);

}  // namespace kessler::geometry
