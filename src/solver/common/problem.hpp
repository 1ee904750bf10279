#pragma once
// A problem as every method receives it (docs/architecture.md): the bodies, with their materials,
// meshes and initial velocities; the boundary conditions; the settings. A method builds its own
// discretisation from it (OTM: nodes at the mesh's vertices, material points at its tets'
// barycentres). The deck gives one (app/methods.cpp), and so does each verification problem.
#include "geometry/mesh.hpp"
#include "geometry/structured_mesh.hpp"
#include "material/material.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/common/settings.hpp"
#include "solver/common/walls.hpp"

#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace kessler {

struct BodySetup {
  std::string name;
  MaterialPtr material;
  // What to mesh (clipped by the problem's symmetry planes), a tet mesh already discretised, or a
  // structured box that each method discretises its own way (neither of which symmetry planes touch).
  std::variant<geometry::MeshRequest, geometry::Discretisation, geometry::StructuredBox> mesh;
  Vec3 velocity = Vec3::Zero();
  // If set, the initial velocity at each position instead of `velocity`.
  std::function<Vec3(const Vec3&)> velocity_field;
  // With a MeshRequest: the faces of its shape whose carriers are held fixed.
  geometry::FixedNodes fixed = geometry::FixedNodes::none;
};

// The carriers of body `body` (-1: of every body) that lie on the plane x[axis] = offset, within
// `tolerance` (infinity: every carrier), have their velocity component along the axis prescribed:
// `velocity`, or history(t) at the middle of each step if a history is given (verification
// problems; a method restored from a checkpoint does not take up a history).
struct PlaneConstraint {
  int axis = 0;
  double offset = 0.0;
  double tolerance = 0.0;
  double velocity = 0.0;
  int body = -1;
  std::function<double(double)> history;
};

// A roller: a frictionless rigid plane x[axis] = offset that the bodies lie against, on its side
// `side` (+1: x[axis] >= offset; -1: x[axis] <= offset). As a symmetry plane is: OTM holds the
// carriers on it (within `tolerance`) to a zero normal velocity; SPH and RKPM see the mirror image
// of the model across it (solver/common/mirror.hpp), so that a particle beside it has the whole of
// its kernel.
struct Roller {
  int axis = 0;
  double offset = 0.0;
  int side = 1;
  double tolerance = 0.0;
};

struct Problem {
  std::string method = "otm";  // the deck's solver.method
  std::vector<BodySetup> bodies;
  // Axes normal to symmetry planes through the origin: carriers on such a plane keep a zero normal
  // velocity.
  std::vector<int> symmetry_axes;
  std::vector<Roller> rollers;
  std::vector<PlaneConstraint> planes;
  std::vector<RigidWall> walls;
  MethodSettings settings;
  // If set, called on the built state before the method's first step (a verification problem's
  // initial crack, say).
  std::function<void(ParticleState&)> prepare;
};

// Where the model lies between its mirror planes: the symmetry planes (through the origin, the model
// on their positive side) and the rollers. Throws kessler::Error for two planes on one side of an
// axis.
MirrorBox mirrorBox(const Problem& problem);

}  // namespace kessler
