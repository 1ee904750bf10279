// wave-speed: a longitudinal wave in a bar under uniaxial strain. A 2 x 2 x 100-cell bar with
// roller (zero normal velocity) lateral faces is pushed at z = 0 by a piston at v0 = 1 m/s;
// the step front travels at the P-wave speed of linear elasticity, c_L = sqrt((K + 4G/3) / rho)
// (docs/validation.md). The front is the place where the slab-averaged velocity reaches v0/2;
// its speed is measured between two times so the start-up transient cancels.
#include "solver/methods.hpp"
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
  Problem problem;
  problem.bodies = {
      boxBody("bar", {Vec3::Zero(), Vec3(2 * h, 2 * h, cells * h)}, {2, 2, cells}, Vec3::Zero(), material)};
  const double tol = 1e-9 * h;
  // Rollers on the four sides (uniaxial strain), a piston at z = 0.
  for (const int axis : {0, 1})
    for (const int side : {1, -1})
      problem.rollers.push_back({.axis = axis, .offset = side > 0 ? 0.0 : 2 * h, .side = side, .tolerance = tol});
  problem.planes = {{.axis = 2, .offset = 0.0, .tolerance = tol, .velocity = v0}};

  const NeoHookeanParameters p{.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33};
  const double c_l = std::sqrt((p.bulkModulus() + 4.0 * p.shearModulus() / 3.0) / p.density);
  const double t1 = 25 * h / c_l, t2 = 75 * h / c_l;

  problem.settings.solver.end_time = t2;
  problem.settings.solver.cfl = 0.3;
  double z1 = std::nan(""), t_first = 0.0;
  const std::unique_ptr<Method> method = runToEnd(problem, [&](const Method& m) {
    if (std::isnan(z1) && m.clock().time >= t1) {
      z1 = frontPosition(m.state().points, h, cells, v0);
      t_first = m.clock().time;
    }
    return true;
  });
  const double z2 = frontPosition(method->state().points, h, cells, v0);
  Outcome o;
  o.name = "wave-speed";
  o.quantity = "longitudinal wave speed (m/s)";
  o.measured = (z2 - z1) / (method->clock().time - t_first);
  o.reference = c_l;
  o.tolerance = 0.02;
  o.note = fmt::format("bar 2x2x{} cells of {} mm, piston {} m/s, {} steps", cells, h * 1e3, v0, method->clock().steps);
  return compare(o);
}

}  // namespace kessler::verify
