#include "solver/otm/morton_order.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace kessler::otm {

namespace {

// Spreads the low 21 bits of v to every third bit.
std::uint64_t spread(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// The permutation that sorts [begin, end) of x by Morton key (ties by index), written into
// order[begin, end).
void sortRange(const std::vector<Vec3>& x, LocalIndex begin, LocalIndex end, const Vec3& lo, const Vec3& hi,
               std::vector<LocalIndex>& order) {
  std::vector<std::pair<std::uint64_t, LocalIndex>> keys;
  keys.reserve(static_cast<std::size_t>(end - begin));
  for (LocalIndex i = begin; i < end; ++i) keys.emplace_back(mortonKey(x[i], lo, hi), i);
  std::sort(keys.begin(), keys.end());
  for (LocalIndex i = begin; i < end; ++i) order[i] = keys[i - begin].second;
}

}  // namespace

std::uint64_t mortonKey(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  std::uint64_t key = 0;
  for (int d = 0; d < 3; ++d) {
    const double extent = hi[d] - lo[d];
    const double t = extent > 0.0 ? std::clamp((x[d] - lo[d]) / extent, 0.0, 1.0) : 0.0;
    key |= spread(static_cast<std::uint64_t>(t * 2097151.0)) << d;
  }
  return key;
}

void sortForLocality(Model& model) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  if (points.size() == 0 || nodes.size() == 0) return;
  Vec3 lo = nodes.x[0], hi = nodes.x[0];
  for (const Vec3& x : nodes.x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }

  std::vector<LocalIndex> order(static_cast<std::size_t>(points.size()));
  std::iota(order.begin(), order.end(), 0);
  for (const IndexRange& body : bodyRanges(points.body, points.size(), model.bodies.size()))
    sortRange(points.x, body.begin, body.end, lo, hi, order);
  points.permute(order);
  model.lme_lambda.assign(order.size(), Vec3::Zero());  // before the first solve: no warm start yet

  order.resize(static_cast<std::size_t>(nodes.size()));
  std::iota(order.begin(), order.end(), 0);
  for (const IndexRange& body : bodyRanges(nodes.body, nodes.size(), model.bodies.size()))
    sortRange(nodes.x, body.begin, body.end, lo, hi, order);
  nodes.permute(order);
  model.connectivity = Connectivity{};
}

void numberInOrder(Model& model) {
  PointStore& points = model.points;
  const IdIndex before(points.id);
  for (auto& pair : model.adjacency) {
    pair = {static_cast<Index>(before.find(pair[0])), static_cast<Index>(before.find(pair[1]))};
    KESSLER_VERIFY(pair[0] >= 0 && pair[1] >= 0, "an adjacency pair names a point that is not in the store");
    if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
  }
  std::iota(points.id.begin(), points.id.end(), Index{0});
  std::iota(model.nodes.id.begin(), model.nodes.id.end(), Index{0});
}

}  // namespace kessler::otm
