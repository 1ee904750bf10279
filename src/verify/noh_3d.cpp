// noh-3d: the spherical Noh problem (Noh, J. Comput. Phys. 72:78, 1987). A sphere of cold ideal
// gas (gamma = 5/3, rho0 = 1, p0 = 0) flows inward at unit speed. A shock leaves the centre at
// D = (gamma - 1)/2 = 1/3; behind it the gas is at rest with rho = rho0 ((gamma + 1)/(gamma - 1))^3
// = 64 and e = 1/2; ahead of it rho = rho0 (1 + t/r)^2. At t = 0.6 the shock is at r = 0.2.
//
// Octant of a unit sphere (three symmetry planes), unstructured Gmsh tetrahedra, the library's
// ideal gas with the solver's default shock capturing. Measured: the mass-weighted density of the
// plateau 0.25 r_s < r < 0.75 r_s (clear of the centre and of the smeared shock) against 64, and
// the shock radius where the radial velocity crosses half the inflow speed.
// The same mass over the space the plateau fills, not over the points' volumes, is judged beside it
// (the two agree where the volumes tile the space).
// Lagrangian and meshfree schemes overheat the gas that stagnates first (Noh's "wall heating"),
// which leaves the density at the centre low: reported as the density within 0.25 r_s, not
// judged.
#include "material/library.hpp"
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/impact_problems.hpp"

#include <algorithm>
#include <cmath>

namespace kessler::verify {

namespace {

constexpr double gamma_gas = 5.0 / 3.0;

}  // namespace

NohResult runNoh3d(double mesh_size, MethodSettings settings, double end_time) {
  BodySetup ball;
  ball.name = "gas";
  ball.material = std::make_shared<ImpactMaterial>("ideal-gas-5/3", library::find("ideal-gas-5/3").parameters);
  geometry::MeshRequest sphere;
  sphere.shape = geometry::Sphere{Vec3::Zero(), 1.0};
  sphere.mesh_size = mesh_size;
  ball.mesh = sphere;
  // Unit speed towards the centre.
  ball.velocity_field = [](const Vec3& x) -> Vec3 {
    const double r = x.norm();
    return r > 0.0 ? Vec3(-x / r) : Vec3(Vec3::Zero());
  };
  Problem problem;
  problem.bodies = {ball};
  problem.symmetry_axes = {0, 1, 2};
  problem.settings = settings;
  problem.settings.solver.end_time = end_time;
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  const ParticleState& model = method->state();

  NohResult r;
  for (LocalIndex p = 0; p < model.points.size(); ++p) r.initial_energy += 0.5 * model.points.mass[p];
  method->initialise();
  while (!method->finished()) method->step();

  const double ratio = (gamma_gas + 1.0) / (gamma_gas - 1.0);
  r.reference_density = ratio * ratio * ratio;
  r.reference_shock_radius = 0.5 * (gamma_gas - 1.0) * end_time;
  const double rs = r.reference_shock_radius;
  double m = 0.0, volume = 0.0, m_centre = 0.0, volume_centre = 0.0;
  // 80 shells for the front and the profile, out to 2 r_s or r = 0.4, whichever is further: r_s / 40
  // wide at t = 0.6, 0.005 wide at any earlier time (the start-up, seen with the shock study's --noh-end).
  const int shells = 80;
  const double dr = std::max(2.0 * rs, 0.4) / shells;
  std::vector<double> shell_mass(shells, 0.0), shell_volume(shells, 0.0), shell_momentum(shells, 0.0),
      shell_energy(shells, 0.0);
  const PointStore& points = model.points;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const double radius = points.x[p].norm();
    if (radius < 0.25 * rs) {
      m_centre += points.mass[p];
      volume_centre += points.volume[p];
    } else if (radius < 0.75 * rs) {
      m += points.mass[p];
      volume += points.volume[p];
    }
    const int s = static_cast<int>(radius / dr);
    if (s < shells) {
      shell_mass[s] += points.mass[p];
      shell_volume[s] += points.volume[p];
      shell_momentum[s] += radius > 0.0 ? points.mass[p] * points.v[p].dot(points.x[p]) / radius : 0.0;
      shell_energy[s] += points.mass[p] * points.energy[p];
    }
  }
  r.density = m / volume;
  r.packed_density = m / (M_PI / 6.0 * (std::pow(0.75 * rs, 3) - std::pow(0.25 * rs, 3)));
  r.centre_density = volume_centre > 0.0 ? m_centre / volume_centre : 0.0;
  for (int s = 0; s < shells; ++s)
    if (shell_mass[s] > 0.0)
      r.profile.push_back({dr * (s + 0.5), shell_mass[s] / shell_volume[s], shell_momentum[s] / shell_mass[s],
                           shell_energy[s] / shell_mass[s],
                           shell_mass[s] / (M_PI / 6.0 * (std::pow(dr * (s + 1), 3) - std::pow(dr * s, 3)))});
  // The front: the outermost shell where the radial velocity has risen above half the inflow
  // speed (the gas behind the shock is at rest, ahead of it flows in at unit speed).
  for (int s = shells - 1; s > 0; --s) {
    if (shell_mass[s] <= 0.0 || shell_mass[s - 1] <= 0.0) continue;
    const double inner = shell_momentum[s - 1] / shell_mass[s - 1], outer = shell_momentum[s] / shell_mass[s];
    if (inner >= -0.5 && outer < -0.5) {
      r.shock_radius = dr * (s - 0.5 + (inner + 0.5) / (inner - outer));
      break;
    }
  }
  // Kinetic, internal and the volume stabilisation's stored energy (docs/theory.md §4).
  r.energy_error = method->energies().total() / r.initial_energy - 1.0;
  r.points = points.owned;
  r.steps = method->clock().steps;
  return r;
}

Outcome noh3d() {
  // Two resolutions: the error must be within 10% at the finer and smaller than at the coarser. The
  // plateau's mass over the space it fills must be within 10% at the finer too: volumes short of
  // their space raise the density the law sees and could pass where the gas is not compressed enough.
  const double coarse = 0.05, fine = 0.035;
  const NohResult a = runNoh3d(coarse), b = runNoh3d(fine);
  const double e_coarse = std::abs(a.density / a.reference_density - 1.0);
  Outcome o;
  o.name = "noh-3d";
  o.quantity = "plateau density (rho0 = 1)";
  o.measured = b.density;
  o.reference = b.reference_density;
  o.tolerance = 0.10;
  o = compare(o);
  o.passed = o.passed && o.error < e_coarse && std::abs(b.packed_density / b.reference_density - 1.0) <= o.tolerance;
  o.note = fmt::format(
      "mesh {} : {:.2f} ({:+.1f}%; {:.2f} over the space it fills, must be within the tolerance too), shock at "
      "r = {:.4f} (vs {:.3f}), centre "
      "(r < {:.2f}) {:.1f} (wall heating); mesh {} : {:.2f} ({:+.1f}%; must be closer; {:.2f} packed), shock at "
      "{:.4f}, centre {:.1f}; {} and {} points, {} and {} steps",
      fine, b.density, 100 * (b.density / b.reference_density - 1.0), b.packed_density, b.shock_radius,
      b.reference_shock_radius, 0.25 * b.reference_shock_radius, b.centre_density, coarse, a.density,
      100 * (a.density / a.reference_density - 1.0), a.packed_density, a.shock_radius, a.centre_density, b.points,
      a.points, b.steps, a.steps);
  return o;
}

}  // namespace kessler::verify
