#include "core/error.hpp"
#include "geometry/gmsh_backend.hpp"

#include <gmsh.h>
#include <omp.h>

#include <algorithm>
#include <exception>
#include <limits>

namespace kessler::geometry::detail {

namespace {

std::mutex& gmshMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

GmshSession::GmshSession() : lock_(gmshMutex()), omp_threads_(omp_get_max_threads()) {
  // No config files: a user's gmshrc must not change Kessler's meshes.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {
    // A destructor must not throw; Gmsh has nothing left for us to release.
  }
  omp_set_num_threads(omp_threads_);
}

std::string currentGmshError() {
  std::string message;
  try {
    throw;
  } catch (const std::exception& e) {
    message = e.what();
  } catch (const std::string& s) {
    message = s;
  } catch (const char* s) {
    message = s;
  } catch (...) {
  }
  if (message.empty()) {
    try {
      gmsh::logger::getLastError(message);
    } catch (...) {
    }
  }
  return message.empty() ? std::string("unknown Gmsh error") : message;
}

TetMesh extractTets(double scale) {
  std::vector<std::size_t> element_tags;
  std::vector<std::size_t> corner_tags;
  gmsh::model::mesh::getElementsByType(4, element_tags, corner_tags);
  KESSLER_VERIFY(corner_tags.size() == 4 * element_tags.size(), "Gmsh returned {} corners for {} tetrahedra",
                 corner_tags.size(), element_tags.size());

  std::vector<std::size_t> used = corner_tags;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  KESSLER_VERIFY(used.size() < static_cast<std::size_t>(std::numeric_limits<LocalIndex>::max()) &&
                     element_tags.size() < static_cast<std::size_t>(std::numeric_limits<LocalIndex>::max()),
                 "mesh too large for 32-bit local indices: {} vertices, {} tetrahedra", used.size(),
                 element_tags.size());
  const auto indexOf = [&used](std::size_t tag) {
    return static_cast<LocalIndex>(std::lower_bound(used.begin(), used.end(), tag) - used.begin());
  };

  TetMesh mesh;
  mesh.tets.resize(element_tags.size());
  for (std::size_t e = 0; e < element_tags.size(); ++e) {
    for (std::size_t c = 0; c < 4; ++c) mesh.tets[e][c] = indexOf(corner_tags[4 * e + c]);
  }

  std::vector<std::size_t> node_tags;
  std::vector<double> coords;
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  mesh.vertices.assign(used.size(), Vec3::Zero());
  std::vector<char> found(used.size(), 0);
  for (std::size_t n = 0; n < node_tags.size(); ++n) {
    const auto it = std::lower_bound(used.begin(), used.end(), node_tags[n]);
    if (it == used.end() || *it != node_tags[n]) continue;
    const auto v = static_cast<std::size_t>(it - used.begin());
    mesh.vertices[v] = scale * Vec3(coords[3 * n], coords[3 * n + 1], coords[3 * n + 2]);
    found[v] = 1;
  }
  const auto missing = std::count(found.begin(), found.end(), 0);
  if (missing > 0) {
    throw InputError(fmt::format("{} tetrahedron corner(s) refer to undefined nodes", missing));
  }
  return mesh;
}

}  // namespace kessler::geometry::detail
