// Import of tetrahedral meshes from Gmsh .msh files.
#include "core/error.hpp"
#include "geometry/gmsh_backend.hpp"

#include <gmsh.h>

#include <fstream>
#include <string>

namespace kessler::geometry::detail {

namespace {

// Gmsh decides how to read a file from its contents, and reads anything that is not a mesh
// as a .geo script (which may run shell commands). Only accept files that start like a
// .msh file (formats 2 and 4 both begin with a $MeshFormat section).
void requireMshHeader(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open the file");
  std::string first;
  in >> first;
  if (first != "$MeshFormat") {
    throw InputError("not a Gmsh .msh file (it does not begin with $MeshFormat)");
  }
}

// Refuses 3-D elements other than linear tetrahedra rather than silently dropping their volume.
void requireOnlyLinearTets() {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  bool has_tets = false;
  for (const int type : types) {
    if (type == 4) {
      has_tets = true;
      continue;
    }
    std::string name;
    int dim = 0;
    int order = 0;
    int nodes = 0;
    int primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
    throw InputError(
        fmt::format("it contains 3-D elements of type '{}' (Gmsh type {}); Kessler needs a mesh of "
                    "linear 4-node tetrahedra only",
                    name, type));
  }
  if (!has_tets) throw InputError("it contains no tetrahedra (a volume mesh of 4-node tetrahedra is needed)");
}

}  // namespace

TetMesh importMesh(const MeshFile& file) {
  try {
    requireMshHeader(file.path);
    GmshSession session;
    try {
      gmsh::open(file.path);
      requireOnlyLinearTets();
      return extractTets(file.scale);
    } catch (const Error&) {
      throw;
    } catch (...) {
      throw InputError(fmt::format("Gmsh cannot read it: {}", currentGmshError()));
    }
  } catch (const InputError& e) {
    throw InputError(fmt::format("mesh file '{}': {}", file.path, e.what()));
  }
}

}  // namespace kessler::geometry::detail
