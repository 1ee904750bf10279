// taylor-bar: the classic copper Taylor impact benchmark (docs/validation.md): a bar of length
// 32.4 mm and radius 3.2 mm hits a rigid frictionless wall at 227 m/s; rho 8930 kg/m^3,
// E 117 GPa, nu 0.35, yield 400 MPa with linear hardening 100 MPa; after 80 us the reported
// final length is 21.42-21.48 mm and the footprint radius 7.11-7.23 mm (converged ~7.23 mm).
// Quarter model (symmetry planes x = 0, y = 0). Pressure from a linear bulk response
// (polynomial EOS with K1 = K, Gamma0 = 0), as the benchmark is elastic-plastic without an EOS.
#include "material/impact_material.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/common/walls.hpp"
#include "verify/fixtures.hpp"
#include "verify/impact_problems.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kessler::verify {

TaylorBarResult runTaylorBar(double mesh_size, double cfl, bool volume_averaging) {
  const double E = 117e9, nu = 0.35, rho = 8930.0;
  const double radius = 3.2e-3, length = 32.4e-3, speed = 227.0;
  ImpactMaterialParameters p;
  eos::PolynomialParameters bulk;
  bulk.density = rho;
  bulk.k1 = E / (3.0 * (1.0 - 2.0 * nu));
  bulk.k2 = bulk.k3 = bulk.gamma0 = 0.0;
  p.eos = eos::Polynomial(bulk);
  p.shear_modulus = E / (2.0 * (1.0 + nu));
  strength::LinearHardeningParameters hardening;
  hardening.sigma0 = 400e6;
  hardening.H = 100e6;
  p.yield = strength::LinearHardening(hardening);
  p.thermal.specific_heat = 383.0;
  auto material = std::make_shared<ImpactMaterial>("Taylor-bar copper", p);

  geometry::MeshRequest cylinder;
  cylinder.shape = geometry::Cylinder{Vec3::Zero(), Vec3(0, 0, length), radius};
  cylinder.mesh_size = mesh_size;
  Problem problem;
  problem.bodies = {BodySetup{.name = "bar", .material = material, .mesh = cylinder, .velocity = Vec3(0, 0, -speed)}};
  problem.symmetry_axes = {0, 1};
  problem.settings.solver.end_time = 80e-6;
  problem.settings.solver.cfl = cfl;
  problem.settings.otm.volume_averaging = volume_averaging;
  problem.walls = {RigidWall{2, 0.0, 1}};
  const std::unique_ptr<Method> method = runToEnd(problem);
  const NodeCloud nodes = method->nodes();

  TaylorBarResult r;
  const PointStore& points = method->state().points;
  // The footprint: the outermost surface within a quarter element of the wall. The surface is the
  // nodes (OTM) or the particles' cells, half a spacing about their centres (SPH, RKPM: node_cloud.hpp).
  const double touching = 0.25 * mesh_size;
  if (surfaceOnNodes(nodes))
    for (LocalIndex a = 0; a < nodes.owned; ++a) {
      const Vec3& x = nodes.x[a];
      r.length = std::max(r.length, x[2]);
      if (x[2] < touching) r.footprint_radius = std::max(r.footprint_radius, std::hypot(x[0], x[1]));
    }
  else
    for (LocalIndex q = 0; q < points.owned; ++q) {
      const Vec3& x = points.x[q];
      const double half = particle_reach * points.spacing(q);
      r.length = std::max(r.length, x[2] + half);
      if (x[2] - half < touching) r.footprint_radius = std::max(r.footprint_radius, std::hypot(x[0], x[1]) + half);
    }
  const Clock clock = method->clock();
  r.steps = clock.steps;
  r.dt_initial = clock.dt_initial;
  r.dt_final = clock.dt_next;
  r.points = points.owned;
  for (LocalIndex q = 0; q < points.owned; ++q)
    if (points.x[q][2] < mesh_size)
      r.point_footprint_radius = std::max(r.point_footprint_radius, std::hypot(points.x[q][0], points.x[q][1]));
  double limit = std::numeric_limits<double>::infinity();
  for (LocalIndex q = 0; q < points.owned; ++q) {
    if (points.broken[q]) continue;
    const double ratio = method->stepLength(q) / points.sound_speed[q];
    if (ratio >= limit) continue;
    limit = ratio;
    r.min_stretch = smallestStretch(points.F[q]);
    r.limiting_r = std::hypot(points.x[q][0], points.x[q][1]);
    r.limiting_z = points.x[q][2];
    r.limiting_h0 = points.spacing0[q];
  }
  r.min_node_distance = std::numeric_limits<double>::infinity();
  for (LocalIndex a = 0; a < nodes.owned; ++a)
    for (LocalIndex b = a + 1; b < nodes.owned; ++b)
      r.min_node_distance = std::min(r.min_node_distance, (nodes.x[a] - nodes.x[b]).norm());
  return r;
}

