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

IdIndex::IdIndex(std::span<const Index> ids) {
  Index largest = -1;
  for (const Index id : ids) {
    KESSLER_VERIFY(id >= 0, "negative id {}", id);
    largest = std::max(largest, id);
  }
  const auto n = static_cast<LocalIndex>(ids.size());
  if (largest < 4 * static_cast<Index>(ids.size()) + 1024) {
    by_id_.assign(static_cast<std::size_t>(largest + 1), -1);
    for (LocalIndex i = 0; i < n; ++i) {
      LocalIndex& slot = by_id_[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])];
      KESSLER_VERIFY(slot < 0, "id {} appears twice (entries {} and {})", ids[static_cast<std::size_t>(i)], slot, i);
      slot = i;
    }
    return;
  }
  sorted_.reserve(ids.size());
  for (LocalIndex i = 0; i < n; ++i) sorted_.emplace_back(ids[static_cast<std::size_t>(i)], i);
  std::sort(sorted_.begin(), sorted_.end());
  for (std::size_t k = 1; k < sorted_.size(); ++k)
    KESSLER_VERIFY(sorted_[k].first != sorted_[k - 1].first, "id {} appears twice (entries {} and {})",
                   sorted_[k].first, sorted_[k - 1].second, sorted_[k].second);
}

LocalIndex IdIndex::find(Index id) const {
  if (sorted_.empty())
    return id >= 0 && static_cast<std::size_t>(id) < by_id_.size() ? by_id_[static_cast<std::size_t>(id)] : -1;
  const auto at = std::lower_bound(sorted_.begin(), sorted_.end(), std::pair<Index, LocalIndex>{id, -1});
  return at != sorted_.end() && at->first == id ? at->second : -1;
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
