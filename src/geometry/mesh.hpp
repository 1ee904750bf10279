#pragma once
// Tetrahedral meshing of shapes through the Gmsh C++ API, import of Gmsh .msh files, and the
// conversion of a tetrahedral mesh into OTM nodes and material points (docs/theory.md §1).
#include "core/types.hpp"
#include "geometry/shape.hpp"

#include <array>
#include <optional>
#include <vector>

namespace kessler::geometry {

// A spherical zone meshed with a smaller element size.
struct Refinement {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  double size = 0.0;
};

struct MeshRequest {
  Shape shape;
  double mesh_size = 0.0;            // target tetrahedron edge length
  std::optional<Refinement> refine;  // optional local refinement
  // Symmetry planes through the origin with normal along these axes (0 = x, 1 = y, 2 = z):
  // only the part of the shape with coordinate >= 0 along each is meshed.
  std::vector<int> symmetry_axes;
};

struct TetMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<LocalIndex, 4>> tets;  // positively oriented (det > 0)
};

// Meshes an analytic shape (clipped by the symmetry planes), or reads a MeshFile. Throws
// kessler::InputError for an unreadable file, a mesh without tetrahedra, a degenerate tet, or a
// mesh that lies on the wrong side of a symmetry plane.
TetMesh meshShape(const MeshRequest& request);

// OTM discretisation of a mesh: nodes = vertices; one material point per tet at its
// barycentre with its volume, and a spacing h = mean edge length of the tet. `adjacency` lists
// the pairs of points whose tets share a face, each pair once with i < j: the initial
// connectivity of the material, from which analysis/ reconstructs fragments. `faces` lists every
// face of the tets once, for a sliding contact's surfaces (empty for a discretisation built
// otherwise).
struct TetFace {
  std::array<LocalIndex, 3> nodes{};  // counter-clockwise seen from outside `inner`
  LocalIndex inner = 0;               // the point (tet) whose face it is
  LocalIndex outer = -1;              // the point (tet) beyond it; -1 on the mesh's boundary
};
struct Discretisation {
  std::vector<Vec3> nodes;
  std::vector<Vec3> points;
  std::vector<double> volumes;
  std::vector<double> spacings;
  std::vector<std::array<LocalIndex, 2>> adjacency;
  std::vector<TetFace> faces;
};

Discretisation discretise(const TetMesh& mesh);

// Which boundary nodes to hold fixed.
enum class FixedNodes {
  none,
  lateral_faces,  // box: the four faces parallel to its thinnest direction; cylinder: the side
};

// Indices of the nodes of `nodes` that lie on the selected faces of `shape` (within a tolerance
// of 1e-6 of the shape's size, or within `depth` of them: a particle method's first layer, whose
// particles sit half a spacing inside). Throws kessler::InputError if the selection does not apply
// to the shape (e.g. lateral faces of a sphere).
std::vector<LocalIndex> selectNodes(const Shape& shape, const std::vector<Vec3>& nodes, FixedNodes which,
                                    double depth = 0.0);

}  // namespace kessler::geometry
