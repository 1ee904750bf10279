// wave-speed: a longitudinal wave in a bar under uniaxial strain. A 2 x 2 x 100-cell bar with
// roller (zero normal velocity) lateral faces is pushed at z = 0 by a piston at v0 = 1 m/s;
// the step front travels at the P-wave speed of linear elasticity, c_L = sqrt((K + 4G/3) / rho)
// (docs/validation.md). The front is the place where the slab-averaged velocity reaches v0/2;
// its speed is measured between two times so the start-up transient cancels.
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

#include <cmath>

namespace kessler::verify {

namespace {

// Position along z where the velocity profile, averaged over slabs of width h, falls through
// half the piston speed, by linear interpolation between slab centres.
double frontPosition(const PointStore& points, double h, int slabs, double v0) {
  std::vector<double> sum(static_cast<std::size_t>(slabs), 0.0), mass(static_cast<std::size_t>(slabs), 0.0);
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const int s = std::clamp(static_cast<int>(points.x[p][2] / h), 0, slabs - 1);
    sum[s] += points.mass[p] * points.v[p][2];
    mass[s] += points.mass[p];
  }
  for (int s = slabs - 1; s > 0; --s) {
    const double hi = sum[s - 1] / mass[s - 1], lo = sum[s] / mass[s];
    if (hi >= 0.5 * v0 && lo < 0.5 * v0) return h * (s - 0.5 + (hi - 0.5 * v0) / (hi - lo));
  }
  return std::nan("");
}

}  // namespace

Outcome waveSpeed() {
  const double h = 1e-3, v0 = 1.0;
  const int cells = 100;
  auto material = elasticAluminium();
  otm::Model model;
  addBoxBody(model, "bar", {Vec3::Zero(), Vec3(2 * h, 2 * h, cells * h)}, {2, 2, cells}, Vec3::Zero(), material);
  const double tol = 1e-9 * h;
  otm::constrainPlane(model, 0, 0.0, tol);
  otm::constrainPlane(model, 0, 2 * h, tol);
  otm::constrainPlane(model, 1, 0.0, tol);
  otm::constrainPlane(model, 1, 2 * h, tol);
  otm::constrainPlane(model, 2, 0.0, tol, v0);

  const NeoHookeanParameters p{.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33};
  const double c_l = std::sqrt((p.bulkModulus() + 4.0 * p.shearModulus() / 3.0) / p.density);
  const double t1 = 25 * h / c_l, t2 = 75 * h / c_l;

  otm::Settings settings;
  settings.end_time = t2;
  settings.cfl = 0.3;
  otm::Integrator integrator(model, settings);
  integrator.initialise();
  double z1 = std::nan(""), t_first = 0.0;
  while (!integrator.finished()) {
    integrator.step();
    if (std::isnan(z1) && integrator.time() >= t1) {
      z1 = frontPosition(model.points, h, cells, v0);
      t_first = integrator.time();
    }
  }
  const double z2 = frontPosition(model.points, h, cells, v0);
  Outcome o;
  o.name = "wave-speed";
  o.quantity = "longitudinal wave speed (m/s)";
  o.measured = (z2 - z1) / (integrator.time() - t_first);
  o.reference = c_l;
  o.tolerance = 0.02;
  o.note = fmt::format("bar 2x2x{} cells of {} mm, piston {} m/s, {} steps", cells, h * 1e3, v0, integrator.steps());
  return compare(o);
}

}  // namespace kessler::verify
