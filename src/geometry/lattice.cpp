#include "geometry/lattice.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace kessler::geometry {

namespace {

// The thinnest part of a shape, m.
double thinnest(const Shape& shape) {
  if (const auto* b = std::get_if<Box>(&shape)) return (b->max - b->min).minCoeff();
  if (const auto* s = std::get_if<Sphere>(&shape)) return 2.0 * s->radius;
  const auto& c = std::get<Cylinder>(shape);
  return std::min(2.0 * c.radius, c.axis.norm());
}

// The volume of the shape on the positive side of the symmetry planes: exact where each plane
// either misses the shape or halves it (a sphere's centre, a cylinder's axis in the plane), a fine
// midpoint sum otherwise.
double clippedVolume(const Shape& shape, const BoundingBox& box, const BoundingBox& clipped,
                     const std::vector<int>& axes) {
  double whole = volume(shape);
  bool exact = true;
  for (const int a : axes) {
    if (box.min[a] >= 0.0) continue;
    const Vec3 centre = 0.5 * (box.min + box.max);
    const auto* c = std::get_if<Cylinder>(&shape);
    const bool halves = std::abs(centre[a]) <= 1e-12 * (box.max - box.min).maxCoeff() &&
                        (c == nullptr || (std::abs(c->base[a]) <= 1e-12 * c->radius && c->axis[a] == 0.0)) &&
                        !std::holds_alternative<Box>(shape);
    if (halves)
      whole *= 0.5;
    else
      exact = false;
  }
  if (exact) return whole;
  constexpr int n = 160;
  const Vec3 step = (clipped.max - clipped.min) / n;
  long inside = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        inside += contains(shape, clipped.min + (Vec3(i, j, k) + Vec3::Constant(0.5)).cwiseProduct(step));
  return static_cast<double>(inside) * step.prod();
}

}  // namespace

namespace {

// The elements (i, j, k) < n of edge `cell` from `origin` whose centroid `keep` accepts.
template <class Keep>
Lattice fill(const Vec3& origin, const Vec3& cell, const std::array<int, 3>& n, Keep&& keep) {
  KESSLER_VERIFY(static_cast<double>(n[0]) * n[1] * n[2] < static_cast<double>(std::numeric_limits<LocalIndex>::max()),
                 "a lattice of {} x {} x {} elements exceeds 32-bit indices", n[0], n[1], n[2]);
  Lattice lattice;
  lattice.origin = origin;
  lattice.cell = cell;
  lattice.count = n;
  std::vector<LocalIndex> at(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
  const auto flat = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i; };
  Discretisation& d = lattice.particles;
  const double element_volume = cell.prod();
  const double spacing = std::cbrt(element_volume);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Vec3 c = origin + (Vec3(i, j, k) + Vec3::Constant(0.5)).cwiseProduct(cell);
        if (!keep(c)) continue;
        at[flat(i, j, k)] = static_cast<LocalIndex>(d.points.size());
        d.points.push_back(c);
        d.volumes.push_back(element_volume);
        d.spacings.push_back(spacing);
        lattice.element.push_back({i, j, k});
      }
  // Elements that share a node: the 26 around each, each pair once (from the one earlier in order).
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const auto [i, j, k] = lattice.element[p];
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj, c = k + dk;
          if (a < 0 || b < 0 || c < 0 || a >= n[0] || b >= n[1] || c >= n[2]) continue;
          const LocalIndex q = at[flat(a, b, c)];
          if (q > static_cast<LocalIndex>(p)) d.adjacency.push_back({static_cast<LocalIndex>(p), q});
        }
  }
  return lattice;
}

}  // namespace

