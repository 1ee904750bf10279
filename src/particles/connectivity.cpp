#include "particles/connectivity.hpp"

namespace kessler {

void Connectivity::buildTranspose(LocalIndex node_count) {
  const LocalIndex np = points();
  const Index entries = offset.empty() ? 0 : offset.back();
  entry_point.resize(static_cast<std::size_t>(entries));
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < np; ++p)
    for (Index k = offset[p]; k < offset[p + 1]; ++k) entry_point[k] = p;

  // Counting sort by node; scanning entries in order keeps each node's list sorted by point.
  node_offset.assign(static_cast<std::size_t>(node_count) + 1, 0);
  for (Index k = 0; k < entries; ++k) ++node_offset[node[k] + 1];
  for (LocalIndex a = 0; a < node_count; ++a) node_offset[a + 1] += node_offset[a];
  node_entry.resize(static_cast<std::size_t>(entries));
  std::vector<Index> cursor(node_offset.begin(), node_offset.end() - 1);
  for (Index k = 0; k < entries; ++k) node_entry[cursor[node[k]]++] = k;
}

}  // namespace kessler
