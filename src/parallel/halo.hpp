#pragma once
// Ghosts (docs/parallel.md, "The distributed step"): copies of other ranks' entries that this rank's
// own entries reach. Entry i of a rank is needed by every other rank whose subdomain meets the box
// x_i +- reach_i (reach: the largest distance at which anything of the other rank can need it, a
// support radius or an erosion ball). build() sends those entries whole and merges them among the
// store's own entries in id order, so that the store holds its part of the whole in the whole's
// order (docs/parallel.md, "One order on every rank"); ghost(i) tells them apart. refresh() later
// sends only chosen arrays again, into the same slots, in messages between neighbouring ranks
// alone. After build() every entry counts as the store's (`owned` is its size): a method computes
// ghosts too, and their owners' values replace what it got wrong.
#include "parallel/communicator.hpp"
#include "parallel/migrate.hpp"
#include "parallel/partition.hpp"

#include <algorithm>
#include <cstring>
#include <span>
#include <vector>

namespace kessler::parallel {

class Halo {
 public:
  // Removes the ghosts of the last build from the store (the own entries stay, in order).
  template <class Store>
  void dropGhosts(Store& store);
  // Finds and fetches the ghosts the store's entries need now, from a store without ghosts whose
  // entries are in id order (as migrate() leaves them); reach[i] for each entry. Collective.
  template <class Store>
  void build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm);

  // The ghosts' values of one array (sized as the store), sent again by their owners. Collective.
  template <class T>
  void refresh(std::vector<T>& values) const;
  // Every array of the store (its fields()) sent again for the ghosts. Collective.
  template <class Store>
  void refreshFields(Store& store) const;

  // Per entry of the store, 1 for a ghost (empty before the first build: none).
  const std::vector<std::uint8_t>& ghostMask() const { return ghost_; }

  LocalIndex ghosts() const { return ghosts_; }
  bool ghost(LocalIndex i) const { return !ghost_.empty() && ghost_[static_cast<std::size_t>(i)] != 0; }
  // How many of this rank's entries it sends, counting an entry once per rank that needs it.
  std::size_t sent() const {
    std::size_t n = 0;
    for (const auto& list : send_) n += list.size();
    return n;
  }
  // The ranks this rank sends to or receives from (the messages of one refresh).
  int neighbours() const { return static_cast<int>(std::max(to_.size(), from_.size())); }

 private:
  // One message to each rank this rank sends to, filled by pack(entries, buffer) with the entries
  // that rank needs, and one from each rank it receives from, of incoming_bytes(slots) bytes, given
  // to unpack(slots, bytes) with the slots its ghosts sit in.
  template <class Pack, class Size, class Unpack>
  void send(Pack&& pack, Size&& incoming_bytes, Unpack&& unpack) const;

  const Communicator* comm_ = nullptr;
  std::vector<std::vector<LocalIndex>> send_;  // per rank, the own entries it needs
  std::vector<std::vector<LocalIndex>> slot_;  // per rank, where each ghost from it sits, in its order
  std::vector<int> to_, from_;                 // the ranks this rank sends to and receives from
  std::vector<std::uint8_t> ghost_;            // per entry of the store
  std::vector<std::byte> scratch_;             // build()'s reordering, kept between builds
  LocalIndex ghosts_ = 0;
};

template <class Store>
void Halo::dropGhosts(Store& store) {
  if (ghosts_ == 0) return;
  KESSLER_VERIFY(ghost_.size() == store.x.size(), "dropping the ghosts of another store");
  std::vector<LocalIndex> own;
  for (std::size_t i = 0; i < ghost_.size(); ++i)
    if (!ghost_[i]) own.push_back(static_cast<LocalIndex>(i));
  keepFields(store, own);
  ghost_.clear();
  ghosts_ = 0;
  for (auto& list : send_) list.clear();
  for (auto& list : slot_) list.clear();
  to_.clear();
  from_.clear();
}

