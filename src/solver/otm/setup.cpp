#include "solver/otm/setup.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "geometry/structured_mesh.hpp"
#include "solver/otm/morton_order.hpp"

#include <algorithm>
#include <cmath>

namespace kessler::otm {

int addBody(Model& model, const std::string& name, const MaterialPtr& material, const geometry::Discretisation& mesh,
            const Vec3& velocity, bool faces) {
  KESSLER_VERIFY(material != nullptr, "body '{}' has no material", name);
  const int body = static_cast<int>(model.bodies.size());
  int material_index = -1;
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (model.materials[m] == material) material_index = static_cast<int>(m);
  if (material_index < 0) {
    material_index = static_cast<int>(model.materials.size());
    model.materials.push_back(material);
  }

  NodeStore& nodes = model.nodes;
  PointStore& points = model.points;
  const auto node_begin = static_cast<std::size_t>(nodes.size());
  const auto point_begin = static_cast<std::size_t>(points.size());
  nodes.resize(node_begin + mesh.nodes.size());
  points.resize(point_begin + mesh.points.size());
  model.lme_lambda.resize(points.size(), Vec3::Zero());

  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const std::size_t a = node_begin + i;
    nodes.id[a] = static_cast<Index>(a);
    nodes.body[a] = body;
    nodes.x[a] = mesh.nodes[i];
    nodes.v[a] = velocity;
  }
  const double rho0 = material->referenceDensity();
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const std::size_t p = point_begin + i;
    points.id[p] = static_cast<Index>(p);
    points.body[p] = body;
    points.x[p] = mesh.points[i];
    points.v[p] = velocity;
    points.volume[p] = points.volume0[p] = mesh.volumes[i];
    points.mass[p] = rho0 * mesh.volumes[i];
    points.spacing0[p] = mesh.spacings[i];
    points.temperature[p] = 293.15;
  }
  const auto offset = static_cast<LocalIndex>(point_begin);
  for (const auto& [i, j] : mesh.adjacency) {
    KESSLER_VERIFY(i >= 0 && i < j && static_cast<std::size_t>(j) < mesh.points.size(),
                   "body '{}': adjacency pair ({}, {}) is not ordered within its {} points", name, i, j,
                   mesh.points.size());
    model.adjacency.push_back({points.id[offset + i], points.id[offset + j]});
    const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
    model.adjacency_length0.push_back((mesh.points[b] - mesh.points[a]).norm());
  }
  if (faces) {
    KESSLER_VERIFY(!mesh.faces.empty() || mesh.points.empty(),
                   "body '{}': a sliding contact needs its tetrahedra's faces", name);
    const auto node_id = [&](LocalIndex i) { return nodes.id[node_begin + static_cast<std::size_t>(i)]; };
    const auto point_id = [&](LocalIndex i) {
      return i < 0 ? Index{-1} : points.id[point_begin + static_cast<std::size_t>(i)];
    };
    for (const geometry::TetFace& f : mesh.faces)
      model.faces.push_back(
          {{node_id(f.nodes[0]), node_id(f.nodes[1]), node_id(f.nodes[2])}, point_id(f.inner), point_id(f.outer)});
  }
  model.bodies.push_back(BodyInfo{name, material_index});
  return body;
}

void constrainNode(Model& model, LocalIndex node, int axis, double velocity) {
  model.nodes.constrained[node] |= static_cast<std::uint8_t>(1u << axis);
  model.nodes.prescribed_v[node][axis] = velocity;
}

std::vector<LocalIndex> nodesOnPlane(const Model& model, int axis, double offset, double tolerance, int body) {
  std::vector<LocalIndex> on;
  for (LocalIndex a = 0; a < model.nodes.size(); ++a) {
    if (body >= 0 && model.nodes.body[a] != body) continue;
    if (std::abs(model.nodes.x[a][axis] - offset) > tolerance) continue;
    on.push_back(a);
  }
  return on;
}

LocalIndex constrainPlane(Model& model, int axis, double offset, double tolerance, double velocity, int body) {
  const std::vector<LocalIndex> on = nodesOnPlane(model, axis, offset, tolerance, body);
  for (const LocalIndex a : on) constrainNode(model, a, axis, velocity);
  return static_cast<LocalIndex>(on.size());
}

