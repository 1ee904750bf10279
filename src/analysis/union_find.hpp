#pragma once
// Disjoint sets with path compression (halving) and union by size: near-constant amortised
// time per operation (Tarjan 1975), so connected components of N points cost O(N).
#include "core/types.hpp"

#include <numeric>
#include <utility>
#include <vector>

namespace kessler::analysis {

class UnionFind {
 public:
  explicit UnionFind(LocalIndex n) : parent_(static_cast<std::size_t>(n)), size_(static_cast<std::size_t>(n), 1) {
    std::iota(parent_.begin(), parent_.end(), LocalIndex{0});
  }

  LocalIndex find(LocalIndex i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }

  // Joins the sets of i and j; returns false if they were already one set. The larger set's
  // root stays root, ties go to the smaller index, so the result depends only on the order of
  // the calls, never on threads.
  bool unite(LocalIndex i, LocalIndex j) {
    LocalIndex a = find(i);
    LocalIndex b = find(j);
    if (a == b) return false;
    if (size_[a] < size_[b] || (size_[a] == size_[b] && b < a)) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

  LocalIndex setSize(LocalIndex i) { return size_[find(i)]; }

 private:
  std::vector<LocalIndex> parent_;
  std::vector<LocalIndex> size_;
};

}  // namespace kessler::analysis