template <class Store>
void Halo::build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm) {
  comm_ = &comm;
  KESSLER_VERIFY(ghosts_ == 0 && store.x.size() == static_cast<std::size_t>(store.owned),
                 "a halo built on a store that holds ghosts (dropGhosts first)");
  const LocalIndex own = store.owned;
  KESSLER_VERIFY(reach.size() == static_cast<std::size_t>(own), "{} reaches for {} entries", reach.size(), own);
  for (LocalIndex i = 1; i < own; ++i)
    KESSLER_VERIFY(store.id[i - 1] < store.id[i], "a halo built on a store out of id order (entry {})", i);
  const auto ranks = static_cast<std::size_t>(comm.size());
  send_.assign(ranks, {});
  for (LocalIndex i = 0; i < own; ++i) {
    const Vec3 r = Vec3::Constant(reach[static_cast<std::size_t>(i)]);
    for (const int rank : partition.ranksMeeting(store.x[i] - r, store.x[i] + r))
      if (rank != comm.rank()) send_[static_cast<std::size_t>(rank)].push_back(i);
  }
  const std::vector<std::size_t> received = unpackEntries(store, comm.exchange(packEntries(store, send_)));

  // Ghosts among the own entries in id order: where each entry goes, then the lists follow.
  const std::size_t n = store.x.size();
  const std::vector<LocalIndex> order = idOrder(store);
  std::vector<LocalIndex> at(n);
  for (std::size_t k = 0; k < n; ++k) {
    KESSLER_VERIFY(k == 0 || store.id[order[k - 1]] != store.id[order[k]], "entry {} is both own and a ghost",
                   store.id[order[k]]);
    at[static_cast<std::size_t>(order[k])] = static_cast<LocalIndex>(k);
  }
  permuteFields(store, order, scratch_);
  store.owned = static_cast<LocalIndex>(n);
  ghost_.assign(n, 0);
  slot_.assign(ranks, {});
  auto next = static_cast<LocalIndex>(own);  // the received entries, rank by rank, before the merge
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t k = 0; k < received[r]; ++k) {
      const LocalIndex slot = at[static_cast<std::size_t>(next++)];
      slot_[r].push_back(slot);
      ghost_[static_cast<std::size_t>(slot)] = 1;
    }
  for (auto& list : send_)
    for (LocalIndex& i : list) i = at[static_cast<std::size_t>(i)];
  to_.clear();
  from_.clear();
  for (std::size_t r = 0; r < ranks; ++r) {
    if (!send_[r].empty()) to_.push_back(static_cast<int>(r));
    if (!slot_[r].empty()) from_.push_back(static_cast<int>(r));
  }
  ghosts_ = static_cast<LocalIndex>(n) - own;
}

template <class Pack, class Size, class Unpack>
void Halo::send(Pack&& pack, Size&& incoming_bytes, Unpack&& unpack) const {
  KESSLER_VERIFY(comm_, "a halo refreshed before it was built");
  const auto ranks = static_cast<std::size_t>(comm_->size());
  std::vector<std::vector<std::byte>> outgoing(ranks), incoming(ranks);
  for (const int r : to_) pack(send_[static_cast<std::size_t>(r)], outgoing[static_cast<std::size_t>(r)]);
  for (const int s : from_)
    incoming[static_cast<std::size_t>(s)].resize(incoming_bytes(slot_[static_cast<std::size_t>(s)]));
  // The sizes are known from build(): messages to and from the neighbours only, no collective.
  comm_->exchangeWith(to_, outgoing, from_, incoming);
  for (const int s : from_) unpack(slot_[static_cast<std::size_t>(s)], incoming[static_cast<std::size_t>(s)]);
}

template <class T>
void Halo::refresh(std::vector<T>& values) const {
  static_assert(bytewise<T>, "a refreshed array must hold plain values");
  KESSLER_VERIFY(ghost_.empty() || values.size() == ghost_.size(),
                 "refreshing an array of {} entries for a store of {}", values.size(), ghost_.size());
  send(
      [&](const std::vector<LocalIndex>& list, std::vector<std::byte>& buffer) {
        buffer.resize(list.size() * sizeof(T));
        std::byte* cursor = buffer.data();
        for (const LocalIndex i : list) {
          std::memcpy(cursor, &values[static_cast<std::size_t>(i)], sizeof(T));
          cursor += sizeof(T);
        }
      },
      [](const std::vector<LocalIndex>& slots) { return slots.size() * sizeof(T); },
      [&](const std::vector<LocalIndex>& slots, const std::vector<std::byte>& buffer) {
        const std::byte* cursor = buffer.data();
        for (const LocalIndex slot : slots) {
          std::memcpy(static_cast<void*>(&values[static_cast<std::size_t>(slot)]), cursor, sizeof(T));
          cursor += sizeof(T);
        }
      });
}

template <class Store>
void Halo::refreshFields(Store& store) const {
  KESSLER_VERIFY(ghost_.empty() || store.x.size() == ghost_.size(),
                 "refreshing a store of {} entries with a halo of {}", store.x.size(), ghost_.size());
  const std::size_t entry_bytes = fieldBytes(store);
  send([&](const std::vector<LocalIndex>& list,
           std::vector<std::byte>& buffer) { packFields(store, std::span<const LocalIndex>(list), buffer); },
       [&](const std::vector<LocalIndex>& slots) { return slots.size() * entry_bytes; },
       [&](const std::vector<LocalIndex>& slots, const std::vector<std::byte>& buffer) {
         const std::size_t end = unpackFieldsInto(store, buffer, 0, std::span<const LocalIndex>(slots));
         KESSLER_VERIFY(end == buffer.size(), "a refresh of {} bytes held {}", buffer.size(), end);
       });
}

}  // namespace kessler::parallel
