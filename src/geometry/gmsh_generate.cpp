// Tetrahedral meshing of analytic shapes with Gmsh's OpenCASCADE kernel.
#include "core/error.hpp"
#include "core/overloaded.hpp"
#include "geometry/gmsh_backend.hpp"

#include <gmsh.h>

#include <cmath>

namespace kessler::geometry::detail {

namespace {

// OpenCASCADE tolerances are absolute (1e-8 by default) and Gmsh's meshers behave best on
// unit-sized models: a 5 mm sphere built in metres meshes ~5x slower and differently. So the
// model is built in units of L, a power of two near the shape's size, so that the scaling back
// to metres adds no round-off (a vertex on a symmetry plane stays exactly on it).
double modelUnit(const Shape& shape) {
  const BoundingBox box = bounds(shape);
  const double extent = (box.max - box.min).maxCoeff();
  return std::exp2(std::round(std::log2(extent)));
}

int addShape(const Shape& shape, double unit) {
  return std::visit(Overloaded{
                        [unit](const Sphere& s) {
                          const Vec3 c = s.center / unit;
                          return gmsh::model::occ::addSphere(c.x(), c.y(), c.z(), s.radius / unit);
                        },
                        [unit](const Box& b) {
                          const Vec3 lo = b.min / unit;
                          const Vec3 size = (b.max - b.min) / unit;
                          return gmsh::model::occ::addBox(lo.x(), lo.y(), lo.z(), size.x(), size.y(),
                                                          size.z());
                        },
                        [unit](const Cylinder& c) {
                          const Vec3 base = c.base / unit;
                          const Vec3 axis = c.axis / unit;
                          return gmsh::model::occ::addCylinder(base.x(), base.y(), base.z(), axis.x(),
                                                               axis.y(), axis.z(), c.radius / unit);
                        },
                        [](const MeshFile&) -> int {
                          KESSLER_VERIFY(false, "a mesh file cannot be meshed again");
                          return -1;
                        },
                    },
                    shape);
}

// Keeps the part of the volume on the non-negative side of every symmetry plane by
// intersecting it with a box that encloses the shape on that side.
void clipBySymmetry(int volume_tag, const MeshRequest& request, double unit) {
  const BoundingBox box = bounds(request.shape);
  Vec3 lo = box.min / unit - Vec3::Ones();
  const Vec3 hi = box.max / unit + Vec3::Ones();
  for (const int axis : request.symmetry_axes) lo[axis] = 0.0;
  const Vec3 size = hi - lo;
  if ((size.array() <= 0.0).any()) {
    throw InputError(fmt::format("the {} lies entirely on the negative side of a symmetry plane",
                                 kindName(request.shape)));
  }
  const int clip = gmsh::model::occ::addBox(lo.x(), lo.y(), lo.z(), size.x(), size.y(), size.z());
  gmsh::vectorpair kept;
  std::vector<gmsh::vectorpair> kept_map;
  gmsh::model::occ::intersect({{3, volume_tag}}, {{3, clip}}, kept, kept_map);
  bool has_volume = false;
  for (const auto& [dim, tag] : kept) has_volume = has_volume || dim == 3;
  if (!has_volume) {
    throw InputError(fmt::format("the {} lies entirely on the negative side of a symmetry plane",
                                 kindName(request.shape)));
  }
}

void setSizes(const MeshRequest& request, double unit) {
  // Sizes come from MeshSizeMax and, with refinement, a background field alone: not from
  // the CAD points (which carry no size) nor extended inwards from the surface mesh.
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", request.mesh_size / unit);
  if (!request.refine) return;
  const Refinement& refine = *request.refine;
  const Vec3 c = refine.center / unit;
  const int ball = gmsh::model::mesh::field::add("Ball");
  gmsh::model::mesh::field::setNumber(ball, "XCenter", c.x());
  gmsh::model::mesh::field::setNumber(ball, "YCenter", c.y());
  gmsh::model::mesh::field::setNumber(ball, "ZCenter", c.z());
  gmsh::model::mesh::field::setNumber(ball, "Radius", refine.radius / unit);
  gmsh::model::mesh::field::setNumber(ball, "VIn", refine.size / unit);
  gmsh::model::mesh::field::setNumber(ball, "VOut", request.mesh_size / unit);
  // A transition layer one coarse element thick grades the size instead of jumping.
  gmsh::model::mesh::field::setNumber(ball, "Thickness", request.mesh_size / unit);
  gmsh::model::mesh::field::setAsBackgroundMesh(ball);
}

}  // namespace

TetMesh generateMesh(const MeshRequest& request) {
  const double unit = modelUnit(request.shape);
  GmshSession session;
  try {
    // Delaunay (1) with a fixed seed, so that the mesh depends only on the request. HXT (10) is
    // 3-5x faster but its meshes of the same request differ from run to run (Gmsh 4.8).
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);
    gmsh::option::setNumber("Mesh.RandomSeed", 1);
    gmsh::model::add("kessler");
    const int tag = addShape(request.shape, unit);
    if (!request.symmetry_axes.empty()) clipBySymmetry(tag, request, unit);
    gmsh::model::occ::synchronize();
    setSizes(request, unit);
    gmsh::model::mesh::generate(3);
    return extractTets(unit);
  } catch (const Error&) {
    throw;
  } catch (...) {
    throw Error(fmt::format("Gmsh failed to mesh the {} (mesh_size {} m): {}", kindName(request.shape),
                            request.mesh_size, currentGmshError()));
  }
}

}  // namespace kessler::geometry::detail
