#pragma once
// RKPM's particles for a problem (docs/theory.md §12): each body's particles as
// solver/common/particle_bodies.hpp makes them (a lattice, a tet mesh filled with cubes), with their
// cells: the lattice's elements.
#include "solver/common/problem.hpp"
#include "solver/rkpm/model.hpp"

namespace kessler::rkpm {

// Throws InputError for a body that cannot be filled, naming it.
Model buildModel(const Problem& problem);

// The particles a plane constraint holds: with an unbounded tolerance every particle (of its body,
// if it names one); otherwise the particles whose cells have a face of the body's surface in the
// plane, within the tolerance: the lattice's first layer. The plane holds the velocity on those
// faces (held_at_surface), where the smoothed gradients of the cells read it, not at the particles
// half a cell inside.
std::vector<LocalIndex> particlesOnPlane(const Model& model, const PlaneConstraint& plane);

}  // namespace kessler::rkpm
