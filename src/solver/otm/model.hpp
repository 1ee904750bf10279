#pragma once
// Everything the OTM integrator advances: the shared particle state (material points, bodies,
// materials, links) and OTM's own discretisation, the nodes and the point-node neighbourhoods.
#include "particles/store.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/otm/connectivity.hpp"
#include "solver/otm/node_store.hpp"

namespace kessler::otm {

// A face of a body's tetrahedra, for the sliding contact (solver/common/sliding_contact.hpp): its
// nodes, counter-clockwise seen from outside `inner`, and the points on its two sides (ids; outer
// -1 on the body's boundary). It is part of the surface while exactly one side is intact material.
struct ContactFace {
  std::array<Index, 3> nodes{};
  Index inner = 0, outer = -1;
};

struct Model : ParticleState {
  NodeStore nodes;
  Connectivity connectivity;  // point-node neighbourhoods and shape functions
  // Per point: the LME Lagrange multiplier of its last solve, the warm start of the next (sized
  // and reordered with the points; zero is a valid start).
  std::vector<Vec3> lme_lambda;
  // Every face of the bodies' tetrahedra but those on a symmetry plane or roller (dropHeldFaces);
  // only with a sliding contact.
  std::vector<ContactFace> faces;
};

}  // namespace kessler::otm
