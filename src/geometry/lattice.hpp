#pragma once
// A shape filled with a lattice of hexahedral elements, one particle at each element's centroid:
// the particle-centroid coincident model of finite-element reconstruction (Zhang & Jia, on SPH
// simulation of satellite breakup; docs/theory.md §10). The particle spacing equals the element edge.
#include "core/types.hpp"
#include "geometry/mesh.hpp"
#include "geometry/shape.hpp"

#include <array>
#include <vector>

namespace kessler::geometry {

struct Lattice {
  // Particles (Discretisation: `points`, `volumes`, `spacings`, and `adjacency` for the pairs of
  // elements that share a node, a face, an edge or a corner; `nodes` empty).
  Discretisation particles;
  // Each particle's element (i, j, k) on the lattice, and the lattice: element (i, j, k) spans
  // origin + (i, j, k) * cell to origin + (i + 1, j + 1, k + 1) * cell.
  std::vector<std::array<int, 3>> element;
  Vec3 origin = Vec3::Zero();
  Vec3 cell = Vec3::Zero();
  std::array<int, 3> count{0, 0, 0};  // elements along each axis (some may lie outside the shape)
};

// Fills an analytic shape, clipped to x[a] >= 0 on each of `symmetry_axes` (planes through the
// origin, which the lattice takes as element faces), with elements of edge about `size`:
//  - a box: a whole number of elements along each axis, as near `size` as fits (the elements are
//    then slightly oblong, the box exact);
//  - a sphere or cylinder: cubes of edge `size`, those whose centroid lies inside; each particle's
//    volume is scaled so that the particles hold the shape's volume (the staircase of a lattice
//    would hold a few percent more or less).
// Throws InputError for a mesh file, for a size that is not positive, and for a shape whose
// thinnest part (a box's least extent, a sphere's or cylinder's diameter, a cylinder's height) is
// less than two elements: one layer of particles is not a body.
Lattice fillLattice(const Shape& shape, double size, const std::vector<int>& symmetry_axes);

// A tet mesh (a mesh file, or a verification problem's unstructured body; already clipped to its
// symmetry planes) filled with elements: those whose centroid lies in a tetrahedron, of about the
// edge the tets' particles had, the cube root of the mesh's volume per tet (so about as many
// particles), a whole number of them across the nodes' bounding box along each axis (as a box's: the
// elements slightly oblong, a box-shaped mesh filled to its faces). Each particle's volume is scaled
// so that the particles hold the mesh's volume. Throws InputError for a mesh without tetrahedra's faces, or
// whose filling is less than two elements across along an axis.
Lattice fillTetLattice(const Discretisation& tets);

// A box of exactly `cells` elements along each axis (at least two; no symmetry clipping).
Lattice fillBoxLattice(const Box& box, const std::array<int, 3>& cells);

}  // namespace kessler::geometry
