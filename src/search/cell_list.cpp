#include "search/cell_list.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace kessler {

// The bounding box (min and max are exact, so the parallel reduction gives the same box for any
// thread count).
CellList::Bounds CellList::boundsOf(std::span<const Vec3> x, LocalIndex count) {
  double lo0 = 0.0, lo1 = 0.0, lo2 = 0.0, hi0 = 0.0, hi1 = 0.0, hi2 = 0.0;
  if (count > 0) {
    lo0 = hi0 = x[0][0];
    lo1 = hi1 = x[0][1];
    lo2 = hi2 = x[0][2];
  }
#pragma omp parallel for schedule(static) reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2)
  for (LocalIndex a = 0; a < count; ++a) {
    lo0 = std::min(lo0, x[a][0]);
    lo1 = std::min(lo1, x[a][1]);
    lo2 = std::min(lo2, x[a][2]);
    hi0 = std::max(hi0, x[a][0]);
    hi1 = std::max(hi1, x[a][1]);
    hi2 = std::max(hi2, x[a][2]);
  }
  const Bounds b{Vec3(lo0, lo1, lo2), Vec3(hi0, hi1, hi2)};
  KESSLER_VERIFY(b.lo.allFinite() && b.hi.allFinite(), "cell list: non-finite node position");
  return b;
}

// At most ~4 cells per position: a few far-flung fragments must not make the grid (and the
// memory) explode.
double CellList::enlargedSize(const Bounds& b, std::int64_t count, double cell_size) {
  KESSLER_VERIFY(cell_size > 0.0 && std::isfinite(cell_size), "cell list: invalid cell size {}", cell_size);
  const Vec3 extent = (b.hi - b.lo).cwiseMax(Vec3::Constant(1e-300));
  const double max_cells = 4.0 * std::max<double>(static_cast<double>(count), 1.0) + 64.0;
  auto cellCount = [&](double cell) {
    double n = 1.0;
    for (int d = 0; d < 3; ++d) n *= std::floor(extent[d] / cell) + 1.0;
    return n;
  };
  double cell = cell_size;
  while (cellCount(cell) > max_cells) cell *= 1.26;
  return cell;
}

void CellList::build(std::span<const Vec3> x, LocalIndex count, double cell_size, bool enlarge) {
  const Bounds bounds = boundsOf(x, count);
  const Vec3 &lo = bounds.lo, &hi = bounds.hi;
  KESSLER_VERIFY(cell_size > 0.0 && std::isfinite(cell_size), "cell list: invalid cell size {}", cell_size);
  cell_ = enlarge ? enlargedSize(bounds, count, cell_size) : cell_size;
  // The cells lie on a lattice through the origin of space, not through this set's corner: the cell
  // a position falls in, and so the order in which a query visits positions, is then the same in
  // any set that holds it, given the cell size (a distributed run's ranks hold overlapping sets and
  // their sums must agree bitwise; docs/parallel.md).
  for (int d = 0; d < 3; ++d) {
    base_[d] = std::floor(lo[d] / cell_);
    dims_[d] = static_cast<int>(std::floor(hi[d] / cell_) - base_[d]) + 1;
  }
  const long cells = static_cast<long>(dims_[0]) * dims_[1] * dims_[2];

  // Counting sort of positions into cells: stable, so each cell lists indices in order.
  std::vector<long>& cell_of = cell_of_;
  cell_of.resize(static_cast<std::size_t>(count));
  start_.assign(static_cast<std::size_t>(cells) + 1, 0);
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < count; ++a) {
    std::array<int, 3> c = cellOf(x[a]);
    for (int d = 0; d < 3; ++d) c[d] = std::clamp(c[d], 0, dims_[d] - 1);
    cell_of[a] = flat(c[0], c[1], c[2]);
  }
  for (LocalIndex a = 0; a < count; ++a) ++start_[cell_of[a] + 1];
  for (long c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  sorted_.resize(static_cast<std::size_t>(count));
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (LocalIndex a = 0; a < count; ++a) sorted_[cursor_[cell_of[a]]++] = a;
  // Positions in cell order: a query streams through them instead of jumping through x.
  for (int d = 0; d < 3; ++d) sorted_x_[d].resize(static_cast<std::size_t>(count));
#pragma omp parallel for schedule(static)
  for (LocalIndex s = 0; s < count; ++s)
    for (int d = 0; d < 3; ++d) sorted_x_[d][s] = x[sorted_[s]][d];
}

}  // namespace kessler
