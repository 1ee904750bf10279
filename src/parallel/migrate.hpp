#pragma once
// Moving store entries between ranks (docs/parallel.md): each entry goes to the rank its
// destination names, carried as bytes by the store's one list of arrays (packFields). After a
// migration a store holds what it kept and what it received, in id order; all owned.
#include "parallel/communicator.hpp"
#include "particles/store_fields.hpp"

#include <cstring>
#include <span>
#include <vector>

namespace kessler::parallel {

// Buffers for an exchange: for each rank r, the count of entries lists[r] and their packed arrays.
template <class Store>
std::vector<std::vector<std::byte>> packEntries(const Store& store, const std::vector<std::vector<LocalIndex>>& lists) {
  std::vector<std::vector<std::byte>> buffers(lists.size());
  for (std::size_t r = 0; r < lists.size(); ++r) {
    const auto count = static_cast<std::uint64_t>(lists[r].size());
    buffers[r].resize(sizeof count);
    std::memcpy(buffers[r].data(), &count, sizeof count);
    packFields(store, std::span<const LocalIndex>(lists[r]), buffers[r]);
  }
  return buffers;
}

// Appends the entries packEntries put in each received buffer, rank by rank, behind the store's;
// returns how many came from each rank (`owned` is left to the caller).
template <class Store>
std::vector<std::size_t> unpackEntries(Store& store, const std::vector<std::vector<std::byte>>& buffers) {
  std::vector<std::size_t> counts(buffers.size());
  for (std::size_t r = 0; r < buffers.size(); ++r) {
    std::uint64_t count = 0;
    KESSLER_VERIFY(buffers[r].size() >= sizeof count, "a message of {} bytes from rank {}", buffers[r].size(), r);
    std::memcpy(&count, buffers[r].data(), sizeof count);
    counts[r] = static_cast<std::size_t>(count);
    const std::size_t end = unpackFields(store, buffers[r], sizeof count, counts[r]);
    KESSLER_VERIFY(end == buffers[r].size(), "a message of {} bytes from rank {} held {}", buffers[r].size(), r, end);
  }
  return counts;
}

template <class Store>
void migrate(Store& store, std::span<const int> destination, const Communicator& comm) {
  KESSLER_VERIFY(destination.size() == static_cast<std::size_t>(store.owned) &&
                     store.x.size() == static_cast<std::size_t>(store.owned),
                 "migrating {} destinations for a store of {} entries, {} owned (ghosts must be dropped first)",
                 destination.size(), store.x.size(), store.owned);
  const auto ranks = static_cast<std::size_t>(comm.size());
  const auto me = static_cast<std::size_t>(comm.rank());
  // What stays stays where it is; only what leaves is packed.
  std::vector<std::vector<LocalIndex>> leaving(ranks);
  std::vector<LocalIndex> staying;
  for (std::size_t i = 0; i < destination.size(); ++i) {
    KESSLER_VERIFY(destination[i] >= 0 && static_cast<std::size_t>(destination[i]) < ranks,
                   "entry {} sent to rank {} of {}", i, destination[i], ranks);
    (static_cast<std::size_t>(destination[i]) == me ? staying : leaving[static_cast<std::size_t>(destination[i])])
        .push_back(static_cast<LocalIndex>(i));
  }
  const std::vector<std::vector<std::byte>> incoming = comm.exchange(packEntries(store, leaving));
  if (staying.size() < destination.size()) keepFields(store, staying);
  unpackEntries(store, incoming);
  store.owned = static_cast<LocalIndex>(store.x.size());
  // Sorted only where arrivals (or the store as it came) are out of id order.
  bool ordered = true;
  for (std::size_t i = 1; i < store.id.size() && ordered; ++i) ordered = store.id[i - 1] < store.id[i];
  if (!ordered) permuteFields(store, idOrder(store));
}

}  // namespace kessler::parallel
