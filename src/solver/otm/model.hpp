#pragma once
// Everything the OTM integrator advances: nodes, material points, bodies and their materials.
#include "material/material.hpp"
#include "particles/connectivity.hpp"
#include "particles/store.hpp"

#include <array>
#include <vector>

namespace kessler::otm {

struct Model {
  NodeStore nodes;
  PointStore points;
  std::vector<BodyInfo> bodies;
  std::vector<MaterialPtr> materials;  // indexed by BodyInfo::material
  Connectivity connectivity;            // point-node neighbourhoods and shape functions
  // Pairs of points (global indices, i < j) whose initial tets share a face; fragments are the
  // connected components of intact material over these links (analysis/fragments.hpp).
  std::vector<std::array<LocalIndex, 2>> adjacency;
  std::vector<double> adjacency_length0;  // initial distance of each pair, same order
};

}  // namespace kessler::otm
