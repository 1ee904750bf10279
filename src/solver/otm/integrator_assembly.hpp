#pragma once
// Step 3-4 of the OTM step (docs/theory.md §4 step 1): lumped nodal mass m_a = sum_p N_a m_p, momentum
// l_a = sum_p N_a m_p v_p and internal force f_a = -sum_p V_p sigma_p grad N_a.
// Two passes: a point-major pass packs what every entry of a point needs (m_p, m_p v_p and
// -V_p sigma_p, zero for debris) into one contiguous record per point; the node-major
// pass then gathers over each node's entries in point order. The gather reads one record per
// entry instead of five scattered arrays, and its summation order does not depend on the
// number of threads.
#include "particles/store.hpp"
#include "solver/otm/connectivity.hpp"
#include "solver/otm/node_store.hpp"

#include <vector>

namespace kessler::otm {

struct PointLoad {
  Mat3 minus_volume_stress;  // -V_p sigma_p (zero for debris)
  Vec3 momentum;             // m_p v_p
  double mass;               // m_p
};

// Fills nodes.mass, nodes.momentum and nodes.force for the owned nodes. `loads` is scratch,
// resized to the number of points (kept between calls so the time loop does not allocate), and
// holds each point's -V sigma of the step afterwards (Integrator::updatePoints books its work).
// With `stabilisation` (per point, Pa; VolumePatch::stabilisationPressures) the forces carry
// sigma - S I: the volume stabilisation's pressure S on top of each point's own stress.
void assembleNodes(const Connectivity& conn, const PointStore& points, NodeStore& nodes, std::vector<PointLoad>& loads,
                   const std::vector<double>* stabilisation = nullptr);

}  // namespace kessler::otm
