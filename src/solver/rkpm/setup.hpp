#pragma once
// RKPM's particles for a problem (docs/theory.md §12): each body's particles as
// solver/common/particle_bodies.hpp makes them, with their cells: a lattice's elements, or a tet
// mesh's tetrahedra.
#include "solver/common/problem.hpp"
#include "solver/rkpm/model.hpp"

namespace kessler::rkpm {

// Throws InputError for a body that cannot be filled, naming it.
Model buildModel(const Problem& problem);

}  // namespace kessler::rkpm
