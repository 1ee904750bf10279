#include "solver/sph/setup.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "particles/store_fields.hpp"
#include "search/cell_list.hpp"
#include "search/morton.hpp"
#include "solver/common/particle_bodies.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler::sph {

namespace {

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

Model buildModel(const Problem& problem) {
  Model model;
  PointStore& points = model.points;
  for (const BodySetup& setup : problem.bodies) {
    KESSLER_VERIFY(setup.material != nullptr, "body '{}' has no material", setup.name);
    BodyParticles made = particlesOf(setup, problem.symmetry_axes, "SPH");
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
    // Fixed faces: the particles of the elements on them.
    for (const LocalIndex i : fixedParticles(setup, made))
      for (int axis = 0; axis < 3; ++axis) prescribe(model, static_cast<LocalIndex>(first) + i, axis, 0.0);
    log::info("  body {:<14} {:>9} particles", setup.name, particles.points.size());
  }
  points.owned = points.size();
  sortForLocality(model);
  for (const PlaneConstraint& plane : problem.planes)
    for (const LocalIndex p : particlesOnPlane(model.points, plane)) prescribe(model, p, plane.axis, plane.velocity);
  if (problem.prepare) problem.prepare(model);
  return model;
}

}  // namespace kessler::sph
