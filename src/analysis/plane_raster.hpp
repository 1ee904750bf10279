#pragma once
// Material projected onto a plane and rasterised: the 2-D occupancy grid in which holes are
// found (flood fill of the empty cells) and measured (area, second-moment ellipse).
#include "core/types.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace kessler::analysis {

using Vec2 = Eigen::Vector2d;

// An orthonormal frame (u, w, normal) with the plane through `origin`.
struct PlaneFrame {
  Vec3 origin = Vec3::Zero();
  Vec3 u = Vec3::UnitX(), w = Vec3::UnitY(), normal = Vec3::UnitZ();

  Vec2 project(const Vec3& x) const { return {u.dot(x - origin), w.dot(x - origin)}; }
  Vec3 lift(const Vec2& q) const { return origin + q[0] * u + q[1] * w; }
};

// u is the global axis least aligned with the normal, made orthogonal to it; w = normal x u.
PlaneFrame planeFrame(const Vec3& origin, const Vec3& normal);

class OccupancyGrid {
 public:
  // Cells of size `cell` covering the points and `keep_inside` with a margin of two cells; a
  // cell is occupied when a point falls in it. The cell grows if the grid would exceed 2^26
  // cells (a plate far larger than its resolution).
  OccupancyGrid(const std::vector<Vec2>& points, double cell, const Vec2& keep_inside);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  int index(int i, int j) const { return j * nx_ + i; }
  bool occupied(int k) const { return occupied_[k] != 0; }
  Vec2 centre(int k) const { return lo_ + cell_ * Vec2(k % nx_ + 0.5, k / nx_ + 0.5); }
  int cellOf(const Vec2& q) const;  // -1 outside the grid
  bool onBorder(int k) const;

 private:
  double cell_;
  Vec2 lo_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint8_t> occupied_;
};

struct EmptyRegion {
  std::vector<int> cells;       // 4-connected empty cells
  bool touches_border = false;  // the region is open to the edge of the grid
};

// The empty region holding the cell of `seed`, or, if that cell is occupied, the one holding
// the nearest empty cell within `search` cells of it (a stray point inside a hole must not hide
// it). None if every cell there is occupied.
std::optional<EmptyRegion> emptyRegionAt(const OccupancyGrid& grid, const Vec2& seed, int search);

// Every empty region, in the order of their first cell.
std::vector<EmptyRegion> emptyRegions(const OccupancyGrid& grid);

struct EllipseFit {
  double area = 0.0;                 // m^2
  double equivalent_diameter = 0.0;  // m, 2 sqrt(area/pi)
  double major = 0.0, minor = 0.0;   // m, full axes
  Vec2 centre = Vec2::Zero();
  Vec2 major_direction = Vec2::UnitX();
  int cells = 0;
};

// Area: the empty cells plus half of the occupied cells edge-adjacent to them (those straddle
// the edge and are on average half empty; without them a circular hole comes out about one cell
// too small). Axes: the ellipse of the same second moments as the empty cells (a uniform
// ellipse of semi-axes a, b has moments a^2/4, b^2/4), both axes then widened by the same
// amount so that its area equals the measured area.
EllipseFit fitEllipse(const OccupancyGrid& grid, const EmptyRegion& region);

}  // namespace kessler::analysis
