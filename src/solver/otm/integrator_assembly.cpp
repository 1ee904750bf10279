#include "solver/otm/integrator_assembly.hpp"

namespace kessler::otm {

void assembleNodes(const Connectivity& conn, const PointStore& points, NodeStore& nodes, std::vector<PointLoad>& loads,
                   const std::vector<double>* stabilisation) {
  const LocalIndex np = points.owned;
  loads.resize(static_cast<std::size_t>(np));
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (LocalIndex p = 0; p < np; ++p) {
      PointLoad& load = loads[p];
      load.mass = points.mass[p];
      load.momentum = points.mass[p] * points.v[p];
      if (points.debris(p))
        load.minus_volume_stress.setZero();
      else if (stabilisation)
        load.minus_volume_stress = -points.volume[p] * (points.stress[p] - (*stabilisation)[p] * Mat3::Identity());
      else
        load.minus_volume_stress = -points.volume[p] * points.stress[p];
    }
    // Dynamic: nodes in contact or in the impact zone have several times the entries of others,
    // and they sit together (each node's sum is its own, so any schedule gives the same result).
#pragma omp for schedule(dynamic, 256)
    for (LocalIndex a = 0; a < nodes.owned; ++a) {
      double m = 0.0;
      Vec3 l = Vec3::Zero(), f = Vec3::Zero();
      for (Index k = conn.node_offset[a]; k < conn.node_offset[a + 1]; ++k) {
        const Connectivity::NodeSlot slot = conn.node_slot[k];
        const Index e = slot.entry;
        const PointLoad& load = loads[slot.point];
        const double N = conn.N[e];
        m += N * load.mass;
        l += N * load.momentum;
        f.noalias() += load.minus_volume_stress * conn.dN[e];
      }
      nodes.mass[a] = m;
      nodes.momentum[a] = l;
      nodes.force[a] = f;
    }
  }
}

}  // namespace kessler::otm
