#include "solver/otm/connectivity.hpp"

#include "core/transpose.hpp"

namespace kessler::otm {

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
  transposeRows(
      offset, node_count, node_offset, scratch, [&](Index k, LocalIndex) { return node[k]; },
      [&](std::size_t entries) { resizeWithHeadroom(node_slot, entries); },
      [&](std::size_t slot, Index k, LocalIndex p) {
        node_slot[slot] = NodeSlot{static_cast<std::uint32_t>(k), p};
      });
}

}  // namespace kessler::otm