Lattice fillTetLattice(const Discretisation& tets) {
  const std::size_t count = tets.points.size();
  if (count == 0 || tets.faces.empty() || tets.nodes.empty())
    throw InputError("a particle lattice fills a tet mesh, and this body has no tetrahedra");
  // Each tet's four nodes, from its faces.
  std::vector<std::array<LocalIndex, 4>> corner(count, {-1, -1, -1, -1});
  auto add = [&](LocalIndex tet, LocalIndex node) {
    auto& c = corner[static_cast<std::size_t>(tet)];
    for (LocalIndex& slot : c) {
      if (slot == node) return;
      if (slot < 0) {
        slot = node;
        return;
      }
    }
  };
  for (const TetFace& f : tets.faces)
    for (const LocalIndex node : f.nodes) {
      add(f.inner, node);
      if (f.outer >= 0) add(f.outer, node);
    }
  double volume = 0.0;
  for (const double v : tets.volumes) volume += v;
  const double size = std::cbrt(volume / static_cast<double>(count));
  Vec3 lo = tets.nodes.front(), hi = lo;
  for (const Vec3& x : tets.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // As a box's (fillLattice): a whole number of elements across the bounding box along each axis, as
  // near the size as fits, so that a mesh of a box is filled to its faces exactly (a symmetry plane or
  // a roller there then mirrors a whole element).
  std::array<int, 3> n{};
  Vec3 cell;
  for (int a = 0; a < 3; ++a) {
    n[a] = std::max(1, static_cast<int>(std::lround((hi[a] - lo[a]) / size)));
    if (n[a] < 2)
      throw InputError(fmt::format("the mesh is {:.4g} mm across along {}, less than two elements of {:.4g} mm",
                                   1e3 * (hi[a] - lo[a]), "xyz"[a], 1e3 * size));
    cell[a] = (hi[a] - lo[a]) / n[a];
  }
  KESSLER_VERIFY(static_cast<double>(n[0]) * n[1] * n[2] < static_cast<double>(std::numeric_limits<LocalIndex>::max()),
                 "a lattice of {} x {} x {} elements exceeds 32-bit indices", n[0], n[1], n[2]);
  // The elements whose centroid lies in a tet (on a shared face: in either), visited tet by tet over
  // the centroids within its bounding box.
  std::vector<std::uint8_t> inside(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);
  const auto flat = [&](const std::array<int, 3>& i) {
    return (static_cast<std::size_t>(i[2]) * n[1] + i[1]) * n[0] + i[0];
  };
  for (std::size_t t = 0; t < count; ++t) {
    const auto& c = corner[t];
    if (c[3] < 0) throw InputError(fmt::format("tet {} of the mesh has fewer than four nodes in its faces", t));
    const Vec3& a = tets.nodes[static_cast<std::size_t>(c[0])];
    Mat3 edges;
    Vec3 tlo = a, thi = a;
    for (int k = 1; k < 4; ++k) {
      const Vec3& x = tets.nodes[static_cast<std::size_t>(c[static_cast<std::size_t>(k)])];
      edges.col(k - 1) = x - a;
      tlo = tlo.cwiseMin(x);
      thi = thi.cwiseMax(x);
    }
    const Mat3 inverse = edges.inverse();
    std::array<int, 3> first{}, last{};
    for (int d = 0; d < 3; ++d) {
      first[d] = std::max(0, static_cast<int>(std::ceil((tlo[d] - lo[d]) / cell[d] - 0.5 - 1e-9)));
      last[d] = std::min(n[d] - 1, static_cast<int>(std::floor((thi[d] - lo[d]) / cell[d] - 0.5 + 1e-9)));
    }
    std::array<int, 3> i{};
    for (i[2] = first[2]; i[2] <= last[2]; ++i[2])
      for (i[1] = first[1]; i[1] <= last[1]; ++i[1])
        for (i[0] = first[0]; i[0] <= last[0]; ++i[0]) {
          const Vec3 centroid = lo + cell.cwiseProduct(Vec3(i[0], i[1], i[2]) + Vec3::Constant(0.5));
          const Vec3 l = inverse * (centroid - a);
          constexpr double eps = 1e-9;
          if (l.minCoeff() >= -eps && l.sum() <= 1.0 + eps) inside[flat(i)] = 1;
        }
  }
  Lattice lattice = fill(lo, cell, n, [&](const Vec3& centroid) {
    std::array<int, 3> i{};
    for (int d = 0; d < 3; ++d)
      i[d] = std::clamp(static_cast<int>(std::floor((centroid[d] - lo[d]) / cell[d])), 0, n[d] - 1);
    return inside[flat(i)] != 0;
  });
  Discretisation& d = lattice.particles;
  if (d.points.empty())
    throw InputError(fmt::format("no element of {:.4g} mm has its centre inside the mesh", 1e3 * size));
  const double scale = volume / (static_cast<double>(d.points.size()) * cell.prod());
  for (double& v : d.volumes) v *= scale;
  return lattice;
}

Lattice fillBoxLattice(const Box& box, const std::array<int, 3>& cells) {
  const Vec3 extent = box.max - box.min;
  for (int a = 0; a < 3; ++a)
    if (cells[a] < 2 || !(extent[a] > 0.0))
      throw InputError(fmt::format("a structured box needs at least two cells along each axis, got {} x {} x {}",
                                   cells[0], cells[1], cells[2]));
  return fill(box.min, extent.cwiseQuotient(Vec3(cells[0], cells[1], cells[2])), cells,
              [](const Vec3&) { return true; });
}

Lattice fillLattice(const Shape& shape, double size, const std::vector<int>& symmetry_axes) {
  if (std::holds_alternative<MeshFile>(shape))
    throw InputError("a particle lattice fills an analytic shape (box, sphere, cylinder), not a mesh file");
  if (!(size > 0.0)) throw InputError(fmt::format("element size must be positive, got {}", size));
  if (thinnest(shape) < 2.0 * size * (1.0 - 1e-9))
    throw InputError(
        fmt::format("the {}'s thinnest part is {:.4g} mm, less than two elements of {:.4g} mm: give a "
                    "mesh_size of at most {:.4g} mm",
                    kindName(shape), 1e3 * thinnest(shape), 1e3 * size, 0.5e3 * thinnest(shape)));
  const BoundingBox box = bounds(shape);
  BoundingBox clipped = box;
  for (const int a : symmetry_axes) clipped.min[a] = std::max(clipped.min[a], 0.0);
  if (clipped.empty()) throw InputError(fmt::format("the {} lies wholly behind a symmetry plane", kindName(shape)));

  std::array<int, 3> n{};
  Vec3 cell;
  const bool is_box = std::holds_alternative<Box>(shape);
  for (int a = 0; a < 3; ++a) {
    const double extent = clipped.max[a] - clipped.min[a];
    if (is_box) {
      // A whole number of elements, as near the size as fits.
      n[a] = std::max(1, static_cast<int>(std::lround(extent / size)));
      cell[a] = extent / n[a];
    } else {
      // Cubes from the symmetry plane or the shape's edge.
      n[a] = std::max(1, static_cast<int>(std::ceil(extent / size - 1e-9)));
      cell[a] = size;
    }
  }
  Lattice lattice = fill(clipped.min, cell, n, [&](const Vec3& c) { return is_box || contains(shape, c); });
  Discretisation& d = lattice.particles;
  if (d.points.empty())
    throw InputError(fmt::format("no element of {:.4g} mm has its centre inside the {}", 1e3 * size, kindName(shape)));
  if (!is_box) {
    const double scale =
        clippedVolume(shape, box, clipped, symmetry_axes) / (static_cast<double>(d.points.size()) * cell.prod());
    for (double& v : d.volumes) v *= scale;
  }
  return lattice;
}

}  // namespace kessler::geometry
