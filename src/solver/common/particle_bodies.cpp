#include "solver/common/particle_bodies.hpp"

#include "core/error.hpp"
#include "geometry/lattice.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler {

namespace {

BodyParticles fromLattice(geometry::Lattice&& lattice) {
  return {std::move(lattice.particles), {lattice.origin, lattice.cell}, std::move(lattice.element)};
}

}  // namespace

BodyParticles particlesOf(const BodySetup& setup, const std::vector<int>& symmetry_axes, const char* method) {
  try {
    if (const auto* structured = std::get_if<geometry::StructuredBox>(&setup.mesh))
      return fromLattice(geometry::fillBoxLattice(structured->box, structured->cells));
    const auto* request = std::get_if<geometry::MeshRequest>(&setup.mesh);
    if (request == nullptr) {
      const auto& given = std::get<geometry::Discretisation>(setup.mesh);
      if (given.faces.empty()) return {given, {}, std::vector<std::array<int, 3>>(given.points.size(), {-1, -1, -1})};
      return fromLattice(geometry::fillTetLattice(given));
    }
    if (std::holds_alternative<geometry::MeshFile>(request->shape)) {
      geometry::MeshRequest clipped = *request;
      clipped.symmetry_axes = symmetry_axes;
      return fromLattice(geometry::fillTetLattice(geometry::discretise(geometry::meshShape(clipped))));
    }
    if (request->refine)
      throw InputError(fmt::format("{} fills a body with one particle size; refine is OTM's", method));
    return fromLattice(geometry::fillLattice(request->shape, request->mesh_size, symmetry_axes));
  } catch (const InputError& e) {
    throw InputError(fmt::format("body '{}': {}", setup.name, e.what()));
  }
}

LocalIndex addParticleBody(ParticleState& state, const BodySetup& setup, const BodyParticles& made) {
  KESSLER_VERIFY(setup.material != nullptr, "body '{}' has no material", setup.name);
  const geometry::Discretisation& particles = made.particles;
  PointStore& points = state.points;
  const int body = static_cast<int>(state.bodies.size());
  int material = -1;
  for (std::size_t m = 0; m < state.materials.size(); ++m)
    if (state.materials[m] == setup.material) material = static_cast<int>(m);
  if (material < 0) {
    material = static_cast<int>(state.materials.size());
    state.materials.push_back(setup.material);
  }
  const auto first = static_cast<std::size_t>(points.size());
  points.resize(first + particles.points.size());
  const double rho0 = setup.material->referenceDensity();
  for (std::size_t i = 0; i < particles.points.size(); ++i) {
    const std::size_t p = first + i;
    points.id[p] = static_cast<Index>(p);
    points.body[p] = body;
    points.x[p] = particles.points[i];
    points.v[p] = setup.velocity_field ? setup.velocity_field(points.x[p]) : setup.velocity;
    points.volume[p] = points.volume0[p] = particles.volumes[i];
    points.mass[p] = rho0 * particles.volumes[i];
    points.spacing0[p] = particles.spacings[i];
    points.temperature[p] = 293.15;
  }
  for (const auto& [i, j] : particles.adjacency) {
    const std::size_t a = first + static_cast<std::size_t>(i), b = first + static_cast<std::size_t>(j);
    state.adjacency.push_back({points.id[a], points.id[b]});
    state.adjacency_length0.push_back((points.x[b] - points.x[a]).norm());
  }
  state.bodies.push_back(BodyInfo{setup.name, material});
  return static_cast<LocalIndex>(first);
}

std::vector<LocalIndex> fixedParticles(const BodySetup& setup, const BodyParticles& made) {
  const auto* request = std::get_if<geometry::MeshRequest>(&setup.mesh);
  if (request == nullptr) return {};
  const double depth = 0.5 * made.particles.spacings.front() * (1.0 + 1e-6);
  return geometry::selectNodes(request->shape, made.particles.points, setup.fixed, depth);
}

std::vector<LocalIndex> particlesOnPlane(const PointStore& points, const PlaneConstraint& plane) {
  std::vector<LocalIndex> on;
  for (LocalIndex p = 0; p < points.size(); ++p) {
    if (plane.body >= 0 && points.body[p] != plane.body) continue;
    if (std::abs(points.x[p][plane.axis] - plane.offset) < points.spacing0[p] + plane.tolerance) on.push_back(p);
  }
  return on;
}

}  // namespace kessler
