#include "solver/rkpm/setup.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/common/particle_bodies.hpp"
#include "solver/rkpm/surface.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace kessler::rkpm {

namespace {

// A lattice body's cell faces: each pair of elements that share a face, once, and each element face
// that no element shares. `first` is the body's first particle.
void latticeFaces(const BodyParticles& made, LocalIndex first, std::vector<CellFace>& faces) {
  const Vec3 cell = made.frame.cell;
  std::map<std::array<int, 3>, LocalIndex> at;
  for (std::size_t i = 0; i < made.element.size(); ++i) at[made.element[i]] = static_cast<LocalIndex>(i);
  for (std::size_t i = 0; i < made.element.size(); ++i) {
    const std::array<int, 3>& e = made.element[i];
    const Vec3 centre =
        made.frame.origin + Vec3((e[0] + 0.5) * cell[0], (e[1] + 0.5) * cell[1], (e[2] + 0.5) * cell[2]);
    for (int a = 0; a < 3; ++a) {
      const double area = cell[(a + 1) % 3] * cell[(a + 2) % 3];
      for (const int side : {-1, 1}) {
        std::array<int, 3> beside = e;
        beside[static_cast<std::size_t>(a)] += side;
        const auto found = at.find(beside);
        if (found != at.end() && side < 0) continue;  // the shared face is listed from its lower element
        CellFace f;
        f.area = Vec3::Zero();
        f.area[a] = side * area;
        f.centroid = centre;
        f.centroid[a] += 0.5 * side * cell[a];
        f.inner = first + static_cast<LocalIndex>(i);
        f.outer = found != at.end() ? first + found->second : -1;
        faces.push_back(f);
      }
    }
  }
}

}  // namespace

Model buildModel(const Problem& problem) {
  Model model;
  PointStore& points = model.points;
  const double support = problem.settings.rkpm.support;
  for (const BodySetup& setup : problem.bodies) {
    const BodyParticles made = particlesOf(setup, problem.symmetry_axes, "RKPM");
    // Every body a lattice (a tet mesh filled with cubes, as SPH's): its elements are the particles'
    // cells and the source of its surface. Irregular tets as cells shocked unstably (validation.md,
    // "RKPM"); a bare particle set has no cells.
    if (made.frame.cell.squaredNorm() == 0.0)
      throw InputError(fmt::format(
          "body '{}': RKPM integrates over its particles' cells, and a bare particle set has none (give a shape, a "
          "structured box or a tet mesh)",
          setup.name));
    const LocalIndex first = addParticleBody(model, setup, made);
    const std::size_t n = made.particles.points.size();
    model.constrained.resize(points.x.size(), 0);
    model.prescribed_v.resize(points.x.size(), Vec3::Zero());
    model.cell_volume.resize(points.x.size(), made.frame.cell.prod());
    latticeFaces(made, first, model.faces);
    model.element.insert(model.element.end(), made.element.begin(), made.element.end());
    if (problem.bodies.size() > 1) {
      std::vector<LocalIndex> all(n);
      for (std::size_t i = 0; i < n; ++i) all[i] = first + static_cast<LocalIndex>(i);
      const std::vector<std::array<LocalIndex, 3>> sheet = latticeSurface(model.element, all);
      model.surface.insert(model.surface.end(), sheet.begin(), sheet.end());
    }
    for (const LocalIndex i : fixedParticles(setup, made)) {
      model.constrained[static_cast<std::size_t>(first + i)] = 7;
      model.prescribed_v[static_cast<std::size_t>(first + i)].setZero();
    }
    log::info("  body {:<14} {:>9} particles (support {} spacings)", setup.name, n, support);
  }
  points.owned = points.size();
  if (problem.bodies.size() > 1 && !problem.settings.solver.contact.sliding())
    log::info(
        "  RKPM's bodies meet through the sliding contact, without friction (it has no seizing contact; "
        "solver.contact: {{ type: sliding, friction: mu }} sets a friction)");
  for (const PlaneConstraint& plane : problem.planes)
    for (const LocalIndex p : particlesOnPlane(model, plane)) {
      model.constrained[p] |= static_cast<std::uint8_t>(1u << plane.axis);
      if (!std::isinf(plane.tolerance))
        model.constrained[p] |= static_cast<std::uint8_t>(held_at_surface << plane.axis);
      model.prescribed_v[p][plane.axis] = plane.velocity;
    }
  model.reference = points.x;
  model.coefficient_x = points.x;
  model.coefficient_v = points.v;
  if (problem.prepare) problem.prepare(model);
  return model;
}

std::vector<LocalIndex> particlesOnPlane(const Model& model, const PlaneConstraint& plane) {
  const PointStore& points = model.points;
  if (std::isinf(plane.tolerance)) return kessler::particlesOnPlane(points, plane);
  std::vector<std::uint8_t> held(static_cast<std::size_t>(points.size()), 0);
  for (const CellFace& f : model.faces) {
    if (!surfaceFaceAlong(f, plane.axis) || (plane.body >= 0 && points.body[f.inner] != plane.body)) continue;
    // In the plane: its centroid on it.
    if (std::abs(f.centroid[plane.axis] - plane.offset) <= plane.tolerance + 1e-9 * std::sqrt(f.area.norm()))
      held[static_cast<std::size_t>(f.inner)] = 1;
  }
  std::vector<LocalIndex> on;
  for (LocalIndex p = 0; p < points.size(); ++p)
    if (held[static_cast<std::size_t>(p)]) on.push_back(p);
  return on;
}

}  // namespace kessler::rkpm
