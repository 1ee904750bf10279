#pragma once
// The particles of a body for a particle method without nodes (SPH, RKPM; docs/theory.md §10, §12):
// a lattice of hexahedral elements with one particle at each centroid (geometry/lattice.hpp). An
// analytic shape is filled at the deck's mesh_size; a structured box takes one particle per cell; a
// tet mesh (a mesh file, a verification problem's unstructured slab) is filled with cubes of about
// its tets' mean volume (about as many particles as it has tets). SPH's finite-element
// reconstruction needs the elements, and RKPM integrates over them and builds its contact surface
// from them.
#include "geometry/mesh.hpp"
#include "particles/store.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/common/problem.hpp"

#include <array>
#include <vector>

namespace kessler {

// A lattice body's elements (geometry/lattice.hpp): element (i, j, k) spans origin + (i, j, k) cell
// to origin + (i + 1, j + 1, k + 1) cell.
struct LatticeFrame {
  Vec3 origin = Vec3::Zero();
  Vec3 cell = Vec3::Zero();  // zero: the body is not a lattice (a bare particle set)
};

struct BodyParticles {
  geometry::Discretisation particles;
  LatticeFrame frame;
  std::vector<std::array<int, 3>> element;  // a lattice's, per particle ({-1, -1, -1} for a bare particle set)
};

// Throws InputError for a body that cannot be filled (thinner than two particles, say), naming it.
// `method` names the method in the refusal of refine (a lattice has one particle size). A bare
// particle set (a Discretisation without tetrahedra) is taken as it is, with no elements.
BodyParticles particlesOf(const BodySetup& setup, const std::vector<int>& symmetry_axes, const char* method);

// Appends a body's particles to `state`: its material (the one an earlier body has, if the same), the
// particles as points (position, initial velocity, volume, mass, spacing, room temperature), their
// adjacency, and the body. Returns the index of its first particle.
LocalIndex addParticleBody(ParticleState& state, const BodySetup& setup, const BodyParticles& made);

// The particles of a body built from `setup` whose elements lie on its fixed faces (indices into
// `particles`; none for a body given as a Discretisation).
std::vector<LocalIndex> fixedParticles(const BodySetup& setup, const BodyParticles& particles);

// The particles that carry a plane's prescribed velocity: those of its body (every body if -1)
// whose centre lies within one spacing, plus the plane's tolerance, of the plane: a lattice's first
// layer, whose elements' faces lie on it, half a spacing away.
std::vector<LocalIndex> particlesOnPlane(const PointStore& points, const PlaneConstraint& plane);

}  // namespace kessler
