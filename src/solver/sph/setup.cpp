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
    const BodyParticles made = particlesOf(setup, problem.symmetry_axes, "SPH");
    model.lattices.push_back(made.frame);
    model.element.insert(model.element.end(), made.element.begin(), made.element.end());
    const auto first = static_cast<std::size_t>(addParticleBody(model, setup, made));
    model.constrained.resize(points.x.size(), 0);
    model.prescribed_v.resize(points.x.size(), Vec3::Zero());
    model.viscosity.resize(points.x.size(), problem.settings.sph.viscosity_min);
    // SPH's viscosity is its own (Integrator::forces): the laws' stays off.
    std::fill(points.viscosity_limiter.begin() + static_cast<std::ptrdiff_t>(first), points.viscosity_limiter.end(),
              1.0);
    // Fixed faces: the particles of the elements on them.
    for (const LocalIndex i : fixedParticles(setup, made))
      for (int axis = 0; axis < 3; ++axis) prescribe(model, static_cast<LocalIndex>(first) + i, axis, 0.0);
    log::info("  body {:<14} {:>9} particles", setup.name, made.particles.points.size());
  }
  points.owned = points.size();
  sortForLocality(model);
  for (const PlaneConstraint& plane : problem.planes)
    for (const LocalIndex p : particlesOnPlane(model.points, plane)) prescribe(model, p, plane.axis, plane.velocity);
  if (problem.prepare) problem.prepare(model);
  return model;
}

}  // namespace kessler::sph
