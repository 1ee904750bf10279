#pragma once
// Point-node connectivity in compressed rows: for each material point its neighbour nodes
// with shape-function values and gradients; and the transpose (for each node the entries
// that reference it, in increasing point order) so that nodal sums are gathers whose
// order does not depend on the number of threads.
#include "core/types.hpp"

#include <cstdint>
#include <vector>

namespace kessler::otm {

struct Connectivity {
  std::vector<Index> offset;     // size points+1; entries of point p: [offset[p], offset[p+1])
  std::vector<LocalIndex> node;  // neighbour node of each entry
  std::vector<double> N;         // shape function value at the point
  std::vector<Vec3> dN;          // its gradient

  // The transpose, for gathers over a node's points: node a's slots are [node_offset[a],
  // node_offset[a+1]); each slot holds an entry referencing the node and that entry's point, side
  // by side (one stream to write when building, one to read when gathering), sorted by point.
  // 32-bit entries: a rank holds fewer than 4e9 (checked).
  struct NodeSlot {
    std::uint32_t entry;
    LocalIndex point;
    bool operator==(const NodeSlot&) const = default;
  };
  std::vector<Index> node_offset;   // size nodes+1
  std::vector<NodeSlot> node_slot;  // the slots of all nodes

  LocalIndex points() const { return offset.empty() ? 0 : static_cast<LocalIndex>(offset.size() - 1); }
  // Sizes node, N and dN for `entries` entries. These are a run's largest arrays and their length
  // changes a little every step: when they must grow they take 1/8 of headroom, where
  // std::vector::resize would double them (hvi-100k: 0.9 KB per point of capacity never used).
  void resizeRows(std::size_t entries);
  // No rows, the arrays' memory kept: a distributed run forgets its rows at every halo build, and
  // memory freed and taken again each step costs a page fault per page written (hvi-100k on 2 ranks:
  // the shape functions took twice as long per point).
  void clear();
  // Builds node_offset and node_slot from offset and node, in parallel; the result
  // does not depend on the thread count. `scratch` (threads x nodes 32-bit counters, like the
  // entries) may be kept by the caller so that the time loop does not allocate.
  void buildTranspose(LocalIndex node_count);
  void buildTranspose(LocalIndex node_count, std::vector<std::uint32_t>& scratch);
};

}  // namespace kessler::otm
