// energy: free axial vibration of an elastic bar (free-free, first mode), started with the
// velocity field v_z = v0 cos(pi z / L) and run for five periods T = 2L / sqrt(E/rho). The
// kinetic energy is taken at the half steps and the strain energy at the full steps, so the
// total oscillates slightly within each period; the drift is the change of its average over
// one period between the first and the last period, relative to the initial energy.
// Tolerance 1%.
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

#include <cmath>
#include <numbers>

namespace kessler::verify {

Outcome energy() {
  const double h = 1e-3, v0 = 2.0;
  const int cells = 40;
  const double length = cells * h;
  auto material = elasticAluminium();
  Problem problem;
  problem.bodies = {boxBody("bar", {Vec3::Zero(), Vec3(2 * h, 2 * h, length)}, {2, 2, cells}, Vec3::Zero(), material)};
  problem.bodies[0].velocity_field = [&](const Vec3& x) {
    return Vec3(0, 0, v0 * std::cos(std::numbers::pi * x[2] / length));
  };
  const double period = 2.0 * length / std::sqrt(70e9 / 2700.0);
  const double end_time = problem.settings.solver.end_time = 5.0 * period;
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  method->initialise();
  const double e0 = method->energies().total();

  // Time-weighted averages of the total energy over the first and the last period.
  double first = 0.0, first_t = 0.0, last = 0.0, last_t = 0.0, worst = 0.0;
  while (!method->finished()) {
    method->step();
    const Clock clock = method->clock();
    const double t = clock.time, dt = clock.dt_last, e = method->energies().total();
    worst = std::max(worst, std::abs(e - e0) / e0);
    if (t <= period) first += e * dt, first_t += dt;
    if (t > end_time - period) last += e * dt, last_t += dt;
  }
  Outcome o;
  o.name = "energy";
  o.quantity = "energy drift over 5 periods / E0";
  o.measured = std::abs(last / last_t - first / first_t) / e0;
  o.reference = 0.0;
  o.tolerance = 0.01;
  o.comparison = Comparison::absolute;
  o.note =
      fmt::format("bar 2x2x{} cells, {} steps, largest excursion {:.2g} of E0", cells, method->clock().steps, worst);
  return compare(o);
}

}  // namespace kessler::verify
