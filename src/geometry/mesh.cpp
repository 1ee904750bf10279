#include "geometry/mesh.hpp"

#include "core/error.hpp"
#include "core/overloaded.hpp"
#include "geometry/gmsh_backend.hpp"

#include <Eigen/Geometry>  // cross products; core/types.hpp has only Core and LU

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

namespace kessler::geometry {

namespace {

bool positiveFinite(double x) {
  return std::isfinite(x) && x > 0.0;
}

void requireValidShape(const Shape& shape) {
  const auto fail = [&shape](const std::string& why) {
    throw InputError(fmt::format("invalid {} shape: {}", kindName(shape), why));
  };
  std::visit(Overloaded{
                 [&](const Sphere& s) {
                   if (!s.center.allFinite()) fail("the centre is not finite");
                   if (!positiveFinite(s.radius)) fail(fmt::format("radius {} m must be positive", s.radius));
                 },
                 [&](const Box& b) {
                   if (!b.min.allFinite() || !b.max.allFinite()) fail("a corner is not finite");
                   if ((b.max.array() <= b.min.array()).any()) fail("max must exceed min along every axis");
                 },
                 [&](const Cylinder& c) {
                   if (!c.base.allFinite() || !c.axis.allFinite()) fail("base or axis is not finite");
                   if (!positiveFinite(c.radius)) fail(fmt::format("radius {} m must be positive", c.radius));
                   if (!(c.axis.norm() > 0.0)) fail("the axis (whose length is the height) must be non-zero");
                 },
                 [&](const MeshFile& m) {
                   if (m.path.empty()) fail("the file path is empty");
                   if (!positiveFinite(m.scale)) fail(fmt::format("scale {} must be positive", m.scale));
                 },
             },
             shape);
}

// The estimated tetrahedron count of a Delaunay mesh (about 8.5 V / h^3 for a regular-ish
// mesh of edge h) must fit the 32-bit local indices; a unit slip in mesh_size is caught here
// instead of hanging in the mesher.
void requireFeasibleSize(const MeshRequest& request) {
  double estimate = 8.5 * volume(request.shape) / std::pow(request.mesh_size, 3);
  if (request.refine) {
    estimate +=
        8.5 * volume(Sphere{request.refine->center, request.refine->radius}) / std::pow(request.refine->size, 3);
  }
  if (estimate > 0.5 * std::numeric_limits<LocalIndex>::max()) {
    throw InputError(
        fmt::format("mesh_size {} m for a {} of volume {} m^3 would give about {:.2g} tetrahedra, "
                    "more than one mesh may hold",
                    request.mesh_size, kindName(request.shape), volume(request.shape), estimate));
  }
}

void requireValidRequest(const MeshRequest& request) {
  requireValidShape(request.shape);
  std::vector<int> axes = request.symmetry_axes;
  for (const int axis : axes) {
    if (axis < 0 || axis > 2) {
      throw InputError(fmt::format("symmetry axis {} must be 0 (x), 1 (y) or 2 (z)", axis));
    }
  }
  std::sort(axes.begin(), axes.end());
  if (std::adjacent_find(axes.begin(), axes.end()) != axes.end()) {
    throw InputError("a symmetry axis is listed twice");
  }
  if (std::holds_alternative<MeshFile>(request.shape)) {
    if (request.refine) throw InputError("refinement cannot be applied to an imported mesh file");
    return;
  }
  if (!positiveFinite(request.mesh_size)) {
    throw InputError(fmt::format("mesh_size {} m must be positive", request.mesh_size));
  }
  if (request.refine) {
    const Refinement& r = *request.refine;
    if (!r.center.allFinite()) throw InputError("refinement centre is not finite");
    if (!positiveFinite(r.radius)) {
      throw InputError(fmt::format("refinement radius {} m must be positive", r.radius));
    }
    if (!positiveFinite(r.size)) throw InputError(fmt::format("refinement size {} m must be positive", r.size));
  }
  requireFeasibleSize(request);
}

double signedDet(const TetMesh& mesh, const std::array<LocalIndex, 4>& t) {
  const Vec3& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).dot((mesh.vertices[t[2]] - a).cross(mesh.vertices[t[3]] - a));
}

double longestEdge(const TetMesh& mesh, const std::array<LocalIndex, 4>& t) {
  double longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      longest = std::max(longest, (mesh.vertices[t[i]] - mesh.vertices[t[j]]).norm());
    }
  }
  return longest;
}

