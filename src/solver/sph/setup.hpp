#pragma once
// SPH's particles for a problem (docs/theory.md §10). A body meshed from an analytic shape is filled
// with a lattice of hexahedral elements, one particle at each centroid (geometry/lattice.hpp): the
// particle spacing is the deck's mesh_size; a structured box, one particle per cell. A body given
// as a tet mesh (a mesh file, a verification problem's unstructured slab) takes one particle per
// tet, at its barycentre, as OTM's points, with the cube root of its volume as its spacing.
#include "solver/common/problem.hpp"
#include "solver/sph/model.hpp"

namespace kessler::sph {

// Throws InputError for a body that cannot be filled (thinner than two particles, say), naming it.
Model buildModel(const Problem& problem);

// The particles that carry a plane's prescribed velocity: those of its body (every body if -1)
// whose centre lies within one spacing, plus the plane's tolerance, of the plane: a lattice's first
// layer (whose elements' faces lie on it, half a spacing away), the barycentres of the tets that
// touch it.
std::vector<LocalIndex> particlesOnPlane(const Model& model, const PlaneConstraint& plane);

}  // namespace kessler::sph
