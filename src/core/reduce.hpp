#pragma once
// Deterministic parallel sums: fixed-size blocks summed in parallel, then the block sums in
// order, so the result is bitwise the same for any number of threads.
#include "core/types.hpp"

#include <vector>

namespace kessler {

template <typename T, typename F>
T deterministicSum(LocalIndex n, T zero, F&& term) {
  constexpr LocalIndex block = 2048;
  const LocalIndex blocks = (n + block - 1) / block;
  std::vector<T> partial(static_cast<std::size_t>(blocks), zero);
#pragma omp parallel for schedule(static)
  for (LocalIndex b = 0; b < blocks; ++b) {
    T sum = zero;
    const LocalIndex end = std::min(n, (b + 1) * block);
    for (LocalIndex i = b * block; i < end; ++i) sum += term(i);
    partial[b] = sum;
  }
  T total = zero;
  for (const T& s : partial) total += s;
  return total;
}

}  // namespace kessler