// Orients every tet positively and refuses degenerate ones. A tet is degenerate when its
// volume is below 1e-10 of the cube of its longest edge (a regular tet has 0.118): only
// round-off or a collapsed element gets there, never a usable sliver.
template <class Fail>
void orientTets(TetMesh& mesh, const Fail& fail) {
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    auto& t = mesh.tets[e];
    const double det = signedDet(mesh, t);
    if (!(std::abs(det) / 6.0 > 1e-10 * std::pow(longestEdge(mesh, t), 3))) {
      fail(fmt::format("tetrahedron {} is degenerate (volume {:.3g} m^3)", e, det / 6.0));
    }
    if (det < 0.0) std::swap(t[2], t[3]);
  }
}

// Vertices on the plane come out of the mesher (or the user's file) within round-off of it:
// those are snapped onto it so that the symmetry condition holds exactly; anything further
// on the negative side is an error.
template <class Fail>
void checkSymmetry(TetMesh& mesh, const std::vector<int>& axes, const Fail& fail) {
  if (axes.empty() || mesh.vertices.empty()) return;
  Vec3 lo = mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double tolerance = 1e-6 * (hi - lo).maxCoeff();
  const char* names = "xyz";
  for (const int axis : axes) {
    for (Vec3& v : mesh.vertices) {
      if (v[axis] < -tolerance) {
        fail(fmt::format("vertex at {}={:.6g} m lies on the negative side of the symmetry plane {}=0", names[axis],
                         v[axis], names[axis]));
      }
      v[axis] = std::max(v[axis], 0.0);
    }
  }
}

bool indicesInRange(const TetMesh& mesh) {
  const auto count = static_cast<LocalIndex>(mesh.vertices.size());
  for (const auto& t : mesh.tets) {
    for (const LocalIndex v : t) {
      if (v < 0 || v >= count) return false;
    }
  }
  return true;
}

// Every face of the tets once, oriented out of its first tet, with the tet beyond it. Faces are
// bucketed by their smallest vertex with a counting sort, so the work is O(N); a bucket holds only
// the few dozen faces around one vertex and is sorted on its own. A face is shared by at most two
// tets in a valid (manifold) tetrahedral mesh.
std::vector<TetFace> tetFaces(const TetMesh& mesh) {
  struct Face {
    LocalIndex b = 0, c = 0;  // the two larger vertices; the smallest is the bucket
    LocalIndex tet = 0;
    std::array<LocalIndex, 3> oriented{};
  };
  // The face opposite vertex `omit` of a positively oriented tet, counter-clockwise seen from outside.
  constexpr std::array<std::array<int, 3>, 4> outward = {{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
  const auto faceOf = [&mesh, &outward](std::size_t e, int omit) {
    const auto& t = mesh.tets[e];
    const auto& o = outward[static_cast<std::size_t>(omit)];
    return std::array<LocalIndex, 3>{t[o[0]], t[o[1]], t[o[2]]};
  };
  const auto sorted = [](std::array<LocalIndex, 3> f) {
    std::sort(f.begin(), f.end());
    return f;
  };
  std::vector<std::size_t> start(mesh.vertices.size() + 1, 0);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e)
    for (int omit = 0; omit < 4; ++omit) ++start[sorted(faceOf(e, omit))[0] + 1];
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) start[v + 1] += start[v];
  std::vector<Face> faces(start.back());
  std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    for (int omit = 0; omit < 4; ++omit) {
      const auto oriented = faceOf(e, omit);
      const auto f = sorted(oriented);
      faces[cursor[f[0]]++] = Face{f[1], f[2], static_cast<LocalIndex>(e), oriented};
    }
  }
  std::vector<TetFace> out;
  out.reserve(2 * mesh.tets.size() + mesh.tets.size() / 2);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto first = faces.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = faces.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last,
              [](const Face& x, const Face& y) { return std::tie(x.b, x.c, x.tet) < std::tie(y.b, y.c, y.tet); });
    for (auto f = first; f != last;) {
      auto run = f + 1;
      while (run != last && run->b == f->b && run->c == f->c) ++run;
      if (run - f > 2) {
        throw InputError(fmt::format("the face ({}, {}, {}) is shared by {} tetrahedra (a valid mesh has at most 2)", v,
                                     f->b, f->c, run - f));
      }
      out.push_back(TetFace{f->oriented, f->tet, run - f == 2 ? (f + 1)->tet : LocalIndex{-1}});
      f = run;
    }
  }
  return out;
}

}  // namespace

