#include "search/morton.hpp"

#include <algorithm>
#include <utility>

namespace kessler {

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

std::vector<LocalIndex> mortonOrder(std::span<const Vec3> x, std::span<const std::int32_t> body, std::size_t bodies,
                                    const Vec3& lo, const Vec3& hi) {
  const auto n = static_cast<LocalIndex>(x.size());
  std::vector<LocalIndex> order(x.size());
  std::vector<std::pair<std::uint64_t, LocalIndex>> keys;
  for (const IndexRange& range : bodyRanges(body, n, bodies)) {
    keys.clear();
    for (LocalIndex i = range.begin; i < range.end; ++i) keys.emplace_back(mortonKey(x[i], lo, hi), i);
    std::sort(keys.begin(), keys.end());
    for (LocalIndex i = range.begin; i < range.end; ++i) order[i] = keys[i - range.begin].second;
  }
  return order;
}

}  // namespace kessler
