#pragma once
// What every particle method advances and every later stage reads (analysis, output): the
// material points grouped by body, the bodies' materials, and the links between points that were
// neighbours in the initial mesh. A method keeps its own discretisation beside it (OTM: nodes and
// the point-node connectivity, solver/otm/model.hpp).
#include "material/material.hpp"
#include "particles/store.hpp"

#include <array>
#include <vector>

namespace kessler {

struct ParticleState {
  PointStore points;
  std::vector<BodyInfo> bodies;
  std::vector<MaterialPtr> materials;  // indexed by BodyInfo::material
  // Pairs of points whose initial tets share a face (OTM), or whose lattice elements share a node
  // (SPH, solver/sph/reconstruction.hpp), by id (PointStore::id: the same on every
  // process and in any order of the store), i < j; fragments are the connected components of
  // intact material over these links (analysis/fragments.hpp).
  std::vector<std::array<Index, 2>> adjacency;
  std::vector<double> adjacency_length0;  // initial distance of each pair, same order
};

// The points numbered 0, 1, ... in store order, once, when a model is built (after a sort for
// locality, search/morton.hpp); the adjacency (by point id) follows.
void numberPointsInOrder(ParticleState& state);

}  // namespace kessler
