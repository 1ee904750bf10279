#include "solver/otm/connectivity.hpp"

#include "core/error.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

namespace kessler::otm {

// Counting sort of the entries by node, in parallel and deterministic: thread t takes a
// contiguous block of points (so of entries), counts its entries per node, and writes them after
// those of threads 0..t-1 for the same node. Scanning each block in entry order keeps every
// node's list sorted by point, whatever the thread count.
namespace {

template <class T>
void resizeWithHeadroom(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 8);
  v.resize(n);
}

}  // namespace

void Connectivity::resizeRows(std::size_t entries) {
  resizeWithHeadroom(node, entries);
  resizeWithHeadroom(N, entries);
  resizeWithHeadroom(dN, entries);
}

void Connectivity::clear() {
  offset.clear();
  node.clear();
  N.clear();
  dN.clear();
  node_offset.clear();
  node_slot.clear();
}

void Connectivity::buildTranspose(LocalIndex node_count) {
  std::vector<std::uint32_t> scratch;
  buildTranspose(node_count, scratch);
}

void Connectivity::buildTranspose(LocalIndex node_count, std::vector<std::uint32_t>& scratch) {
  const LocalIndex np = points();
  const Index entries = offset.empty() ? 0 : offset.back();
  KESSLER_VERIFY(entries <= Index{std::numeric_limits<std::uint32_t>::max()},
                 "{} point-node entries on one rank: more than the transpose's 32-bit indices hold", entries);
  resizeWithHeadroom(node_slot, static_cast<std::size_t>(entries));
  node_offset.assign(static_cast<std::size_t>(node_count) + 1, 0);
  const int threads = omp_get_max_threads();
  scratch.resize(static_cast<std::size_t>(threads) * static_cast<std::size_t>(node_count));
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    // Blocks of equal numbers of entries rather than points (contact rows are longer, debris rows
    // empty); the result does not depend on where the blocks end.
    auto blockStart = [&](int u) {
      const Index target = entries * u / nt;
      return static_cast<LocalIndex>(std::lower_bound(offset.begin(), offset.end(), target) - offset.begin());
    };
    const LocalIndex begin = std::min(blockStart(t), np);
    const LocalIndex end = t + 1 == nt ? np : std::min(blockStart(t + 1), np);
    std::uint32_t* count = scratch.data() + static_cast<std::size_t>(t) * static_cast<std::size_t>(node_count);
    std::fill(count, count + node_count, std::uint32_t{0});
    for (LocalIndex p = begin; p < end; ++p)
      for (Index k = offset[p]; k < offset[p + 1]; ++k) ++count[node[k]];
#pragma omp barrier
        // Node a's entries: those of thread 0, then thread 1, ...; the offsets by nodes in parallel.
#pragma omp for schedule(static)
    for (LocalIndex a = 0; a < node_count; ++a) {
      Index total = 0;
      for (int u = 0; u < nt; ++u) total += scratch[static_cast<std::size_t>(u) * node_count + a];
      node_offset[a + 1] = total;
    }
#pragma omp single
    for (LocalIndex a = 0; a < node_count; ++a) node_offset[a + 1] += node_offset[a];
#pragma omp for schedule(static)
    for (LocalIndex a = 0; a < node_count; ++a) {
      auto at = static_cast<std::uint32_t>(node_offset[a]);
      for (int u = 0; u < nt; ++u) {
        std::uint32_t& c = scratch[static_cast<std::size_t>(u) * node_count + a];
        const std::uint32_t n = c;
        c = at;
        at += n;
      }
    }
    for (LocalIndex p = begin; p < end; ++p)
      for (Index k = offset[p]; k < offset[p + 1]; ++k) {
        node_slot[count[node[k]]++] = NodeSlot{static_cast<std::uint32_t>(k), p};
      }
  }
}

}  // namespace kessler::otm
