// wave-speed: a longitudinal wave in a bar under uniaxial strain. A 2 x 2 x 100-cell bar with
// roller (zero normal velocity) lateral faces is pushed at z = 0 by a piston at v0 = 1 m/s;
// the step front travels at the P-wave speed of linear elasticity, c_L = sqrt((K + 4G/3) / rho)
// (docs/validation.md). The front is the place where the slab-averaged velocity reaches v0/2;
// its speed is measured between two times so the start-up transient cancels.
//
// plate-wave: the same piston on a plate 4 cells thick whose two faces are free (rollers on the
// other two sides: a plane wave in an infinite plate). A wave much longer than the plate is thick
// is one of plane stress across the thickness and plane strain across the width: it travels at the
// plate speed c_p = sqrt(E / (rho (1 - nu^2))) and carries the axial stress -rho c_p v0 (Graff,
// Wave Motion in Elastic Solids, 1975, on plates). A step is not a long wave: the plate's dispersion
// spreads the front, whose half-height point lags the long-wave speed by about 1% here
// (docs/validation.md, "A plate's extensional wave"). Both the speed and the stress behind the front
// are judged: a method whose free faces were too stiff or too soft would carry the wave at the
// bulk's or the bar's speed and impedance instead.
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

#include <cmath>

namespace kessler::verify {

namespace {

constexpr double cell = 1e-3, piston_speed = 1.0;
constexpr int cells = 100;

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

struct Front {
  double speed = 0.0;     // between a quarter and three quarters of the bar's length
  double position = 0.0;  // at the end
  // The volume-mean axial stress at the end, from 10 cells past the piston to 15 short of the front.
  double stress = 0.0;
  Index steps = 0;
};

// A box of `across` x `thick` x 100 cells, rollers on its x faces (and on its y faces if `rollers_y`),
// pushed at z = 0 by the piston until a wave at `speed` would have crossed three quarters of it.
Front pushBox(int across, int thick, bool rollers_y, double speed) {
  Problem problem;
  problem.bodies = {boxBody("bar", {Vec3::Zero(), Vec3(across * cell, thick * cell, cells * cell)},
                            {across, thick, cells}, Vec3::Zero(), elasticAluminium())};
  const double tol = 1e-9 * cell;
  for (const int axis : {0, 1}) {
    if (axis == 1 && !rollers_y) continue;
    const double width = (axis == 0 ? across : thick) * cell;
    for (const int side : {1, -1})
      problem.rollers.push_back({.axis = axis, .offset = side > 0 ? 0.0 : width, .side = side, .tolerance = tol});
  }
  problem.planes = {{.axis = 2, .offset = 0.0, .tolerance = tol, .velocity = piston_speed}};
  const double t1 = 25 * cell / speed, t2 = 75 * cell / speed;
  problem.settings.solver.end_time = t2;
  problem.settings.solver.cfl = 0.3;
  double z1 = std::nan(""), t_first = 0.0;
  const std::unique_ptr<Method> method = runToEnd(problem, [&](const Method& m) {
    if (std::isnan(z1) && m.clock().time >= t1) {
      z1 = frontPosition(m.state().points, cell, cells, piston_speed);
      t_first = m.clock().time;
    }
    return true;
  });
  const PointStore& points = method->state().points;
  Front f;
  f.position = frontPosition(points, cell, cells, piston_speed);
  f.speed = (f.position - z1) / (method->clock().time - t_first);
  double sum = 0.0, volume = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (points.x[p][2] >= 10 * cell && points.x[p][2] <= f.position - 15 * cell) {
      sum += points.volume[p] * points.stress[p](2, 2);
      volume += points.volume[p];
    }
  f.stress = volume > 0.0 ? sum / volume : std::nan("");
  f.steps = method->clock().steps;
  return f;
}

// The front's speed against `reference`, within 2%.
Outcome speedOutcome(const char* name, const char* quantity, const Front& f, double reference) {
  Outcome o;
  o.name = name;
  o.quantity = quantity;
  o.measured = f.speed;
  o.reference = reference;
  o.tolerance = 0.02;
  return compare(o);
}

}  // namespace

Outcome waveSpeed() {
  const NeoHookeanParameters p = elasticAluminiumParameters();
  const double c_l = std::sqrt((p.bulkModulus() + 4.0 * p.shearModulus() / 3.0) / p.density);
  const Front f = pushBox(2, 2, true, c_l);
  Outcome o = speedOutcome("wave-speed", "longitudinal wave speed (m/s)", f, c_l);
  o.note = fmt::format("bar 2x2x{} cells of {} mm, piston {} m/s, {} steps", cells, cell * 1e3, piston_speed, f.steps);
  return o;
}

Outcome plateWave() {
  const NeoHookeanParameters p = elasticAluminiumParameters();
  const double nu = p.poisson_ratio;
  const double c_p = std::sqrt(p.youngs_modulus / (p.density * (1.0 - nu * nu)));
  const double stress = -p.density * c_p * piston_speed;
  const Front f = pushBox(2, 4, false, c_p);
  Outcome o = speedOutcome("plate-wave", "plate wave speed (m/s)", f, c_p);
  const double stress_error = std::abs(f.stress / stress - 1.0);
  o.passed = o.passed && stress_error <= o.tolerance;
  o.note = fmt::format(
      "plate 4 cells of {} mm thick, free faces, piston {} m/s; axial stress behind the front {:.3f} MPa vs {:.3f} "
      "({:.2f}%, tol 2%); {} steps",
      cell * 1e3, piston_speed, f.stress * 1e-6, stress * 1e-6, 100 * stress_error, f.steps);
  return o;
}

}  // namespace kessler::verify
