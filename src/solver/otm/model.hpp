#pragma once
// Everything the OTM integrator advances: nodes, material points, bodies and their materials.
#include "material/material.hpp"
#include "particles/connectivity.hpp"
#include "particles/store.hpp"

#include <vector>

namespace kessler::otm {

struct Model {
  NodeStore nodes;
  PointStore points;
  std::vector<BodyInfo> bodies;
  std::vector<MaterialPtr> materials;  // indexed by BodyInfo::material
  Connectivity connectivity;            // point-node neighbourhoods and shape functions
};

}  // namespace kessler::otm
