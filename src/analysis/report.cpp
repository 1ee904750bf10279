#include "analysis/report.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kessler::analysis {
namespace {

double bodyMass(const ParticleState& model, int b) {
  double mass = 0.0;
  forEachPointOf(model.points, b, [&](LocalIndex p) { mass += model.points.mass[p]; });
  return mass;
}

bool isProjectile(const ImpactGeometry& geometry, int b) {
  for (const int p : geometry.projectile_bodies)
    if (p == b) return true;
  return false;
}

double density(const ParticleState& model, int b) {
  return model.materials[model.bodies[b].material]->referenceDensity();
}

// The projectile as the engineering models see it: a sphere of the projectile's mass and the
// density of its (first) body, hitting at the impact speed and the obliquity of the shot to the
// first plate's normal.
Projectile equivalentProjectile(const ParticleState& model, const ImpactGeometry& geometry, double mass) {
  Projectile projectile;
  projectile.density = density(model, geometry.projectile_bodies.front());
  projectile.diameter = std::cbrt(6.0 * mass / (std::numbers::pi * projectile.density));
  projectile.speed = geometry.impact_speed;
  const Vec3 e = geometry.shot_direction.normalized();
  projectile.obliquity = std::acos(std::clamp(e.dot(geometry.plates.front().normal), -1.0, 1.0));
  return projectile;
}

ShieldComparison compareShield(const ParticleState& model, const ImpactGeometry& geometry, const WallProperties& wall,
                               double projectile_mass, const RearWallDamage& simulated) {
  ShieldComparison c;
  c.projectile = equivalentProjectile(model, geometry, projectile_mass);
  c.wall = wall;
  c.simulated = simulated.classification;
  const PlateSpec& first = geometry.plates.front();
  const PlateSpec& last = geometry.plates.back();
  // The equations are fits for aluminium walls, and the wall's properties default to Al 6061-T6's.
  const double wall_density = density(model, last.body);
  if (wall.defaults && std::abs(wall_density - 2700.0) > 0.1 * 2700.0)
    c.caveat = fmt::format(
        "the rear wall's properties are Al 6061-T6's defaults, its material's density is {:.0f} kg/m^3: give "
        "analysis.rear_wall (yield stress, Brinell hardness, sound speed) for this material",
        wall_density);
  if (geometry.plates.size() >= 2) {
    c.model = "christiansen_whipple";
    c.spacing = first.normal.dot(last.normal) * last.frontFace() - first.rear_face;
    const WhippleShield shield{first.thickness, density(model, first.body), last.thickness, wall.yield_stress,
                               c.spacing};
    const BallisticLimit limit = whippleBallisticLimit(shield, c.projectile);
    c.critical_diameter = limit.critical_diameter;
    c.regime = std::string(regimeName(limit.regime));
    c.predicts_perforation = c.projectile.diameter > limit.critical_diameter;
  } else {
    c.model = "cour_palais_single_wall";
    const SingleWall single{first.thickness, density(model, first.body), wall.brinell_hardness, wall.sound_speed};
    const Penetration penetration = courPalaisPenetration(single, c.projectile);
    c.critical_diameter = penetration.perforation_diameter;
    c.penetration_depth = penetration.depth;
    c.regime = std::string(damageName(penetration.damage));
    c.predicts_perforation = penetration.damage == WallDamage::perforation;
  }
  return c;
}

// Did anything break? A body that is no longer one fragment, or that lost points to erosion or
// came apart below the resolution (eroded_mass), has made debris.
bool anythingBroke(const FragmentSet& set, std::size_t bodies) {
  std::vector<int> pieces(bodies, 0);
  for (const Fragment& f : set.fragments) ++pieces[static_cast<std::size_t>(f.body)];
  for (std::size_t b = 0; b < bodies; ++b)
    if (pieces[b] != 1 || set.eroded_mass[b] > 0.0) return true;
  return false;
}

}  // namespace

Report analyse(const ParticleState& model, const ImpactGeometry& geometry, const std::vector<double>& reference_lengths,
               const WallProperties& wall) {
  checkGeometry(model, geometry);
  Report report;
  report.geometry = geometry;
  for (const BodyInfo& body : model.bodies) report.body_names.push_back(body.name);
  for (const MaterialPtr& material : model.materials) report.material_names.push_back(material->name());

  FragmentOptions options;
  options.link_stretch = geometry.link_stretch;
  options.symmetry_axes = geometry.symmetry_axes;
  report.fragments = findFragments(model, reference_lengths, options);

  const double images = Mirror(geometry.symmetry_axes).images();
  double projectile_mass = 0.0;
  double target_mass = 0.0;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    (isProjectile(geometry, b) ? projectile_mass : target_mass) += images * bodyMass(model, b);
  if (projectile_mass > 0.0 && target_mass > 0.0 && geometry.impact_speed > 0.0) {
    report.event = BreakupEvent{projectile_mass, target_mass, geometry.impact_speed};
    report.breakup = nasaBreakup(*report.event);
  }

  report.debris = anythingBroke(report.fragments, model.bodies.size());
  if (report.debris) {
    for (int i = 0; i < static_cast<int>(geometry.plates.size()); ++i)
      report.holes.push_back(measureHole(model, geometry, i));
    report.clouds = measureClouds(model, geometry);
    report.ejecta = measureEjecta(model, geometry);
  }
  if (!geometry.plates.empty()) {
    report.rear_wall = measureRearWall(model, report.fragments, geometry);
    if (report.debris && projectile_mass > 0.0 && geometry.impact_speed > 0.0)
      report.shield = compareShield(model, geometry, wall, projectile_mass, *report.rear_wall);
  }
  return report;
}

}  // namespace kessler::analysis
