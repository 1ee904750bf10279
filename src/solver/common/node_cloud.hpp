#pragma once
// A method's node cloud as output and the run loop see it (Method::nodes): written to nodes.xdmf
// beside the points. OTM: its nodes (solver/otm/node_store.hpp), material positions that carry the
// bodies' surfaces; RKPM: its kernel coefficients, which are not material positions (a body's
// surface is then its particles' cells, as for a method without nodes); empty for a method without
// nodes (SPH).
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
  bool material = true;  // the nodes are material positions that carry the bodies' surfaces
};

// Whether a body's surface is read from the node cloud (else from the particles' cells, half a
// spacing beyond their centres).
inline bool surfaceOnNodes(const NodeCloud& nodes) {
  return nodes.owned > 0 && nodes.material;
}

}  // namespace kessler