void dropHeldFaces(Model& model) {
  // A boundary face whose nodes are all held along one axis, on one plane normal to it, and not all
  // held in every direction (a symmetry plane, a roller): the body goes on beyond it. A body held
  // whole (a rigid wall) keeps its faces.
  const NodeStore& nodes = model.nodes;
  const auto held = [&](const ContactFace& f) {
    if (f.outer >= 0) return false;
    bool rigid = true;
    for (const Index a : f.nodes) rigid = rigid && (nodes.constrained[static_cast<std::size_t>(a)] & 7u) == 7u;
    if (rigid) return false;
    for (int axis = 0; axis < 3; ++axis) {
      bool all = true;
      for (const Index a : f.nodes) all = all && ((nodes.constrained[static_cast<std::size_t>(a)] >> axis) & 1u) != 0;
      if (!all) continue;
      const double x0 = nodes.x[static_cast<std::size_t>(f.nodes[0])][axis];
      const double size =
          (nodes.x[static_cast<std::size_t>(f.nodes[1])] - nodes.x[static_cast<std::size_t>(f.nodes[0])]).norm();
      bool flat = true;
      for (const Index a : f.nodes)
        flat = flat && std::abs(nodes.x[static_cast<std::size_t>(a)][axis] - x0) <= 1e-6 * size;
      if (flat) return true;
    }
    return false;
  };
  model.faces.erase(std::remove_if(model.faces.begin(), model.faces.end(), held), model.faces.end());
}

void orderForLocality(Model& model) {
  sortForLocality(model);
  // Before the numbering, each entry's id is still its index at creation.
  std::vector<Index> node_now(model.nodes.id.size()), point_now(model.points.id.size());
  for (std::size_t a = 0; a < node_now.size(); ++a)
    node_now[static_cast<std::size_t>(model.nodes.id[a])] = static_cast<Index>(a);
  for (std::size_t p = 0; p < point_now.size(); ++p)
    point_now[static_cast<std::size_t>(model.points.id[p])] = static_cast<Index>(p);
  for (ContactFace& f : model.faces) {
    for (Index& a : f.nodes) a = node_now[static_cast<std::size_t>(a)];
    f.inner = point_now[static_cast<std::size_t>(f.inner)];
    if (f.outer >= 0) f.outer = point_now[static_cast<std::size_t>(f.outer)];
  }
  numberInOrder(model);
}

Model buildModel(const Problem& problem) {
  Model model;
  const bool faces = problem.settings.solver.contact.sliding();
  for (const BodySetup& setup : problem.bodies) {
    const LocalIndex first_node = model.nodes.size(), first_point = model.points.size();
    const auto* request = std::get_if<geometry::MeshRequest>(&setup.mesh);
    const auto* structured = std::get_if<geometry::StructuredBox>(&setup.mesh);
    geometry::Discretisation meshed;
    if (request != nullptr) {
      geometry::MeshRequest clipped = *request;
      clipped.symmetry_axes = problem.symmetry_axes;
      meshed = geometry::discretise(geometry::meshShape(clipped));
    } else if (structured != nullptr) {
      meshed = geometry::discretise(geometry::structuredBoxMesh(structured->box, structured->cells));
    }
    const geometry::Discretisation& disc =
        request != nullptr || structured != nullptr ? meshed : std::get<geometry::Discretisation>(setup.mesh);
    const int body = addBody(model, setup.name, setup.material, disc, setup.velocity, faces);
    if (setup.velocity_field) {
      for (LocalIndex a = first_node; a < model.nodes.size(); ++a)
        model.nodes.v[a] = setup.velocity_field(model.nodes.x[a]);
      for (LocalIndex p = first_point; p < model.points.size(); ++p)
        model.points.v[p] = setup.velocity_field(model.points.x[p]);
    }
    if (request == nullptr) continue;
    for (LocalIndex local : geometry::selectNodes(request->shape, disc.nodes, setup.fixed))
      for (int axis = 0; axis < 3; ++axis) constrainNode(model, first_node + local, axis);
    // Nodes on a symmetry plane (Gmsh puts them on the clipping plane up to round-off) keep a
    // zero normal velocity; a body clear of the plane has none.
    for (int axis : problem.symmetry_axes) constrainPlane(model, axis, 0.0, 1e-6 * request->mesh_size, 0.0, body);
    log::info("  body {:<14} {:>9} nodes {:>9} points", setup.name, disc.nodes.size(), disc.points.size());
  }
  // A roller holds the nodes on it, as a symmetry plane (OTM's nodes interpolate: no mirror image).
  for (const Roller& roller : problem.rollers)
    constrainPlane(model, roller.axis, roller.offset, roller.tolerance, 0.0, -1);
  for (const PlaneConstraint& plane : problem.planes)
    constrainPlane(model, plane.axis, plane.offset, plane.tolerance, plane.velocity, plane.body);
  if (problem.prepare) problem.prepare(model);
  dropHeldFaces(model);
  // Points and nodes in Morton order, numbered in it, once, before anything refers to their
  // indices or ids (the first output and checkpoint already see this order; a restart continues it).
  orderForLocality(model);
  return model;
}

}  // namespace kessler::otm
