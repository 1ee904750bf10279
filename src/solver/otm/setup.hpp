#pragma once
// Building a model: bodies meshed into tetrahedra become nodes and material points
// (docs/theory.md §1: V_p = V_tet, m_p = rho0 V_p, F_p = I), with fixed nodes and symmetry planes.
#include "geometry/mesh.hpp"
#include "solver/common/problem.hpp"
#include "solver/otm/model.hpp"

#include <string>
#include <vector>

namespace kessler::otm {

// Meshes every body of the problem and builds the model: its bodies with their initial velocities,
// fixed faces and symmetry planes, then its plane constraints (the nodes on each plane), then the
// problem's `prepare`.
Model buildModel(const Problem& problem);

// Appends one body from an existing discretisation (used by verification problems), with its
// faces (Model::faces) if `faces`. Returns the body index.
int addBody(Model& model, const std::string& name, const MaterialPtr& material, const geometry::Discretisation& mesh,
            const Vec3& velocity, bool faces = false);

// Drops from Model::faces those on the body's boundary that lie on a plane their nodes are held
// normal to (a symmetry plane, a roller; not a face held in every direction): no contact surface.
void dropHeldFaces(Model& model);

// Puts the points and nodes in Morton order and numbers them in it (ids = indices), the faces'
// ids with them.
void orderForLocality(Model& model);

// Prescribes velocity component `axis` of a node (0 for a fixed or symmetry constraint).
void constrainNode(Model& model, LocalIndex node, int axis, double velocity = 0.0);

// The nodes of `body` (-1: all bodies) lying on the plane x[axis] = offset, within `tolerance`.
std::vector<LocalIndex> nodesOnPlane(const Model& model, int axis, double offset, double tolerance, int body = -1);

// Constrains the normal velocity of every node of nodesOnPlane. Returns how many nodes it
// constrained.
LocalIndex constrainPlane(Model& model, int axis, double offset, double tolerance, double velocity = 0.0,
                          int body = -1);

}  // namespace kessler::otm
