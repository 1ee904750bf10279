#include "solver/otm/node_store.hpp"

#include "particles/store_fields.hpp"

namespace kessler::otm {

// Tripwire: an array added to the store but not to its fields() list would be lost by a
// permutation, a resize or a restart (the last term: `owned`, padded).
static_assert(sizeof(NodeStore) == NodeStore::field_count * sizeof(std::vector<double>) + sizeof(std::int64_t),
              "NodeStore gained or lost an array: add it to NodeStore::fields() and field_count");

void NodeStore::permute(const std::vector<LocalIndex>& order) {
  permuteFields(*this, order);
}

void NodeStore::resize(std::size_t n) {
  resizeFields(*this, n);
}

}  // namespace kessler::otm
