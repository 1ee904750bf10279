#pragma once
// Moving store entries between ranks (docs/parallel.md): each entry goes to the rank its
// destination names, carried as bytes by the store's one list of arrays (packFields). After a
// migration a store holds what it kept and what it received, ordered by the rank each entry came
// from and, within a rank, as that rank held them; all owned.
#include "parallel/communicator.hpp"
#include "particles/store_fields.hpp"

#include <cstring>
#include <span>
#include <vector>

namespace kessler::parallel {

template <class Store>
void migrate(Store& store, std::span<const int> destination, const Communicator& comm) {
  KESSLER_VERIFY(destination.size() == static_cast<std::size_t>(store.owned) &&
                     store.x.size() == static_cast<std::size_t>(store.owned),
                 "migrating {} destinations for a store of {} entries, {} owned (ghosts must be dropped first)",
                 destination.size(), store.x.size(), store.owned);
  const auto ranks = static_cast<std::size_t>(comm.size());
  std::vector<std::vector<LocalIndex>> leaving(ranks);
  for (std::size_t i = 0; i < destination.size(); ++i) {
    KESSLER_VERIFY(destination[i] >= 0 && static_cast<std::size_t>(destination[i]) < ranks,
                   "entry {} sent to rank {} of {}", i, destination[i], ranks);
    leaving[static_cast<std::size_t>(destination[i])].push_back(static_cast<LocalIndex>(i));
  }
  std::vector<std::vector<std::byte>> outgoing(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    const auto count = static_cast<std::uint64_t>(leaving[r].size());
    outgoing[r].resize(sizeof count);
    std::memcpy(outgoing[r].data(), &count, sizeof count);
    packFields(store, std::span<const LocalIndex>(leaving[r]), outgoing[r]);
  }
  const std::vector<std::vector<std::byte>> incoming = comm.exchange(outgoing);
  resizeFields(store, 0);
  for (const std::vector<std::byte>& buffer : incoming) {
    std::uint64_t count = 0;
    KESSLER_VERIFY(buffer.size() >= sizeof count, "a migration message of {} bytes", buffer.size());
    std::memcpy(&count, buffer.data(), sizeof count);
    const std::size_t end = unpackFields(store, buffer, sizeof count, static_cast<std::size_t>(count));
    KESSLER_VERIFY(end == buffer.size(), "a migration message of {} bytes held {}", buffer.size(), end);
  }
  store.owned = static_cast<LocalIndex>(store.x.size());
}

}  // namespace kessler::parallel
