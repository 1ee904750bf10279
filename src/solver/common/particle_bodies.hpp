#pragma once
// The particles of a body for a particle method without nodes (SPH, RKPM; docs/theory.md §10, §12).
// A body meshed from an analytic shape is filled with a lattice of hexahedral elements, one particle
// at each centroid (geometry/lattice.hpp): the particle spacing is the deck's mesh_size; a structured
// box, one particle per cell. A body given as a tet mesh (a mesh file, a verification problem's
// unstructured slab) takes one particle per tet, at its barycentre, as OTM's points, with the cube
// root of its volume as its spacing (RKPM, whose cells are then the tets); latticeParticlesOf fills
// it with cubes instead (SPH).
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
  Vec3 cell = Vec3::Zero();  // zero: the body is not a lattice (a tet mesh's barycentres)
};

struct BodyParticles {
  geometry::Discretisation particles;  // a tet mesh's keeps its nodes and faces
  LatticeFrame frame;
  std::vector<std::array<int, 3>> element;  // a lattice's, per particle ({-1, -1, -1} for a tet mesh's)
};

// Throws InputError for a body that cannot be filled (thinner than two particles, say), naming it.
// `method` names the method in the refusal of refine (a lattice has one particle size).
BodyParticles particlesOf(const BodySetup& setup, const std::vector<int>& symmetry_axes, const char* method);

// The same, with a tet mesh filled with cubes as well (geometry::fillTetLattice): every body a
// lattice of hexahedral elements, as SPH's finite-element reconstruction needs (docs/theory.md §10).
// A bare particle set (a Discretisation without tetrahedra) is taken as it is.
BodyParticles latticeParticlesOf(const BodySetup& setup, const std::vector<int>& symmetry_axes, const char* method);

// Appends a body's particles to `state`: its material (the one an earlier body has, if the same), the
// particles as points (position, initial velocity, volume, mass, spacing, room temperature), their
// adjacency, and the body. Returns the index of its first particle.
LocalIndex addParticleBody(ParticleState& state, const BodySetup& setup, const BodyParticles& made);

// The particles of a body built from `setup` whose elements lie on its fixed faces (indices into
// `particles`; none for a body given as a Discretisation).
std::vector<LocalIndex> fixedParticles(const BodySetup& setup, const BodyParticles& particles);

// The particles that carry a plane's prescribed velocity: those of its body (every body if -1)
// whose centre lies within one spacing, plus the plane's tolerance, of the plane: a lattice's first
// layer (whose elements' faces lie on it, half a spacing away), the barycentres of the tets that
// touch it.
std::vector<LocalIndex> particlesOnPlane(const PointStore& points, const PlaneConstraint& plane);

}  // namespace kessler
