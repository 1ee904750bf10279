#pragma once
// Everything the OTM integrator advances: the shared particle state (material points, bodies,
// materials, links) and OTM's own discretisation, the nodes and the point-node neighbourhoods.
#include "particles/store.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/otm/connectivity.hpp"
#include "solver/otm/node_store.hpp"

namespace kessler::otm {

struct Model : ParticleState {
  NodeStore nodes;
  Connectivity connectivity;  // point-node neighbourhoods and shape functions
  // Per point: the LME Lagrange multiplier of its last solve, the warm start of the next (sized
  // and reordered with the points; zero is a valid start).
  std::vector<Vec3> lme_lambda;
};

}  // namespace kessler::otm
