#include "solver/common/particle_state.hpp"

#include "core/error.hpp"

#include <numeric>
#include <utility>

namespace kessler {

void numberPointsInOrder(ParticleState& state) {
  PointStore& points = state.points;
  const IdIndex before(points.id);
  for (auto& pair : state.adjacency) {
    pair = {static_cast<Index>(before.find(pair[0])), static_cast<Index>(before.find(pair[1]))};
    KESSLER_VERIFY(pair[0] >= 0 && pair[1] >= 0, "an adjacency pair names a point that is not in the store");
    if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
  }
  std::iota(points.id.begin(), points.id.end(), Index{0});
}

}  // namespace kessler
