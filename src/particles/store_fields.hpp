#pragma once
// Resizing, reordering and packing a store through its one list of arrays (the store's static
// fields()): shared by the point store and a method's own stores (OTM's nodes,
// solver/otm/node_store.hpp). Packing is what moving entries between processes sends.
#include "core/error.hpp"
#include "core/types.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numeric>
#include <span>
#include <type_traits>
#include <vector>

namespace kessler {

// Every array of `store` reordered: new index i holds what old index order[i] held (order: a
// permutation).
template <class Store>
void permuteFields(Store& store, const std::vector<LocalIndex>& order) {
  KESSLER_VERIFY(order.size() == store.x.size(), "permutation of {} entries for {} particles", order.size(),
                 store.x.size());
  Store::fields(store, [&](const char* name, auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == order.size(), "permutation of {} entries for '{}', which holds {}", order.size(),
                   name, values.size());
    std::remove_reference_t<decltype(values)> scratch(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = values[static_cast<std::size_t>(order[i])];
    values.swap(scratch);
  });
}

// Keeps the entries `keep` (ascending) of every array, in place, and drops the others; all owned.
template <class Store>
void keepFields(Store& store, const std::vector<LocalIndex>& keep) {
  Store::fields(store, [&](const char*, auto& values, const auto&) {
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const auto from = static_cast<std::size_t>(keep[k]);
      if (from != k) values[k] = values[from];
    }
    values.resize(keep.size());
  });
  store.owned = static_cast<LocalIndex>(keep.size());
}

// The permutation that puts a store's entries in id order (for permuteFields): the order of the
// whole run, which any rank's part keeps (docs/parallel.md, "One order on every rank").
template <class Store>
std::vector<LocalIndex> idOrder(const Store& store) {
  std::vector<LocalIndex> order(store.id.size());
  std::iota(order.begin(), order.end(), LocalIndex{0});
  std::sort(order.begin(), order.end(), [&](LocalIndex a, LocalIndex b) { return store.id[a] < store.id[b]; });
  return order;
}

// Every array of `store` resized to n (new entries take their field's fresh value); all owned.
template <class Store>
void resizeFields(Store& store, std::size_t n) {
  Store::fields(store, [&](const char*, auto& values, const auto& fresh) { values.resize(n, fresh); });
  store.owned = static_cast<LocalIndex>(n);
}

// Values copied as bytes: trivially copyable ones, and Eigen's fixed vectors and matrices, which
// are plain runs of doubles.
// A struct of such values opts in by specialising PlainValue.
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Mat3) == 9 * sizeof(double));
template <class T>
struct PlainValue
    : std::bool_constant<std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>> {};
template <class T>
inline constexpr bool bytewise = PlainValue<T>::value;

// The bytes one entry takes in every array (what packFields writes per entry).
template <class Store>
std::size_t fieldBytes(Store& store) {
  std::size_t bytes = 0;
  Store::fields(store, [&](const char*, const auto& values, const auto&) {
    bytes += sizeof(typename std::remove_reference_t<decltype(values)>::value_type);
  });
  return bytes;
}

// Every index of `entries` names an entry of every array of the store (what: the operation, for the
// error).
template <class Store>
void checkEntries(const Store& store, std::span<const LocalIndex> entries, const char* what) {
  std::size_t shortest = std::numeric_limits<std::size_t>::max();
  Store::fields(store,
                [&](const char*, const auto& values, const auto&) { shortest = std::min(shortest, values.size()); });
  for (const LocalIndex i : entries)
    KESSLER_VERIFY(i >= 0 && static_cast<std::size_t>(i) < shortest, "{} entry {} of a store of {}", what, i, shortest);
}

// Appends entries `which` of every array to `buffer`, array by array in fields() order (raw bytes:
// the arrays hold trivially copyable values).
template <class Store>
void packFields(const Store& store, std::span<const LocalIndex> which, std::vector<std::byte>& buffer) {
  // The buffer grows once, and each index is checked once.
  checkEntries(store, which, "packing");
  std::size_t at = buffer.size();
  buffer.resize(at + which.size() * fieldBytes(store));
  Store::fields(store, [&](const char*, const auto& values, const auto&) {
    using T = typename std::remove_reference_t<decltype(values)>::value_type;
    static_assert(bytewise<T>, "a store array must hold plain values to be packed");
    std::byte* to = buffer.data() + at;
    for (const LocalIndex i : which) {
      std::memcpy(to, &values[static_cast<std::size_t>(i)], sizeof(T));
      to += sizeof(T);
    }
    at += which.size() * sizeof(T);
  });
}

// Appends `count` entries packed by packFields, from `buffer` at `offset`, behind the store's
// entries (`owned` is left as it was: the caller says whether they are its own or ghosts). Returns
// the offset after them.
template <class Store>
std::size_t unpackFields(Store& store, std::span<const std::byte> buffer, std::size_t offset, std::size_t count) {
  Store::fields(store, [&](const char* name, auto& values, const auto&) {
    using T = typename std::remove_reference_t<decltype(values)>::value_type;
    static_assert(bytewise<T>, "a store array must hold plain values to be unpacked");
    KESSLER_VERIFY(offset + count * sizeof(T) <= buffer.size(), "unpacking {} entries of '{}' past the buffer's end",
                   count, name);
    const std::size_t first = values.size();
    values.resize(first + count);
    if (count > 0) std::memcpy(static_cast<void*>(&values[first]), buffer.data() + offset, count * sizeof(T));
    offset += count * sizeof(T);
  });
  return offset;
}

// Overwrites entries `slots` of every array with values packed by packFields for as many entries,
// from `buffer` at `offset` (a refresh of ghosts); returns the offset after them.
template <class Store>
std::size_t unpackFieldsInto(Store& store, std::span<const std::byte> buffer, std::size_t offset,
                             std::span<const LocalIndex> slots) {
  checkEntries(store, slots, "unpacking into");
  KESSLER_VERIFY(offset + slots.size() * fieldBytes(store) <= buffer.size(),
                 "unpacking {} entries past the buffer's end ({} bytes from {})", slots.size(), buffer.size(), offset);
  Store::fields(store, [&](const char*, auto& values, const auto&) {
    using T = typename std::remove_reference_t<decltype(values)>::value_type;
    static_assert(bytewise<T>, "a store array must hold plain values to be unpacked");
    for (const LocalIndex i : slots) {
      std::memcpy(static_cast<void*>(&values[static_cast<std::size_t>(i)]), buffer.data() + offset, sizeof(T));
      offset += sizeof(T);
    }
  });
  return offset;
}

}  // namespace kessler
