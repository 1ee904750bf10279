#pragma once
// What a shielding engineer measures on a light-gas-gun test article, taken from the model at
// the end of a run: the hole in each plate, the debris cloud behind the target, the back-splash
// in front of it, and the damage of the rear wall. Definitions with equations: docs/analysis.md.
#include "analysis/fragments.hpp"
#include "analysis/plane_raster.hpp"
#include "geometry/shape.hpp"
#include "solver/common/particle_state.hpp"

#include <string>
#include <vector>

namespace kessler::analysis {

// A plate of the original configuration.
struct PlateSpec {
  int body = -1;
  Vec3 normal = Vec3::UnitZ();  // unit, from the front face to the rear face (along the shot)
  double rear_face = 0.0;       // normal . x on the original rear face, m
  double thickness = 0.0;       // m
  double frontFace() const { return rear_face - thickness; }
};

// A box plate: its normal is the box's thinnest direction, pointing along the shot.
PlateSpec plateFromBox(int body, const geometry::Box& box, const Vec3& shot_direction);

// Where the line x0 + t e meets the plane normal . x = offset of a plate.
Vec3 shotLineHit(const Vec3& x0, const Vec3& direction, const Vec3& normal, double offset);

struct ImpactGeometry {
  Vec3 shot_direction = -Vec3::UnitZ();  // direction of travel of the projectile
  Vec3 impact_point = Vec3::Zero();      // where the shot line meets the first plate's front face
  double impact_speed = 0.0;             // m/s, for the breakup and ballistic-limit models
  std::vector<int> projectile_bodies;
  std::vector<PlateSpec> plates;   // in the order the shot line meets them; the last is the rear wall
  int cloud_reference = 0;         // index into plates: the target the debris cloud is measured from
  std::vector<int> symmetry_axes;  // mirror planes through the origin of a half/quarter model
  double cell_size = 0.0;          // hole raster cell, m; 0: the plate's mean initial point spacing
  double link_stretch = 2.5;       // FragmentOptions::link_stretch
};

// Throws kessler::InputError when a body index is out of range, a plate is listed twice, the
// shot direction or a normal is zero, or the shot does not travel from a plate's front face
// to its rear face.
void checkGeometry(const ParticleState& model, const ImpactGeometry& geometry);

// The raster cell for the holes of a plate: geometry.cell_size, or the mean initial spacing
// of the plate's points.
double holeCell(const ParticleState& model, const ImpactGeometry& geometry, int plate);

struct HoleMeasurement {
  int plate = 0;
  int body = 0;
  bool found = false;          // false: intact plate material covers the impact point
  bool open = false;           // the hole reaches the edge of the plate (the plate is cut through)
  double cell = 0.0;           // raster cell, m
  EllipseFit ellipse;          // area, equivalent diameter, axes (m)
  Vec3 centre = Vec3::Zero();  // on the plate's original mid-plane
  Vec3 major_direction = Vec3::UnitX();
  // Part of the hole's area that no intact plate material covers at any depth (petals and a
  // bulge that left the original slab cover the rest): the area times the fraction of the
  // hole's empty cells that are clear all through, m^2.
  double through_area = 0.0;
};

// The hole in plates[plate]: the intact points of the plate inside its original thickness slab,
// projected on its plane and rasterised; the hole is the empty region around the shot line.
HoleMeasurement measureHole(const ParticleState& model, const ImpactGeometry& geometry, int plate);

struct CloudMeasurement {
  std::string name;           // body name, or "all"
  int body = -1;              // -1 for the whole cloud
  double mass = 0.0;          // kg behind the reference rear face (full model)
  long points = 0;            // simulated points
  double leading_edge = 0.0;  // m, furthest axial distance from the rear face along the shot line
  double max_radius = 0.0;    // m, largest distance from the shot line
  double length = 0.0;        // m, axial extent
  double width = 0.0;         // m, 2 max_radius
  double length_to_width = 0.0;
  // The bulk of the cloud, 95 % of its mass: a few fast points (the jetting rim of the contact,
  // a shocked point's velocity noise) set the extremes above.
  double bulk_leading_edge = 0.0;     // m, axial distance that 95 % of the mass lies behind
  double bulk_radius = 0.0;           // m, distance from the shot line within which 95 % lies
  double bulk_length_to_width = 0.0;  // (5 % to 95 % axial extent) / (2 bulk_radius)
  // How fast it travels and spreads (Piekutowski's normalised velocities, docs/analysis.md §5):
  // the mass-weighted mean velocity along the shot line, the axial velocity that 5 % of the mass
  // exceeds (the bulk front) and the radial velocity (away from the shot line) that 5 % exceeds.
  double mean_axial_speed = 0.0;     // m/s
  double bulk_axial_speed = 0.0;     // m/s
  double bulk_radial_speed = 0.0;    // m/s
  Vec3 front_centre = Vec3::Zero();  // mass centre of the leading 10 % of the length
  double front_deflection = 0.0;     // rad, angle of the front centre from the shot line
  double front_normal_angle = 0.0;   // rad, angle of the front centre from the plate normal
};

// One cloud per projectile body and for the reference plate's body, then "all" of them.
std::vector<CloudMeasurement> measureClouds(const ParticleState& model, const ImpactGeometry& geometry);

struct EjectaMeasurement {
  double mass = 0.0;  // kg in front of the first plate moving up-range (full model)
  long points = 0;
  double height = 0.0;       // m, furthest distance in front of the original front face
  double inner_angle = 0.0;  // rad from the plate's outward normal: 5 % mass percentile
  double outer_angle = 0.0;  // 95 % mass percentile (the cone's half-angle)
  double axis_tilt = 0.0;    // rad, mean ejecta direction from the outward normal
};

EjectaMeasurement measureEjecta(const ParticleState& model, const ImpactGeometry& geometry);

struct RearWallDamage {
  int plate = 0;
  int body = 0;
  int perforations = 0;                       // holes through the whole wall
  std::vector<double> perforation_diameters;  // equivalent diameters, m, largest first
  long spall_fragments = 0;                   // detached fragments behind the rear face (full model)
  double spall_mass = 0.0;                    // kg
  double eroded_mass_behind = 0.0;            // kg of eroded wall points behind the rear face
  double debris_struck = 0.0;                 // kg of debris whose last strike was on the wall
  double bulge = 0.0;           // m, how far the wall's attached material reaches behind its original rear face
  double incipient_mass = 0.0;  // kg of failed wall material in the rear half of the wall, still attached
  // The wall's thickness over its points' mean initial spacing: how finely its response is
  // resolved. The shipped whipple wall (1.6) held against a sphere that perforated it at 3.0
  // (docs/validation.md, "The open problem").
  double spacings_through = 0.0;
  // The NASA damage classes (docs/analysis.md §7), worst first: perforation | detached_spall |
  // incipient_spall | bulge | none. The first two are failures.
  std::string classification = "none";
  bool failed() const { return classification == "perforation" || classification == "detached_spall"; }
};

// The last plate: perforations are the bounded empty regions (at least 4 cells) of the
// projection of the wall's largest fragment at any depth; detached spall is every other wall
// fragment whose centre lies behind the original rear face; incipient spall is failed wall
// material still in the wall, nearer its rear face than its front face where it lies; a bulge is
// the wall reaching more than one spacing behind its original rear face.
RearWallDamage measureRearWall(const ParticleState& model, const FragmentSet& fragments,
                               const ImpactGeometry& geometry);

}  // namespace kessler::analysis
