#pragma once
// Ghosts (docs/parallel.md, "The distributed step"): copies of other ranks' entries that this rank's
// own entries reach. Entry i of a rank is needed by every other rank whose subdomain meets the box
// x_i +- reach_i (reach: the largest distance at which anything of the other rank can need it, a
// support radius or an erosion ball). build() sends those entries whole and merges them among the
// store's own entries in id order, so that the store holds its part of the whole in the whole's
// order (docs/parallel.md, "One order on every rank"); ghost(i) tells them apart. A build sends
// entries out to a reach and a skin, so that the ghosts it leaves stay enough while entries move:
// build() again keeps them in their slots and sends their values afresh while every entry needed
// now is among them, and otherwise replaces them with those needed now, in one pass over the
// store. Ghosts beyond the need are held and updated, but no own entry reads them. refresh()
// later sends only chosen arrays again, into the same slots, in messages between neighbouring ranks
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
  // Removes the ghosts of the last build from the store (the own entries stay, in order): before a
  // migration.
  template <class Store>
  void dropGhosts(Store& store);
  // Finds and fetches the ghosts the store's own entries need now (reach[k] for the k-th own
  // entry). Where the last build's ghosts hold them all, on every rank, they stay in their slots and
  // take their owners' values afresh; otherwise the entries within the reach and its skin are put
  // among the own entries in id order, in place of the last build's. The own entries must be in id
  // order (as migrate() leaves them). Collective.
  template <class Store>
  void build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm);
  // A build's margin: entries are sent out to (1 + skin) times their reach.
  static constexpr double skin = 0.25;
  // Builds that fetched ghosts afresh, and builds that kept them.
  long fetches() const { return fetches_; }
  long keeps() const { return keeps_; }
  // The own entries of the store, in order (all of them before the first build).
  template <class Store>
  std::vector<LocalIndex> ownEntries(const Store& store) const;

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
  bool built_ = false;  // since the last dropGhosts()
  long fetches_ = 0, keeps_ = 0;
};

template <class Store>
void Halo::dropGhosts(Store& store) {
  built_ = false;  // entries move after this: the next build fetches
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
std::vector<LocalIndex> Halo::ownEntries(const Store& store) const {
  KESSLER_VERIFY(ghost_.empty() || ghost_.size() == store.x.size(), "a halo of {} entries for a store of {}",
                 ghost_.size(), store.x.size());
  std::vector<LocalIndex> own;
  own.reserve(store.x.size() - static_cast<std::size_t>(ghosts_));
  for (std::size_t i = 0; i < store.x.size(); ++i)
    if (ghost_.empty() || !ghost_[i]) own.push_back(static_cast<LocalIndex>(i));
  return own;
}

template <class Store>
void Halo::build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm) {
  comm_ = &comm;
  const std::vector<LocalIndex> own = ownEntries(store);
  KESSLER_VERIFY(reach.size() == own.size(), "{} reaches for {} own entries", reach.size(), own.size());
  for (std::size_t k = 1; k < own.size(); ++k)
    KESSLER_VERIFY(store.id[own[k - 1]] < store.id[own[k]], "a halo built on a store out of id order (entry {})",
                   own[k]);
  const auto ranks = static_cast<std::size_t>(comm.size());
  // The own entries each rank needs within `scale` times their reach, in order.
  auto wanted = [&](double scale) {
    std::vector<std::vector<LocalIndex>> lists(ranks);
    for (std::size_t k = 0; k < own.size(); ++k) {
      const Vec3& x = store.x[own[k]];
      const Vec3 r = Vec3::Constant(scale * reach[k]);
      for (const int rank : partition.ranksMeeting(x - r, x + r))
        if (rank != comm.rank()) lists[static_cast<std::size_t>(rank)].push_back(own[k]);
    }
    return lists;
  };
  // The last build's ghosts do while each rank is sent all it needs now (both lists in store order).
  bool short_of = !built_;
  if (built_) {
    const std::vector<std::vector<LocalIndex>> needed = wanted(1.0);
    for (std::size_t r = 0; r < ranks && !short_of; ++r)
      short_of = !std::includes(send_[r].begin(), send_[r].end(), needed[r].begin(), needed[r].end());
  }
  if (!comm.any(short_of)) {
    refreshFields(store);
    ++keeps_;
    return;
  }
  ++fetches_;
  send_ = wanted(1.0 + skin);
  const std::vector<std::vector<std::byte>> incoming = comm.exchange(packEntries(store, send_));

  // Each message: its entry count, then each array of its entries in fields() order. The ghosts
  // take their places among the own entries, in id order.
  constexpr std::size_t header = sizeof(std::uint64_t);
  const std::size_t entry_bytes = fieldBytes(store);
  std::vector<PackedEntries> lists(ranks);
  std::vector<std::size_t> count(ranks, 0);
  for (std::size_t r = 0; r < ranks; ++r) {
    std::uint64_t n = 0;
    KESSLER_VERIFY(incoming[r].size() >= header, "a message of {} bytes from rank {}", incoming[r].size(), r);
    std::memcpy(&n, incoming[r].data(), header);
    count[r] = static_cast<std::size_t>(n);
    KESSLER_VERIFY(incoming[r].size() == header + count[r] * entry_bytes,
                   "a message of {} bytes from rank {} for {} entries", incoming[r].size(), r, count[r]);
    lists[r] = {incoming[r].data() + header, count[r]};
  }
  const std::size_t held = ghost_.empty() ? store.x.size() : ghost_.size();
  const std::vector<MergeSource> from = mergeById(store, std::span<const LocalIndex>(own), lists, scratch_);
  const std::size_t total = from.size();

  // Where each own entry went (for the lists of what this rank sends), and each ghost sits.
  std::vector<LocalIndex> at(held, -1);
  ghost_.assign(total, 0);
  slot_.assign(ranks, {});
  for (std::size_t r = 0; r < ranks; ++r) slot_[r].reserve(count[r]);
  for (std::size_t i = 0; i < total; ++i) {
    if (from[i].list < 0) {
      at[from[i].k] = static_cast<LocalIndex>(i);
    } else {
      slot_[static_cast<std::size_t>(from[i].list)].push_back(static_cast<LocalIndex>(i));
      ghost_[i] = 1;
    }
  }
  for (auto& list : send_)
    for (LocalIndex& i : list) i = at[static_cast<std::size_t>(i)];
  store.owned = static_cast<LocalIndex>(total);
  to_.clear();
  from_.clear();
  for (std::size_t r = 0; r < ranks; ++r) {
    if (!send_[r].empty()) to_.push_back(static_cast<int>(r));
    if (!slot_[r].empty()) from_.push_back(static_cast<int>(r));
  }
  ghosts_ = static_cast<LocalIndex>(total - own.size());
  built_ = true;
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
