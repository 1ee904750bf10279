#pragma once
// What the distributed-step tests share (test_otm_ranks.cpp, test_sph_ranks.cpp): a fracturing
// material, bitwise comparison, and the own entries of a rank that differ from one process's.
#include "material/impact_material.hpp"
#include "material/library.hpp"

#include <cstring>
#include <span>
#include <unordered_map>

namespace kessler::testing {

// Aluminium 6061-T6 with its strength, equation of state and fracture energy (material/library.hpp).
inline MaterialPtr fracturing() {
  return std::make_shared<ImpactMaterial>("al", library::find("Al6061-T6").parameters);
}

inline bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
template <class M>
bool same(const M& a, const M& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// Entries of `mine` that are this rank's own and differ from the entry of `whole` with the same id.
template <class Store, class Compare>
int differing(const Store& mine, std::span<const std::uint8_t> ghost, const Store& whole, Compare&& compare) {
  std::unordered_map<Index, LocalIndex> index;
  for (LocalIndex i = 0; i < whole.owned; ++i) index[whole.id[i]] = i;
  int differ = 0;
  for (LocalIndex i = 0; i < mine.owned; ++i) {
    if (!ghost.empty() && ghost[static_cast<std::size_t>(i)]) continue;
    const auto found = index.find(mine.id[i]);
    if (found == index.end() || !compare(i, found->second)) ++differ;
  }
  return differ;
}

}  // namespace kessler::testing
