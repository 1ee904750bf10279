#include "solver/sph/setup.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "geometry/lattice.hpp"
#include "particles/store_fields.hpp"
#include "search/cell_list.hpp"
#include "search/morton.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler::sph {

namespace {

// The particles of one body: a lattice for an analytic shape or a structured box, the tets'
// barycentres otherwise (with no lattice: frame.cell zero, elements empty).
struct BodyParticles {
  geometry::Discretisation particles;
  LatticeFrame frame;
  std::vector<std::array<int, 3>> element;
};

BodyParticles fromLattice(geometry::Lattice&& lattice) {
  return {std::move(lattice.particles), {lattice.origin, lattice.cell}, std::move(lattice.element)};
}

BodyParticles particlesOf(const BodySetup& setup, const std::vector<int>& symmetry_axes) {
  if (const auto* structured = std::get_if<geometry::StructuredBox>(&setup.mesh)) {
    try {
      return fromLattice(geometry::fillBoxLattice(structured->box, structured->cells));
    } catch (const InputError& e) {
      throw InputError(fmt::format("body '{}': {}", setup.name, e.what()));
    }
  }
  const auto* request = std::get_if<geometry::MeshRequest>(&setup.mesh);
  if (request == nullptr || std::holds_alternative<geometry::MeshFile>(request->shape)) {
    BodyParticles tets;
    if (request == nullptr) {
      tets.particles = std::get<geometry::Discretisation>(setup.mesh);
    } else {
      geometry::MeshRequest clipped = *request;
      clipped.symmetry_axes = symmetry_axes;
      tets.particles = geometry::discretise(geometry::meshShape(clipped));
    }
    // A particle's spacing is the cube root of its volume (a tet's mean edge, OTM's support size,
    // is about twice the distance between barycentres).
    geometry::Discretisation& d = tets.particles;
    for (std::size_t p = 0; p < d.points.size(); ++p) d.spacings[p] = std::cbrt(d.volumes[p]);
    tets.element.assign(d.points.size(), {-1, -1, -1});
    return tets;
  }
  if (request->refine)
    throw InputError(fmt::format("body '{}': SPH fills a body with one particle size; refine is OTM's", setup.name));
  try {
    return fromLattice(geometry::fillLattice(request->shape, request->mesh_size, symmetry_axes));
  } catch (const InputError& e) {
    throw InputError(fmt::format("body '{}': {}", setup.name, e.what()));
  }
}

void prescribe(Model& model, LocalIndex p, int axis, double velocity) {
  model.constrained[p] |= static_cast<std::uint8_t>(1u << axis);
  model.prescribed_v[p][axis] = velocity;
}

// Each body's particles along a Morton curve (search/morton.hpp), so that a particle's neighbours
// lie close to it in memory, and numbered in that order.
void sortForLocality(Model& model) {
  PointStore& points = model.points;
  if (points.size() == 0) return;
  const CellList::Bounds box = CellList::boundsOf(points.x, points.size());
  Particles particles(model);
  permuteFields(particles, mortonOrder(points.x, points.body, model.bodies.size(), box.lo, box.hi));
  numberPointsInOrder(model);
}

}  // namespace

std::vector<LocalIndex> particlesOnPlane(const Model& model, const PlaneConstraint& plane) {
  const PointStore& points = model.points;
  std::vector<LocalIndex> on;
  for (LocalIndex p = 0; p < points.size(); ++p) {
    if (plane.body >= 0 && points.body[p] != plane.body) continue;
    if (std::abs(points.x[p][plane.axis] - plane.offset) < points.spacing0[p] + plane.tolerance) on.push_back(p);
  }
  return on;
}

Model buildModel(const Problem& problem) {
  Model model;
  PointStore& points = model.points;
  for (const BodySetup& setup : problem.bodies) {
    KESSLER_VERIFY(setup.material != nullptr, "body '{}' has no material", setup.name);
    BodyParticles made = particlesOf(setup, problem.symmetry_axes);
    const geometry::Discretisation& particles = made.particles;
    model.lattices.push_back(made.frame);
    model.element.insert(model.element.end(), made.element.begin(), made.element.end());
    const int body = static_cast<int>(model.bodies.size());
    int material = -1;
    for (std::size_t m = 0; m < model.materials.size(); ++m)
      if (model.materials[m] == setup.material) material = static_cast<int>(m);
    if (material < 0) {
      material = static_cast<int>(model.materials.size());
      model.materials.push_back(setup.material);
    }
    const auto first = static_cast<std::size_t>(points.size());
    points.resize(first + particles.points.size());
    model.constrained.resize(points.x.size(), 0);
    model.prescribed_v.resize(points.x.size(), Vec3::Zero());
    model.viscosity.resize(points.x.size(), problem.settings.sph.viscosity_min);
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
      points.viscosity_limiter[p] = 1.0;  // SPH's viscosity is its own (Integrator::forces)
    }
    for (const auto& [i, j] : particles.adjacency) {
      const std::size_t a = first + static_cast<std::size_t>(i), b = first + static_cast<std::size_t>(j);
      model.adjacency.push_back({points.id[a], points.id[b]});
      model.adjacency_length0.push_back((points.x[b] - points.x[a]).norm());
    }
    model.bodies.push_back(BodyInfo{setup.name, material});
    if (const auto* request = std::get_if<geometry::MeshRequest>(&setup.mesh)) {
      // Fixed faces: the particles of the elements on them.
      const std::vector<Vec3> x(points.x.begin() + static_cast<std::ptrdiff_t>(first), points.x.end());
      const double depth = 0.5 * particles.spacings.front() * (1.0 + 1e-6);
      for (const LocalIndex i : geometry::selectNodes(request->shape, x, setup.fixed, depth))
        for (int axis = 0; axis < 3; ++axis) prescribe(model, static_cast<LocalIndex>(first) + i, axis, 0.0);
    }
    log::info("  body {:<14} {:>9} particles", setup.name, particles.points.size());
  }
  points.owned = points.size();
  sortForLocality(model);
  for (const PlaneConstraint& plane : problem.planes)
    for (const LocalIndex p : particlesOnPlane(model, plane)) prescribe(model, p, plane.axis, plane.velocity);
  if (problem.prepare) problem.prepare(model);
  return model;
}

}  // namespace kessler::sph
