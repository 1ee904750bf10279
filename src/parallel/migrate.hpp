#pragma once
// Moving store entries between ranks (docs/parallel.md): each entry goes to the rank its
// destination names, carried as bytes by the store's one list of arrays (packFields). After a
// migration a store holds what it kept and what it received, in id order; all owned.
#include "parallel/communicator.hpp"
#include "particles/store_fields.hpp"

#include <cstring>
#include <limits>
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

// Entries packed by packFields: `count` of them from `bytes` on, their arrays one after another.
struct PackedEntries {
  const std::byte* bytes = nullptr;
  std::size_t count = 0;
};
// Where an entry of a merge came from: the store's own entry k (list -1), or entry k of a packed list.
struct MergeSource {
  int list = -1;
  std::size_t k = 0;
};

// Rewrites every array of `store` as its entries `kept` and the entries of each packed list, merged
// by id (`kept`, and each list, must be in id order), through `scratch` (kept by the caller between
// calls, so that a merge every step allocates nothing); returns where each entry came from. One pass over the arrays,
// where appending, sorting and permuting would take three. An id met twice is an error.
template <class Store>
std::vector<MergeSource> mergeById(Store& store, std::span<const LocalIndex> kept, std::span<const PackedEntries> lists,
                                   std::vector<std::byte>& scratch) {
  std::size_t id_at = 0, before = 0;  // bytes per entry of the arrays before the ids
  Store::fields(store, [&](const char*, const auto& values, const auto&) {
    if (static_cast<const void*>(&values) == static_cast<const void*>(&store.id)) id_at = before;
    before += sizeof(typename std::remove_reference_t<decltype(values)>::value_type);
  });
  auto listId = [&](std::size_t l, std::size_t k) {
    Index id = 0;
    std::memcpy(&id, lists[l].bytes + lists[l].count * id_at + k * sizeof(Index), sizeof id);
    return id;
  };
  std::size_t total = kept.size();
  for (const PackedEntries& list : lists) total += list.count;
  std::vector<MergeSource> from;
  from.reserve(total);
  std::vector<std::size_t> next(lists.size(), 0);
  std::size_t next_kept = 0;
  Index last = 0;
  for (std::size_t i = 0; i < total; ++i) {
    MergeSource best;
    Index best_id = std::numeric_limits<Index>::max();
    if (next_kept < kept.size()) {
      best = {-1, static_cast<std::size_t>(kept[next_kept])};
      best_id = store.id[kept[next_kept]];
    }
    for (std::size_t l = 0; l < lists.size(); ++l)
      if (next[l] < lists[l].count && listId(l, next[l]) < best_id) {
        best = {static_cast<int>(l), next[l]};
        best_id = listId(l, next[l]);
      }
    KESSLER_VERIFY(i == 0 || best_id > last, "entry {} met twice in a merge (or a list out of id order)", best_id);
    last = best_id;
    ++(best.list < 0 ? next_kept : next[static_cast<std::size_t>(best.list)]);
    from.push_back(best);
  }
  // Runs of entries that come one after another from one source (a rank's part of space holds
  // runs of consecutive ids), each copied at once.
  struct Run {
    int list;
    std::size_t k, count;
  };
  std::vector<Run> runs;
  for (const MergeSource& f : from) {
    if (!runs.empty() && runs.back().list == f.list && runs.back().k + runs.back().count == f.k)
      ++runs.back().count;
    else
      runs.push_back({f.list, f.k, 1});
  }
  before = 0;
  Store::fields(store, [&](const char*, auto& values, const auto&) {
    using T = typename std::remove_reference_t<decltype(values)>::value_type;
    static_assert(bytewise<T>, "a store array must hold plain values to be merged through bytes");
    scratch.resize(total * sizeof(T));
    std::byte* to = scratch.data();
    for (const Run& run : runs) {
      const std::byte* source = run.list < 0
                                    ? reinterpret_cast<const std::byte*>(values.data() + run.k)
                                    : lists[static_cast<std::size_t>(run.list)].bytes +
                                          lists[static_cast<std::size_t>(run.list)].count * before + run.k * sizeof(T);
      std::memcpy(to, source, run.count * sizeof(T));
      to += run.count * sizeof(T);
    }
    values.resize(total);
    if (total > 0) std::memcpy(static_cast<void*>(values.data()), scratch.data(), total * sizeof(T));
    before += sizeof(T);
  });
  store.owned = static_cast<LocalIndex>(total);
  return from;
}

// Every rank's entries `own` (in id order) on rank 0, merged by id into `whole` (a store of the same
// kind); returns, on rank 0, where each of its entries came from (list: the rank, k: the entry's place
// in that rank's `own`), and nothing elsewhere. Collective.
template <class Store>
std::vector<MergeSource> gatherById(const Store& store, std::span<const LocalIndex> own, Store& whole,
                                    const Communicator& comm) {
  std::vector<std::byte> bytes;
  packFields(store, own, bytes);
  const std::vector<std::vector<std::byte>> in = comm.gather(std::move(bytes));
  if (!comm.root()) return {};
  const std::size_t entry_bytes = fieldBytes(whole);
  std::vector<PackedEntries> lists;
  for (const std::vector<std::byte>& part : in) {
    KESSLER_VERIFY(entry_bytes > 0 && part.size() % entry_bytes == 0, "gathering: a message of {} bytes", part.size());
    lists.push_back({part.data(), part.size() / entry_bytes});
  }
  std::vector<std::byte> scratch;
  return mergeById(whole, {}, lists, scratch);
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