namespace {

// The reported ranges (docs/validation.md, Taylor bar); errors are distances from the range.
constexpr double length_low = 21.42e-3, length_high = 21.48e-3, radius_low = 7.11e-3, radius_high = 7.23e-3;

// Distance of `value` from the reported range [low, high], relative to the nearest end; 0 inside.
double rangeError(double value, double low, double high) {
  if (value < low) return (low - value) / low;
  if (value > high) return (value - high) / high;
  return 0.0;
}

// Length and footprint radius at one resolution against the reported ranges (docs/validation.md),
// each within 3% of the nearest end of its range.
Outcome taylorBarAt(const std::string& name, double mesh_size) {
  const TaylorBarResult r = runTaylorBar(mesh_size);
  const double e_radius = rangeError(r.footprint_radius, radius_low, radius_high);
  Outcome o;
  o.name = name;
  o.quantity = "final length (m), error from the reported range";
  o.measured = r.length;
  o.reference = r.length < length_low ? length_low : std::min(r.length, length_high);
  o.tolerance = 0.03;
  o = compare(o);
  o.passed = o.passed && e_radius <= 0.03;
  // The outermost material point by the wall is printed beside the metric, not judged: the node
  // metric and it differ by up to 0.7 mm between meshes (docs/validation.md, Taylor bar).
  o.note = fmt::format(
      "footprint radius {:.3f} mm vs {:.2f}-{:.2f} ({:.1f}% outside, tol 3%; outermost material point by the "
      "wall at {:.3f} mm, not judged); mesh {} mm, {} points, {} steps",
      1e3 * r.footprint_radius, 1e3 * radius_low, 1e3 * radius_high, 100 * e_radius, 1e3 * r.point_footprint_radius,
      1e3 * mesh_size, r.points, r.steps);
  return o;
}

}  // namespace

Outcome taylorBar() {
  return taylorBarAt("taylor-bar", 0.8e-3);
}

// The CI version (docs/validation.md, resolution study): 1 mm, 1,594 points, about 19,500 steps.
// Besides the 3% at 1 mm, the length must have moved towards the reported range from a 1.6 mm run
// (421 points, seconds): the length converges from above (22.22, 21.90, 21.84, 21.73 mm at 1.6,
// 1.2, 1.0, 0.8 mm), so a 1 mm pass is not a coarse-mesh accident. The radius is not monotone in
// the mesh size (7.37, 7.36, 7.21, 7.59 mm) and is only held to the 3%.
Outcome taylorBarCoarse() {
  Outcome o = taylorBarAt("taylor-bar-coarse", 1.0e-3);
  const TaylorBarResult coarser = runTaylorBar(1.6e-3);
  const double e_coarser = rangeError(coarser.length, length_low, length_high);
  o.passed = o.passed && (o.error == 0.0 || o.error < e_coarser);
  o.note += fmt::format("; length at 1.6 mm {:.3f} mm ({:.2f}% outside): must be farther", 1e3 * coarser.length,
                        100 * e_coarser);
  return o;
}

}  // namespace kessler::verify
