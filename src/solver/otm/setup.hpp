#pragma once
// Building a model: bodies meshed into tetrahedra become nodes and material points
// (docs/theory.md §1: V_p = V_tet, m_p = rho0 V_p, F_p = I), with fixed nodes and symmetry planes.
#include "geometry/mesh.hpp"
#include "solver/otm/model.hpp"

#include <string>
#include <vector>

namespace kessler::otm {

struct BodySetup {
  std::string name;
  MaterialPtr material;
  geometry::MeshRequest mesh;
  Vec3 velocity = Vec3::Zero();
  geometry::FixedNodes fixed = geometry::FixedNodes::none;
};

// Meshes every body and builds the model. `symmetry_axes` lists the axes normal to symmetry
// planes through the origin: nodes on such a plane keep a zero normal velocity.
Model buildModel(const std::vector<BodySetup>& bodies, const std::vector<int>& symmetry_axes);

// Appends one body from an existing discretisation (used by verification problems).
// Returns the body index.
int addBody(Model& model, const std::string& name, const MaterialPtr& material, const geometry::Discretisation& mesh,
            const Vec3& velocity);

// Prescribes velocity component `axis` of a node (0 for a fixed or symmetry constraint).
void constrainNode(Model& model, LocalIndex node, int axis, double velocity = 0.0);

// Constrains the normal velocity of every node of `body` (-1: all bodies) lying on the plane
// x[axis] = offset, within `tolerance`. Returns how many nodes it constrained.
LocalIndex constrainPlane(Model& model, int axis, double offset, double tolerance, double velocity = 0.0,
                          int body = -1);

}  // namespace kessler::otm
