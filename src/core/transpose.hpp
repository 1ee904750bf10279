#pragma once
// The transpose of compressed rows, in parallel, with a result that does not depend on the number
// of threads: a per-thread counting sort. Row r's entries are [offset[r], offset[r + 1]), each
// naming a column (or none); the transpose lists each column's entries in increasing entry order,
// so by row. OTM's point-node connectivity (node -> its points' entries) and SPH's pairs (particle
// -> the pairs that lower particles list with it) are both such transposes: their gathers then sum
// in an order fixed by the data alone.
#include "core/error.hpp"
#include "core/types.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <omp.h>

namespace kessler {

// The first row of block u of nt blocks of compressed rows (row r's entries [offset[r], offset[r + 1]))
// that hold about equal numbers of entries rather than rows (rows differ in length); u = nt gives the
// number of rows. A pass that splits rows among threads by it balances their entries.
inline LocalIndex entryBlockStart(std::span<const Index> offset, int u, int nt) {
  const auto rows = offset.empty() ? LocalIndex{0} : static_cast<LocalIndex>(offset.size() - 1);
  if (u >= nt) return rows;
  const Index target = (offset.empty() ? 0 : offset.back()) * u / nt;
  return std::min(static_cast<LocalIndex>(std::lower_bound(offset.begin(), offset.end(), target) - offset.begin()),
                  rows);
}

// column(k, r): the column of entry k of row r, or -1 for an entry the transpose leaves out.
// Fills column_offset (size columns + 1), calls resize(total) with the number of entries listed,
// then emit(slot, k, r) for each, slot its place in [column_offset[c], column_offset[c + 1]).
// `scratch` (threads x columns 32-bit counters) may be kept by the caller so that a time loop does
// not allocate. At most 2^32 - 1 entries (checked).
template <class Column, class Resize, class Emit>
void transposeRows(std::span<const Index> offset, LocalIndex columns, std::vector<Index>& column_offset,
                   std::vector<std::uint32_t>& scratch, Column&& column, Resize&& resize, Emit&& emit) {
  const Index entries = offset.empty() ? 0 : offset.back();
  KESSLER_VERIFY(entries <= Index{std::numeric_limits<std::uint32_t>::max()},
                 "{} entries on one rank: more than a transpose's 32-bit counters hold", entries);
  const auto n = static_cast<std::size_t>(columns);
  column_offset.assign(n + 1, 0);
  const int threads = omp_get_max_threads();
  scratch.resize(static_cast<std::size_t>(threads) * n);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    // Blocks of equal numbers of entries; the result does not depend on where the blocks end.
    const LocalIndex begin = entryBlockStart(offset, t, nt), end = entryBlockStart(offset, t + 1, nt);
    std::uint32_t* count = scratch.data() + static_cast<std::size_t>(t) * n;
    std::fill(count, count + n, std::uint32_t{0});
    for (LocalIndex r = begin; r < end; ++r)
      for (Index k = offset[r]; k < offset[r + 1]; ++k)
        if (const LocalIndex c = column(k, r); c >= 0) ++count[c];
#pragma omp barrier
          // Column c's entries: those of thread 0's block, then thread 1's, ...
#pragma omp for schedule(static)
    for (std::size_t c = 0; c < n; ++c) {
      Index total = 0;
      for (int u = 0; u < nt; ++u) total += scratch[static_cast<std::size_t>(u) * n + c];
      column_offset[c + 1] = total;
    }
#pragma omp single
    {
      for (std::size_t c = 0; c < n; ++c) column_offset[c + 1] += column_offset[c];
      resize(static_cast<std::size_t>(column_offset[n]));
    }
#pragma omp for schedule(static)
    for (std::size_t c = 0; c < n; ++c) {
      auto at = static_cast<std::uint32_t>(column_offset[c]);
      for (int u = 0; u < nt; ++u) {
        std::uint32_t& slot = scratch[static_cast<std::size_t>(u) * n + c];
        const std::uint32_t listed = slot;
        slot = at;
        at += listed;
      }
    }
    for (LocalIndex r = begin; r < end; ++r)
      for (Index k = offset[r]; k < offset[r + 1]; ++k)
        if (const LocalIndex c = column(k, r); c >= 0) emit(static_cast<std::size_t>(count[c]++), k, r);
  }
}

}  // namespace kessler
