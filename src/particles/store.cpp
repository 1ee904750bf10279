#include "particles/store.hpp"

#include "core/error.hpp"
#include "particles/store_fields.hpp"

#include <algorithm>
#include <cmath>

namespace kessler {

// Tripwire: an array added to the store but not to its fields() list would be lost by a
// permutation, a resize or a restart (the last term: `owned`, padded).
static_assert(sizeof(PointStore) == PointStore::field_count * sizeof(std::vector<double>) + sizeof(std::int64_t),
              "PointStore gained or lost an array: add it to PointStore::fields() and field_count");

void PointStore::permute(const std::vector<LocalIndex>& order) {
  permuteFields(*this, order);
}

void PointStore::resize(std::size_t n) {
  resizeFields(*this, n);
}

double PointStore::spacing(LocalIndex p) const {
  return spacing0[p] * std::cbrt(volume[p] / volume0[p]);
}

std::vector<LocalIndex> indexById(const PointStore& points) {
  Index largest = -1;
  for (const Index id : points.id) largest = std::max(largest, id);
  std::vector<LocalIndex> index(static_cast<std::size_t>(largest + 1), -1);
  for (LocalIndex p = 0; p < points.size(); ++p) {
    KESSLER_VERIFY(points.id[p] >= 0, "point {} has the negative id {}", p, points.id[p]);
    index[static_cast<std::size_t>(points.id[p])] = p;
  }
  return index;
}

std::vector<IndexRange> bodyRanges(std::span<const std::int32_t> body, LocalIndex count, std::size_t bodies) {
  std::vector<IndexRange> ranges(bodies);
  std::vector<std::uint8_t> seen(bodies, 0);
  for (LocalIndex i = 0; i < count;) {
    const std::int32_t b = body[static_cast<std::size_t>(i)];
    KESSLER_VERIFY(b >= 0 && static_cast<std::size_t>(b) < bodies, "entry {} belongs to body {}, of {} bodies", i, b,
                   bodies);
    KESSLER_VERIFY(!seen[static_cast<std::size_t>(b)], "entry {} of body {} is apart from the body's other entries", i,
                   b);
    seen[static_cast<std::size_t>(b)] = 1;
    LocalIndex end = i + 1;
    while (end < count && body[static_cast<std::size_t>(end)] == b) ++end;
    ranges[static_cast<std::size_t>(b)] = {i, end};
    i = end;
  }
  return ranges;
}

}  // namespace kessler
