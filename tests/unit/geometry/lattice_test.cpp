// The particle lattice of SPH's finite-element reconstruction (geometry/lattice.hpp).
#include "geometry/lattice.hpp"
#include "core/error.hpp"
#include "geometry/structured_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>

namespace kessler::geometry {
namespace {

double total(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(Lattice, BoxIsFilledExactlyWithWholeElements) {
  const Box box{Vec3(-1e-3, 0, 0), Vec3(2e-3, 1e-3, 4.1e-3)};
  const Lattice l = fillLattice(box, 0.5e-3, {});
  // 6 x 2 x 8 elements (4.1 mm / 0.5 mm rounds to 8, of 0.5125 mm).
  ASSERT_EQ(l.particles.points.size(), 96u);
  EXPECT_NEAR(total(l.particles.volumes), 3e-3 * 1e-3 * 4.1e-3, 1e-20);
  EXPECT_NEAR(l.cell[2], 4.1e-3 / 8, 1e-15);
  // Centroids half an element inside the faces.
  EXPECT_NEAR(l.particles.points.front()[0], -1e-3 + 0.25e-3, 1e-15);
  // Elements sharing a node, over a 6 x 2 x 8 block: for each offset (di, dj, dk) of the 13 forward
  // ones, (6 - |di|)(2 - |dj|)(8 - |dk|) pairs.
  std::size_t pairs = 0;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if (std::make_tuple(dk, dj, di) > std::make_tuple(0, 0, 0))
          pairs += static_cast<std::size_t>((6 - std::abs(di)) * (2 - std::abs(dj)) * (8 - std::abs(dk)));
  EXPECT_EQ(l.particles.adjacency.size(), pairs);
  EXPECT_EQ(l.count, (std::array<int, 3>{6, 2, 8}));
}

TEST(Lattice, SphereHoldsItsVolumeAndSymmetryPlanesAreElementFaces) {
  const Sphere sphere{Vec3(0, 0, 5e-3), 5e-3};
  const Lattice whole = fillLattice(sphere, 0.5e-3, {});
  const double v = 4.0 / 3.0 * std::numbers::pi * 125e-9;
  EXPECT_NEAR(total(whole.particles.volumes) / v, 1.0, 1e-12);
  const Lattice quarter = fillLattice(sphere, 0.5e-3, {0, 1});
  EXPECT_NEAR(total(quarter.particles.volumes) / (v / 4), 1.0, 1e-12);
  for (const Vec3& x : quarter.particles.points) {
    EXPECT_GT(x[0], 0.0);
    // Centroids at (i + 1/2) h from the plane x = 0.
    EXPECT_NEAR(std::fmod(x[0] / 0.5e-3, 1.0), 0.5, 1e-9);
  }
  EXPECT_NEAR(static_cast<double>(quarter.particles.points.size()),
              static_cast<double>(whole.particles.points.size()) / 4.0, 1.0);
}

TEST(Lattice, StructuredBoxHasOneParticlePerCell) {
  const Lattice l = fillBoxLattice(Box{Vec3::Zero(), Vec3(2e-3, 2e-3, 9e-3)}, {2, 2, 6});
  ASSERT_EQ(l.particles.points.size(), 24u);
  EXPECT_NEAR(l.cell[2], 1.5e-3, 1e-15);
  EXPECT_NEAR(total(l.particles.volumes), 36e-9, 1e-20);
  EXPECT_THROW(fillBoxLattice(Box{Vec3::Zero(), Vec3(1e-3, 1e-3, 1e-3)}, {1, 2, 2}), InputError);
}

// A tet mesh filled with cubes: about one cube per tet, each centroid inside the meshed box, the
// elements from the box's corner, the mesh's volume held; a bare particle set is refused.
TEST(Lattice, TetMeshIsFilledWithElementsInsideIt) {
  const Box box{Vec3(0, 0, 0), Vec3(4e-3, 3e-3, 6e-3)};
  const Discretisation tets = discretise(structuredBoxMesh(box, {4, 3, 6}));  // 6 Kuhn tets per cell
  const Lattice lattice = fillTetLattice(tets);
  const Discretisation& d = lattice.particles;
  // A whole number of elements across the box along each axis, as near the tets' spacing as fits:
  // the box filled to its faces, each element whole (no volume scaled).
  const double size = std::cbrt(volume(box) / static_cast<double>(tets.points.size()));
  const Vec3 extent = box.max - box.min;
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(lattice.count[a], std::lround(extent[a] / size));
    EXPECT_NEAR(lattice.cell[a] * lattice.count[a], extent[a], 1e-15);
  }
  EXPECT_EQ(lattice.origin, box.min);
  EXPECT_EQ(static_cast<long>(d.points.size()),
            static_cast<long>(lattice.count[0]) * lattice.count[1] * lattice.count[2]);
  for (const Vec3& x : d.points)
    EXPECT_TRUE((x.array() >= box.min.array()).all() && (x.array() <= box.max.array()).all());
  for (const double v : d.volumes) EXPECT_NEAR(v, lattice.cell.prod(), 1e-12 * lattice.cell.prod());
  EXPECT_NEAR(total(d.volumes), volume(box), 1e-12 * volume(box));
  EXPECT_GT(static_cast<double>(d.points.size()), 0.5 * static_cast<double>(tets.points.size()));
  EXPECT_LT(static_cast<double>(d.points.size()), 1.5 * static_cast<double>(tets.points.size()));

  Discretisation cloud;
  cloud.points = {Vec3::Zero()};
  cloud.volumes = {1e-9};
  EXPECT_THROW(fillTetLattice(cloud), InputError);
}

TEST(Lattice, RefusesABodyThinnerThanTwoElements) {
  const Box plate{Vec3(0, 0, 0), Vec3(10e-3, 10e-3, 0.9e-3)};
  EXPECT_THROW(fillLattice(plate, 0.5e-3, {}), InputError);
  EXPECT_NO_THROW(fillLattice(plate, 0.45e-3, {}));
  EXPECT_THROW(fillLattice(MeshFile{"x.msh", 1.0}, 1e-3, {}), InputError);
}

}  // namespace
}  // namespace kessler::geometry
