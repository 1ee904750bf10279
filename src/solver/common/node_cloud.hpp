#pragma once
// A method's node cloud as output and the run loop see it (Method::nodes): written to nodes.xdmf
// beside the points. OTM: its nodes (solver/otm/node_store.hpp); empty for a method without nodes.
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
};

}  // namespace kessler