TetMesh meshShape(const MeshRequest& request) {
  requireValidRequest(request);
  if (const auto* file = std::get_if<MeshFile>(&request.shape)) {
    TetMesh mesh = detail::importMesh(*file);
    const auto fail = [file](const std::string& why) {
      throw InputError(fmt::format("mesh file '{}': {}", file->path, why));
    };
    checkSymmetry(mesh, request.symmetry_axes, fail);
    orientTets(mesh, fail);
    return mesh;
  }
  TetMesh mesh = detail::generateMesh(request);
  const auto fail = [&request](const std::string& why) {
    throw Error(fmt::format("meshing the {} gave a bad mesh: {}", kindName(request.shape), why));
  };
  if (mesh.tets.empty()) fail("no tetrahedra (mesh_size too large for the shape?)");
  checkSymmetry(mesh, request.symmetry_axes, fail);
  orientTets(mesh, fail);
  return mesh;
}

Discretisation discretise(const TetMesh& mesh) {
  const auto n = static_cast<std::ptrdiff_t>(mesh.tets.size());
  Discretisation d;
  d.nodes = mesh.vertices;
  d.points.resize(mesh.tets.size());
  d.volumes.resize(mesh.tets.size());
  d.spacings.resize(mesh.tets.size());
  KESSLER_VERIFY(indicesInRange(mesh), "a tetrahedron refers to a vertex outside the {} of the mesh",
                 mesh.vertices.size());
  // Exceptions cannot leave an OpenMP region: remember the first bad tet and report it after.
  std::ptrdiff_t first_bad = n;
#pragma omp parallel for reduction(min : first_bad)
  for (std::ptrdiff_t e = 0; e < n; ++e) {
    const auto& t = mesh.tets[e];
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    const Vec3& p = mesh.vertices[t[3]];
    const double vol = (b - a).dot((c - a).cross(p - a)) / 6.0;
    if (!(vol > 0.0)) first_bad = std::min(first_bad, e);
    d.points[e] = 0.25 * (a + b + c + p);
    d.volumes[e] = vol;
    d.spacings[e] =
        ((b - a).norm() + (c - a).norm() + (p - a).norm() + (c - b).norm() + (p - b).norm() + (p - c).norm()) / 6.0;
  }
  if (first_bad < n) {
    throw InputError(fmt::format("tetrahedron {} has non-positive volume {:.3g} m^3 (inverted or degenerate)",
                                 first_bad, d.volumes[first_bad]));
  }
  // Pairs of tets that share a face, each pair once with i < j.
  d.faces = tetFaces(mesh);
  for (const TetFace& f : d.faces)
    if (f.outer >= 0) d.adjacency.push_back({f.inner, f.outer});
  return d;
}

std::vector<LocalIndex> selectNodes(const Shape& shape, const std::vector<Vec3>& nodes, FixedNodes which,
                                    double depth) {
  if (which == FixedNodes::none) return {};
  if (!std::holds_alternative<Box>(shape) && !std::holds_alternative<Cylinder>(shape)) {
    throw InputError(fmt::format("fixed lateral faces apply to boxes and cylinders, not to a {}", kindName(shape)));
  }
  requireValidShape(shape);
  const BoundingBox box = bounds(shape);
  const double tolerance = std::max(1e-6 * (box.max - box.min).maxCoeff(), depth);
  KESSLER_VERIFY(nodes.size() < static_cast<std::size_t>(std::numeric_limits<LocalIndex>::max()),
                 "{} nodes exceed 32-bit local indices", nodes.size());

  std::vector<LocalIndex> selected;
  const auto select = [&](const auto& onFace) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (onFace(nodes[i])) selected.push_back(static_cast<LocalIndex>(i));
    }
  };
  if (const auto* b = std::get_if<Box>(&shape)) {
    // The thinnest direction is the plate normal; on ties (a cube) the later axis wins, so a
    // square plate in the xy-plane counts z as its normal.
    const Vec3 extent = b->max - b->min;
    int normal = 2;
    for (int axis = 1; axis >= 0; --axis) {
      if (extent[axis] < extent[normal]) normal = axis;
    }
    select([&](const Vec3& x) {
      if ((x.array() < b->min.array() - tolerance).any() || (x.array() > b->max.array() + tolerance).any()) {
        return false;
      }
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == normal) continue;
        if (std::abs(x[axis] - b->min[axis]) <= tolerance || std::abs(x[axis] - b->max[axis]) <= tolerance) {
          return true;
        }
      }
      return false;
    });
  } else {
    const auto& c = std::get<Cylinder>(shape);
    const double height = c.axis.norm();
    const Vec3 unit_axis = c.axis / height;
    select([&](const Vec3& x) {
      const Vec3 d = x - c.base;
      const double along = d.dot(unit_axis);
      if (along < -tolerance || along > height + tolerance) return false;
      return std::abs((d - along * unit_axis).norm() - c.radius) <= tolerance;
    });
  }
  return selected;
}

}  // namespace kessler::geometry
