#pragma once
// Uniform-grid cell list over a set of positions, for fixed-radius neighbour queries.
// Queries visit candidates cell by cell, then by index. The cells lie on a lattice through the
// origin of space, so for a given cell size that order is the same for any number of threads and
// in any set of positions that holds the candidates in the same relative index order (the
// overlapping sets of a distributed run's ranks; docs/parallel.md).
#include "core/types.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#if defined(__AVX2__)
#include <immintrin.h>
#endif
#include <cmath>
#include <span>
#include <utility>
#include <vector>

namespace kessler {

class CellList {
 public:
  // Bins positions [0, count) into cubic cells of edge `cell_size`, enlarged if the grid would have
  // far more cells than positions (e.g. for a sparse debris cloud) unless `enlarge` is false.
  void build(std::span<const Vec3> x, LocalIndex count, double cell_size, bool enlarge = true);
  // The cell size build() uses: `cell_size`, enlarged where `count` positions within `bounds` spread
  // so far that the grid would exceed a few cells per position. A distributed run's ranks find it
  // from the whole run's bounds and count (agreedCellSize), and build with it as it is: a rank's
  // part, as spread as the whole with fewer positions, would be enlarged further, and its queries
  // would meet their candidates in another order.
  struct Bounds {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  };
  static Bounds boundsOf(std::span<const Vec3> x, LocalIndex count);
  static double enlargedSize(const Bounds& bounds, std::int64_t count, double cell_size);

  // Calls f(index, squared distance) for every binned position within `radius` of q.
  template <typename F>
  void forEachWithin(const Vec3& q, double radius, F&& f) const {
    forEachWithinFrom(q, radius, 0, std::forward<F>(f));
  }
  // The same for the positions of index `first` and above alone (a pair search that lists each pair
  // by its lower end skips the others without a call).
  template <typename F>
  void forEachWithinFrom(const Vec3& q, double radius, LocalIndex first, F&& f) const;

  // Calls f(cell) for every cell that may hold a position within `radius` of q; the binned
  // positions of a cell are indexAt(s) for s in [cellBegin(cell), cellEnd(cell)).
  template <typename F>
  void forEachCellNear(const Vec3& q, double radius, F&& f) const;
  // Calls f(neighbour) for the cell itself and the up to 26 cells around it.
  template <typename F>
  void forEachCellAround(long cell, F&& f) const;
  long cellCount() const { return static_cast<long>(start_.size()) - 1; }
  LocalIndex cellBegin(long cell) const { return start_[static_cast<std::size_t>(cell)]; }
  LocalIndex cellEnd(long cell) const { return start_[static_cast<std::size_t>(cell) + 1]; }
  LocalIndex indexAt(LocalIndex slot) const { return sorted_[static_cast<std::size_t>(slot)]; }

  double cellSize() const { return cell_; }

 private:
  std::array<int, 3> cellOf(const Vec3& x) const;
  // The cells [lo, hi] (per axis, clamped to the grid) that may hold a position within `radius`
  // of q; false if there are none.
  bool cellRange(const Vec3& q, double radius, std::array<int, 3>& lo, std::array<int, 3>& hi) const;
  long flat(int i, int j, int k) const { return (static_cast<long>(k) * dims_[1] + j) * dims_[0] + i; }

  Vec3 base_ = Vec3::Zero();  // the lattice coordinates (integers) of the grid's first cell
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<LocalIndex> start_;   // size cells+1
  std::vector<LocalIndex> sorted_;  // position indices grouped by cell
  // Their coordinates, in the same order and one array each, so that the distances of a run of
  // positions are computed four or eight at a time.
  std::array<std::vector<double>, 3> sorted_x_;
  std::vector<long> cell_of_;       // build scratch, kept so that rebuilding does not allocate
  std::vector<LocalIndex> cursor_;  // build scratch
};

inline std::array<int, 3> CellList::cellOf(const Vec3& x) const {
  std::array<int, 3> c{};
  // Clamped to one cell beyond the grid before the conversion: a far query stays in int's range,
  // and a NaN (which no clamp changes, and whose conversion is undefined) is below the grid.
  for (int d = 0; d < 3; ++d) {
    const double cell = std::floor(x[d] / cell_) - base_[d];
    c[d] = std::isnan(cell) ? -1 : static_cast<int>(std::clamp(cell, -1.0, static_cast<double>(dims_[d])));
  }
  return c;
}

inline bool CellList::cellRange(const Vec3& q, double radius, std::array<int, 3>& lo, std::array<int, 3>& hi) const {
  lo = cellOf(q - Vec3::Constant(radius));
  hi = cellOf(q + Vec3::Constant(radius));
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::max(lo[d], 0);
    hi[d] = std::min(hi[d], dims_[d] - 1);
    if (lo[d] > hi[d]) return false;
  }
  return true;
}

