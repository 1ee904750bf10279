#pragma once
// Resizing and reordering a store through its one list of arrays (the store's static fields()):
// shared by the point store and a method's own stores (OTM's nodes, solver/otm/node_store.hpp).
#include "core/error.hpp"
#include "core/types.hpp"

#include <type_traits>
#include <vector>

namespace kessler {

// Every array of `store` reordered: new index i holds what old index order[i] held (order: a
// permutation).
template <class Store>
void permuteFields(Store& store, const std::vector<LocalIndex>& order) {
  KESSLER_VERIFY(order.size() == store.x.size(), "permutation of {} entries for {} particles", order.size(),
                 store.x.size());
  Store::fields(store, [&](const char* name, auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == order.size(), "permutation of {} entries for '{}', which holds {}", order.size(),
                   name, values.size());
    std::remove_reference_t<decltype(values)> scratch(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = values[static_cast<std::size_t>(order[i])];
    values.swap(scratch);
  });
}

// Every array of `store` resized to n (new entries take their field's fresh value); all owned.
template <class Store>
void resizeFields(Store& store, std::size_t n) {
  Store::fields(store, [&](const char*, auto& values, const auto& fresh) { values.resize(n, fresh); });
  store.owned = static_cast<LocalIndex>(n);
}

}  // namespace kessler
