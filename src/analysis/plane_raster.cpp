#include "analysis/plane_raster.hpp"

#include "core/error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kessler::analysis {
namespace {

constexpr double max_cells = 67108864.0;  // 2^26 bytes of occupancy

// Breadth-first flood fill over the 4-neighbours of empty cells, marking `visited`.
EmptyRegion floodFill(const OccupancyGrid& grid, int start, std::vector<std::uint8_t>& visited) {
  EmptyRegion region;
  visited[start] = 1;
  region.cells.push_back(start);
  for (std::size_t head = 0; head < region.cells.size(); ++head) {
    const int k = region.cells[head];
    region.touches_border = region.touches_border || grid.onBorder(k);
    const int i = k % grid.nx();
    const int j = k / grid.nx();
    const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& [a, b] : neighbours) {
      if (a < 0 || b < 0 || a >= grid.nx() || b >= grid.ny()) continue;
      const int m = grid.index(a, b);
      if (visited[m] || grid.occupied(m)) continue;
      visited[m] = 1;
      region.cells.push_back(m);
    }
  }
  std::sort(region.cells.begin(), region.cells.end());
  return region;
}

}  // namespace

PlaneFrame planeFrame(const Vec3& origin, const Vec3& normal) {
  KESSLER_VERIFY(normal.norm() > 0.0, "a plane needs a non-zero normal");
  PlaneFrame frame;
  frame.origin = origin;
  frame.normal = normal.normalized();
  int least = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(frame.normal[a]) < std::abs(frame.normal[least])) least = a;
  const Vec3 axis = Vec3::Unit(least);
  frame.u = (axis - axis.dot(frame.normal) * frame.normal).normalized();
  frame.w = frame.normal.cross(frame.u);
  return frame;
}

OccupancyGrid::OccupancyGrid(const std::vector<Vec2>& points, double cell, const Vec2& keep_inside) : cell_(cell) {
  KESSLER_VERIFY(cell > 0.0 && std::isfinite(cell), "raster cell {} m must be positive", cell);
  Vec2 lo = keep_inside;
  Vec2 hi = keep_inside;
  for (const Vec2& q : points) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const auto cellsAlong = [&](int a) { return (hi[a] - lo[a]) / cell_ + 4.0; };
  if (cellsAlong(0) * cellsAlong(1) > max_cells) cell_ *= std::sqrt(cellsAlong(0) * cellsAlong(1) / max_cells);
  lo_ = lo - Vec2::Constant(2.0 * cell_);
  nx_ = static_cast<int>(std::ceil(cellsAlong(0)));
  ny_ = static_cast<int>(std::ceil(cellsAlong(1)));
  occupied_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0);
  for (const Vec2& q : points) {
    const int k = cellOf(q);
    if (k >= 0) occupied_[k] = 1;
  }
}

int OccupancyGrid::cellOf(const Vec2& q) const {
  const double fi = std::floor((q[0] - lo_[0]) / cell_);
  const double fj = std::floor((q[1] - lo_[1]) / cell_);
  if (!(fi >= 0.0 && fj >= 0.0 && fi < nx_ && fj < ny_)) return -1;
  return index(static_cast<int>(fi), static_cast<int>(fj));
}

bool OccupancyGrid::onBorder(int k) const {
  const int i = k % nx_;
  const int j = k / nx_;
  return i == 0 || j == 0 || i == nx_ - 1 || j == ny_ - 1;
}

std::optional<EmptyRegion> emptyRegionAt(const OccupancyGrid& grid, const Vec2& seed, int search) {
  const int home = grid.cellOf(seed);
  if (home < 0) return std::nullopt;
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  const int i0 = home % grid.nx();
  const int j0 = home / grid.nx();
  for (int j = std::max(0, j0 - search); j <= std::min(grid.ny() - 1, j0 + search); ++j) {
    for (int i = std::max(0, i0 - search); i <= std::min(grid.nx() - 1, i0 + search); ++i) {
      const int k = grid.index(i, j);
      if (grid.occupied(k)) continue;
      const double d = (grid.centre(k) - seed).squaredNorm();
      if (d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
  }
  if (best < 0) return std::nullopt;
  std::vector<std::uint8_t> visited(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0);
  return floodFill(grid, best, visited);
}

std::vector<EmptyRegion> emptyRegions(const OccupancyGrid& grid) {
  std::vector<std::uint8_t> visited(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0);
  std::vector<EmptyRegion> regions;
  for (int k = 0; k < grid.nx() * grid.ny(); ++k)
    if (!visited[k] && !grid.occupied(k)) regions.push_back(floodFill(grid, k, visited));
  return regions;
}

EllipseFit fitEllipse(const OccupancyGrid& grid, const EmptyRegion& region) {
  KESSLER_VERIFY(!region.cells.empty(), "an ellipse fit needs at least one cell");
  const double c = grid.cell();
  EllipseFit fit;
  fit.cells = static_cast<int>(region.cells.size());
  Vec2 sum = Vec2::Zero();
  for (const int k : region.cells) sum += grid.centre(k);
  fit.centre = sum / fit.cells;
  Eigen::Matrix2d moments = Eigen::Matrix2d::Zero();
  for (const int k : region.cells) {
    const Vec2 d = grid.centre(k) - fit.centre;
    moments += d * d.transpose();
  }
  // A uniform cell of side c adds c^2/12 to each moment about its centre.
  moments = moments / fit.cells + Eigen::Matrix2d::Identity() * (c * c / 12.0);

  std::vector<std::uint8_t> in_region(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0);
  for (const int k : region.cells) in_region[k] = 1;
  std::vector<int> band;
  for (const int k : region.cells) {
    const int i = k % grid.nx();
    const int j = k / grid.nx();
    const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& [a, b] : neighbours) {
      if (a < 0 || b < 0 || a >= grid.nx() || b >= grid.ny()) continue;
      const int m = grid.index(a, b);
      if (grid.occupied(m) && !in_region[m]) {
        in_region[m] = 2;
        band.push_back(m);
      }
    }
  }
  fit.area = (static_cast<double>(fit.cells) + 0.5 * static_cast<double>(band.size())) * c * c;
  fit.equivalent_diameter = 2.0 * std::sqrt(fit.area / std::numbers::pi);

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(moments);
  const double major_raw = 4.0 * std::sqrt(std::max(solver.eigenvalues()[1], 0.0));
  const double minor_raw = 4.0 * std::sqrt(std::max(solver.eigenvalues()[0], 0.0));
  fit.major_direction = solver.eigenvectors().col(1);
  // Widen both axes by 2 delta: (M + 2 delta)(m + 2 delta) = 4 A / pi.
  const double linear = 2.0 * (major_raw + minor_raw);
  const double constant = major_raw * minor_raw - 4.0 * fit.area / std::numbers::pi;
  const double delta = (-linear + std::sqrt(std::max(linear * linear - 16.0 * constant, 0.0))) / 8.0;
  fit.major = major_raw + 2.0 * delta;
  fit.minor = std::max(minor_raw + 2.0 * delta, 0.0);
  return fit;
}

}  // namespace kessler::analysis
