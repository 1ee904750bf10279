#include "particles/store.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace kessler {

namespace {

template <typename T>
void permuteArray(std::vector<T>& values, const std::vector<LocalIndex>& order, std::vector<T>& scratch) {
  KESSLER_VERIFY(values.size() == order.size(), "permutation of {} entries for an array of {}", order.size(),
                 values.size());
  scratch.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = values[order[i]];
  values.swap(scratch);
}

// Tripwires: an array added to a store but not to its fields() list would be lost by a
// permutation, a resize or a restart (the last term: `owned`, padded).
static_assert(sizeof(PointStore) == PointStore::field_count * sizeof(std::vector<double>) + sizeof(std::int64_t),
              "PointStore gained or lost an array: add it to PointStore::fields() and field_count");
static_assert(sizeof(NodeStore) == NodeStore::field_count * sizeof(std::vector<double>) + sizeof(std::int64_t),
              "NodeStore gained or lost an array: add it to NodeStore::fields() and field_count");

template <class Store>
void permuteStore(Store& store, const std::vector<LocalIndex>& order) {
  KESSLER_VERIFY(order.size() == store.x.size(), "permutation of {} entries for {} particles", order.size(),
                 store.x.size());
  Store::fields(store, [&](const char*, auto& values, const auto&) {
    std::remove_reference_t<decltype(values)> scratch;
    permuteArray(values, order, scratch);
  });
}

template <class Store>
void resizeStore(Store& store, std::size_t n) {
  Store::fields(store, [&](const char*, auto& values, const auto& fresh) { values.resize(n, fresh); });
  store.owned = static_cast<LocalIndex>(n);
}

}  // namespace

void NodeStore::permute(const std::vector<LocalIndex>& order) {
  permuteStore(*this, order);
}

void PointStore::permute(const std::vector<LocalIndex>& order) {
  permuteStore(*this, order);
}

void NodeStore::resize(std::size_t n) {
  resizeStore(*this, n);
}

void PointStore::resize(std::size_t n) {
  resizeStore(*this, n);
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
