#include "search/cell_list.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace kessler {

void CellList::build(const std::vector<Vec3>& x, LocalIndex count, double cell_size) {
  KESSLER_VERIFY(cell_size > 0.0 && std::isfinite(cell_size), "cell list: invalid cell size {}", cell_size);
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  if (count > 0) {
    lo = x[0];
    hi = x[0];
    for (LocalIndex a = 1; a < count; ++a) {
      lo = lo.cwiseMin(x[a]);
      hi = hi.cwiseMax(x[a]);
    }
  }
  KESSLER_VERIFY(lo.allFinite() && hi.allFinite(), "cell list: non-finite node position");
  // Keep the grid at most ~4 cells per position: a few far-flung fragments must not make
  // the grid (and the memory) explode.
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  const double max_cells = 4.0 * std::max<double>(count, 1) + 64.0;
  auto cellCount = [&](double cell) {
    double n = 1.0;
    for (int d = 0; d < 3; ++d) n *= std::floor(extent[d] / cell) + 1.0;
    return n;
  };
  cell_ = cell_size;
  while (cellCount(cell_) > max_cells) cell_ *= 1.26;
  origin_ = lo;
  for (int d = 0; d < 3; ++d) dims_[d] = static_cast<int>(std::floor(extent[d] / cell_)) + 1;
  const long cells = static_cast<long>(dims_[0]) * dims_[1] * dims_[2];

  // Counting sort of positions into cells: stable, so each cell lists indices in order.
  std::vector<long>& cell_of = cell_of_;
  cell_of.resize(static_cast<std::size_t>(count));
  start_.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (LocalIndex a = 0; a < count; ++a) {
    std::array<int, 3> c = cellOf(x[a]);
    for (int d = 0; d < 3; ++d) c[d] = std::clamp(c[d], 0, dims_[d] - 1);
    cell_of[a] = flat(c[0], c[1], c[2]);
    ++start_[cell_of[a] + 1];
  }
  for (long c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  sorted_.resize(static_cast<std::size_t>(count));
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (LocalIndex a = 0; a < count; ++a) sorted_[cursor_[cell_of[a]]++] = a;
  // Positions in cell order: a query streams through them instead of jumping through x.
  for (int d = 0; d < 3; ++d) {
    sorted_x_[d].resize(static_cast<std::size_t>(count));
    for (LocalIndex s = 0; s < count; ++s) sorted_x_[d][s] = x[sorted_[s]][d];
  }
}

}  // namespace kessler