template <typename F>
void CellList::forEachCellNear(const Vec3& q, double radius, F&& f) const {
  std::array<int, 3> lo, hi;
  if (!cellRange(q, radius, lo, hi)) return;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) f(flat(i, j, k));
}

template <typename F>
void CellList::forEachCellAround(long cell, F&& f) const {
  const int i0 = static_cast<int>(cell % dims_[0]);
  const int j0 = static_cast<int>(cell / dims_[0] % dims_[1]);
  const int k0 = static_cast<int>(cell / (static_cast<long>(dims_[0]) * dims_[1]));
  for (int k = std::max(k0 - 1, 0); k <= std::min(k0 + 1, dims_[2] - 1); ++k)
    for (int j = std::max(j0 - 1, 0); j <= std::min(j0 + 1, dims_[1] - 1); ++j)
      for (int i = std::max(i0 - 1, 0); i <= std::min(i0 + 1, dims_[0] - 1); ++i) f(flat(i, j, k));
}

template <typename F>
void CellList::forEachWithinFrom(const Vec3& q, double radius, LocalIndex first, F&& f) const {
  const double r2 = radius * radius;
  std::array<int, 3> lo, hi;
  if (!cellRange(q, radius, lo, hi)) return;
  // The cells of a row along x are consecutive, so are their positions: one loop per row, the
  // distances first (vectorised), then the calls.
  constexpr int chunk = 64;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j) {
      const LocalIndex end = start_[flat(hi[0], j, k) + 1];
      for (LocalIndex begin = start_[flat(lo[0], j, k)]; begin < end; begin += chunk) {
        const int n = std::min<int>(chunk, end - begin);
        const double* x = sorted_x_[0].data() + begin;
        const double* y = sorted_x_[1].data() + begin;
        const double* z = sorted_x_[2].data() + begin;
        const LocalIndex* index = sorted_.data() + begin;
        // The hits as the bits of a mask, visited in order: no branch per candidate (five in six
        // lie outside the radius, and a branch on each would be mispredicted).
        double d2[chunk];
        std::uint64_t hits = 0;
        int i = 0;
#if defined(__AVX2__)
        const __m256d qx = _mm256_set1_pd(q[0]), qy = _mm256_set1_pd(q[1]), qz = _mm256_set1_pd(q[2]);
        const __m256d r2v = _mm256_set1_pd(r2);
        const __m128i below = _mm_set1_epi32(first - 1);
        for (; i + 4 <= n; i += 4) {
          const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(x + i), qx);
          const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(y + i), qy);
          const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(z + i), qz);
          const __m256d d =
              _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
          _mm256_storeu_pd(d2 + i, d);
          const __m128i above = _mm_cmpgt_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(index + i)), below);
          const int within = _mm256_movemask_pd(_mm256_cmp_pd(d, r2v, _CMP_LE_OQ));
          hits |= static_cast<std::uint64_t>(within & _mm_movemask_ps(_mm_castsi128_ps(above))) << i;
        }
#endif
        for (; i < n; ++i) {
          const double dx = x[i] - q[0], dy = y[i] - q[1], dz = z[i] - q[2];
          d2[i] = dx * dx + dy * dy + dz * dz;
          hits |= static_cast<std::uint64_t>(d2[i] <= r2 && index[i] >= first) << i;
        }
        for (; hits != 0; hits &= hits - 1) {
          const int hit = std::countr_zero(hits);
          f(index[hit], d2[hit]);
        }
      }
    }
}

}  // namespace kessler
