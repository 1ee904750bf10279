#include "io/deck.hpp"
#include "io/deck_parts.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace kessler::io {

namespace {

namespace fs = std::filesystem;

// Memory per tetrahedron of a run, all included: a material point with its state and shape
// functions (~12 neighbours), its share of nodes, neighbour lists and output buffers.
constexpr double bytes_per_tet = 3.0 * 1024.0;
// Volume of a tetrahedron of edge h in a Gmsh mesh, in units of h^3 (a regular one is 0.118 h^3).
constexpr double tet_volume_factor = 0.1;
// A mesh file holds about this many bytes per tetrahedron (ASCII .msh: element and node lines).
constexpr double mesh_file_bytes_per_tet = 40.0;
// Overlaps smaller than this fraction of the smaller body are sampling noise or touching faces.
constexpr double overlap_tolerance = 1e-3;
// A body whose overlap with another is this close to all of its volume lies inside it.
constexpr double inside_tolerance = 0.02;

double tetrahedra(double volume, double size) { return volume / (tet_volume_factor * size * size * size); }

double bodyTetrahedra(const BodyConfig& body, const std::vector<int>& symmetry_axes) {
  const geometry::MeshRequest& mesh = body.mesh;
  if (const auto* file = std::get_if<geometry::MeshFile>(&mesh.shape)) {
    std::error_code error;
    const auto size = fs::file_size(file->path, error);
    return error ? 0.0 : static_cast<double>(size) / mesh_file_bytes_per_tet;
  }
  const double full = geometry::volume(mesh.shape);
  const double kept = keptVolume(mesh.shape, symmetry_axes);
  if (!mesh.refine || !(full > 0.0)) return tetrahedra(kept, mesh.mesh_size);
  // The zone's share of the body, assumed the same on the kept side as over the whole body.
  const geometry::Sphere zone{.center = mesh.refine->center, .radius = mesh.refine->radius};
  const double fine = std::min(geometry::overlapVolume(mesh.shape, zone, 32), full) * kept / full;
  return tetrahedra(kept - fine, mesh.mesh_size) + tetrahedra(fine, mesh.refine->size);
}

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) : 0.0;
}

std::string formatBytes(double bytes) {
  static constexpr std::array<const char*, 7> unit{"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  std::size_t i = 0;
  while (bytes >= 1024.0 && i + 1 < unit.size()) {
    bytes /= 1024.0;
    ++i;
  }
  return fmt::format("{:.3g} {}", bytes, unit[i]);
}

}  // namespace

double keptVolume(const geometry::Shape& shape, const std::vector<int>& symmetry_axes) {
  if (std::holds_alternative<geometry::MeshFile>(shape)) return 0.0;
  geometry::BoundingBox box = geometry::bounds(shape);
  bool cut = false;
  for (int axis : symmetry_axes) {
    if (box.max[axis] <= 0.0) return 0.0;
    if (box.min[axis] < 0.0) {
      box.min[axis] = 0.0;
      cut = true;
    }
  }
  if (!cut) return geometry::volume(shape);
  return geometry::overlapVolume(shape, geometry::Box{.min = box.min, .max = box.max}, 32);
}

double estimateMemoryBytes(const RunConfig& config) {
  double tets = 0.0;
  for (const BodyConfig& body : config.bodies) tets += bodyTetrahedra(body, config.symmetry_axes);
  return tets * bytes_per_tet;
}

void checkOverlaps(const std::vector<BodyConfig>& bodies, const Field& bodies_field) {
  const std::vector<Field> items = bodies_field.list();
  for (std::size_t j = 1; j < bodies.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      const geometry::Shape& a = bodies[i].mesh.shape;
      const geometry::Shape& b = bodies[j].mesh.shape;
      const double smaller = std::min(geometry::volume(a), geometry::volume(b));
      if (!(smaller > 0.0)) continue;  // a mesh file: its volume is unknown before it is read
      const double overlap = geometry::overlapVolume(a, b);
      if (overlap > overlap_tolerance * smaller && overlap > (1.0 - inside_tolerance) * smaller) {
        const bool j_smaller = geometry::volume(b) <= geometry::volume(a);
        const std::size_t inner = j_smaller ? j : i, outer = j_smaller ? i : j;
        items[j].failBare(fmt::format("body '{}' lies inside body '{}'{}: bodies must start apart (a projectile "
                                      "in front of the plate it strikes)",
                                      bodies[inner].name, bodies[outer].name,
                                      outer == j ? "" : fmt::format(" (bodies[{}])", outer)));
      }
      if (overlap > overlap_tolerance * smaller)
        items[j].failBare(
            fmt::format("body '{}' overlaps body '{}' (bodies[{}]) by about {:.3g} m^3, {:.2g}% of the "
                        "smaller one",
                        bodies[j].name, bodies[i].name, i, overlap, 100.0 * overlap / smaller));
    }
  }
}

void checkMemory(const RunConfig& config, const Field& bodies_field) {
  const double available = physicalMemoryBytes();
  const double needed = estimateMemoryBytes(config);
  if (!(available > 0.0) || needed <= available) return;
  double largest = -1.0;
  std::string largest_name;
  for (const BodyConfig& body : config.bodies) {
    const double tets = bodyTetrahedra(body, config.symmetry_axes);
    if (tets > largest) {
      largest = tets;
      largest_name = body.name;
    }
  }
  bodies_field.failBare(
      fmt::format("the run would need about {} of memory ({:.3g} tetrahedra, most of them in body "
                  "'{}'), more than this machine's {}; use a larger mesh_size or a smaller refinement "
                  "zone",
                  formatBytes(needed), needed / bytes_per_tet, largest_name, formatBytes(available)));
}

}  // namespace kessler::io
