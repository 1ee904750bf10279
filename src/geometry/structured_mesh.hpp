#pragma once
// A structured tetrahedral mesh of a box: n[0] x n[1] x n[2] cubes, each split into six
// tetrahedra around its main diagonal (Kuhn / Freudenthal triangulation). Deterministic and
// free of mesh-generator noise, for verification problems with controlled resolution.
#include "geometry/mesh.hpp"

namespace kessler::geometry {

TetMesh structuredBoxMesh(const Box& box, const std::array<int, 3>& cells);

// A box of n[0] x n[1] x n[2] cells, which each method discretises its own way (OTM: the Kuhn tets
// above; SPH: one particle per cell, geometry/lattice.hpp): verification problems with a controlled
// resolution that every method runs.
struct StructuredBox {
  Box box;
  std::array<int, 3> cells{1, 1, 1};
};

}  // namespace kessler::geometry
