#pragma once
// A method's node cloud as output and the run loop see it (Method::nodes): written to nodes.xdmf
// beside the points. OTM: its nodes (solver/otm/node_store.hpp), which carry the bodies' surfaces:
// its walls and contact act on them. RKPM: its kernel coefficients, which are not material
// positions. SPH: the reconstructed elements' nodes (solver/sph/reconstruction.hpp), rebuilt from
// the particles for the fragment analysis, while its walls and contact act on the particles' cells.
// For RKPM and SPH a body's surface is therefore its particles' cells; the cloud is empty for a
// method without nodes.
#include "core/types.hpp"

#include <cstdint>
#include <span>

namespace kessler {

struct NodeCloud {
  std::span<const Index> id;
  std::span<const std::int32_t> body;
  std::span<const Vec3> x;
  std::span<const Vec3> v;
  std::span<const double> mass;
  LocalIndex owned = 0;  // the first `owned` are this process's own
  bool surface = true;   // the nodes carry the bodies' surfaces (the method's walls and contact act on them)
};

// Whether a body's surface is read from the node cloud (else from the particles' cells, half a
// spacing beyond their centres).
inline bool surfaceOnNodes(const NodeCloud& nodes) {
  return nodes.owned > 0 && nodes.surface;
}

}  // namespace kessler
