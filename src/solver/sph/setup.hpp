#pragma once
// SPH's particles for a problem (docs/theory.md §10): each body's particles as
// solver/common/particle_bodies.hpp makes them.
#include "solver/common/problem.hpp"
#include "solver/sph/model.hpp"

namespace kessler::sph {

// Throws InputError for a body that cannot be filled (thinner than two particles, say), naming it.
Model buildModel(const Problem& problem);

}  // namespace kessler::sph
