#pragma once
// Ghosts (docs/parallel.md, "The distributed step"): copies of other ranks' entries that this rank's
// own entries reach. Entry i of a rank is needed by every other rank whose subdomain meets the box
// x_i +- reach_i (reach: the largest distance at which anything of the other rank can need it, a
// support radius or an erosion ball). build() sends those entries whole and appends them behind
// the store's owned entries, by the rank they come from and, within a rank, in the order that rank
// holds them; refresh() later sends only chosen arrays again, into the same slots, in messages
// between neighbouring ranks alone.
#include "parallel/communicator.hpp"
#include "parallel/migrate.hpp"
#include "parallel/partition.hpp"

#include <cstring>
#include <span>
#include <vector>

namespace kessler::parallel {

class Halo {
 public:
  // Drops the store's ghosts, then finds and fetches the ones it needs now. Collective.
  template <class Store>
  void build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm);

  // The ghosts' values of one array (sized owned + ghosts, as the store's), sent again by their
  // owners. Collective.
  template <class T>
  void refresh(std::vector<T>& values) const;

  LocalIndex ghosts() const { return ghosts_; }
  // How many of this rank's entries it sends, counting an entry once per rank that needs it.
  std::size_t sent() const {
    std::size_t n = 0;
    for (const auto& list : send_) n += list.size();
    return n;
  }
  // The ranks this rank sends to or receives from (the messages of one refresh).
  int neighbours() const;

 private:
  const Communicator* comm_ = nullptr;
  std::vector<std::vector<LocalIndex>> send_;  // per rank, the owned entries it needs
  std::vector<std::size_t> receive_;           // per rank, how many ghosts come from it
  std::vector<int> to_, from_;                 // the ranks this rank sends to and receives from
  LocalIndex owned_ = 0, ghosts_ = 0;
};

template <class Store>
void Halo::build(Store& store, const Partition& partition, std::span<const double> reach, const Communicator& comm) {
  comm_ = &comm;
  resizeFields(store, static_cast<std::size_t>(store.owned));  // no ghosts
  owned_ = store.owned;
  KESSLER_VERIFY(reach.size() == static_cast<std::size_t>(owned_), "{} reaches for {} owned entries", reach.size(),
                 owned_);
  const auto ranks = static_cast<std::size_t>(comm.size());
  send_.assign(ranks, {});
  for (LocalIndex i = 0; i < owned_; ++i) {
    const Vec3 r = Vec3::Constant(reach[static_cast<std::size_t>(i)]);
    for (const int rank : partition.ranksMeeting(store.x[i] - r, store.x[i] + r))
      if (rank != comm.rank()) send_[static_cast<std::size_t>(rank)].push_back(i);
  }
  receive_ = unpackEntries(store, comm.exchange(packEntries(store, send_)));
  to_.clear();
  from_.clear();
  for (std::size_t r = 0; r < ranks; ++r) {
    if (!send_[r].empty()) to_.push_back(static_cast<int>(r));
    if (receive_[r] > 0) from_.push_back(static_cast<int>(r));
  }
  ghosts_ = static_cast<LocalIndex>(store.x.size()) - owned_;
}

template <class T>
void Halo::refresh(std::vector<T>& values) const {
  static_assert(bytewise<T>, "a refreshed array must hold plain values");
  KESSLER_VERIFY(comm_, "a halo refreshed before it was built");
  KESSLER_VERIFY(values.size() == static_cast<std::size_t>(owned_ + ghosts_),
                 "refreshing an array of {} entries over {} owned and {} ghosts", values.size(), owned_, ghosts_);
  const auto ranks = static_cast<std::size_t>(comm_->size());
  std::vector<std::vector<std::byte>> outgoing(ranks), incoming(ranks);
  for (const int r : to_) {
    const auto& list = send_[static_cast<std::size_t>(r)];
    auto& buffer = outgoing[static_cast<std::size_t>(r)];
    buffer.resize(list.size() * sizeof(T));
    std::byte* at = buffer.data();
    for (const LocalIndex i : list) {
      std::memcpy(at, &values[static_cast<std::size_t>(i)], sizeof(T));
      at += sizeof(T);
    }
  }
  for (const int s : from_)
    incoming[static_cast<std::size_t>(s)].resize(receive_[static_cast<std::size_t>(s)] * sizeof(T));
  // The sizes are known from build(): messages to and from the neighbours only, no collective.
  comm_->exchangeWith(to_, outgoing, from_, incoming);
  std::size_t slot = static_cast<std::size_t>(owned_);
  for (std::size_t r = 0; r < ranks; ++r) {
    if (receive_[r] > 0) std::memcpy(static_cast<void*>(&values[slot]), incoming[r].data(), incoming[r].size());
    slot += receive_[r];
  }
}

inline int Halo::neighbours() const {
  int n = 0;
  for (std::size_t r = 0; r < send_.size(); ++r) n += (!send_[r].empty() || receive_[r] > 0) ? 1 : 0;
  return n;
}

}  // namespace kessler::parallel
