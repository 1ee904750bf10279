// momentum: two elastic bodies of different size collide obliquely and seize together. With
// nodal momentum gathered from the material points (docs/theory.md §4) and forces whose
// sum vanishes by the LME identity sum_a grad N_a = 0, total linear momentum is conserved to
// round-off. Measured: the largest change of total momentum over the run divided by the
// momentum scale sum_p m_p |v_p(0)|; tolerance 1e-10. The run must also show a real
// exchange of momentum between the bodies, or the problem fails.
#include "core/exact_sum.hpp"
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

namespace kessler::verify {

Outcome momentum() {
  const double h = 1e-3;
  auto material = elasticAluminium();
  const int a = 0;
  Problem problem;
  problem.bodies = {
      boxBody("cube A", {Vec3(0, 0, 0), Vec3(4 * h, 4 * h, 4 * h)}, {4, 4, 4}, Vec3(150.0, 20.0, -10.0), material),
      boxBody("block B", {Vec3(4.3 * h, 1.5 * h, -1.2 * h), Vec3(10.3 * h, 7.5 * h, 3.8 * h)}, {6, 6, 5},
              Vec3(-60.0, 0.0, 5.0), material)};
  problem.settings.solver.end_time = 6e-6;
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  method->initialise();
  const ParticleState& model = method->state();

  auto bodyMomentum = [&](int body) {
    return exactSums<3>(model.points.owned, [&](LocalIndex p) -> Vec3 {
      return model.points.body[p] == body ? Vec3(model.points.mass[p] * model.points.v[p]) : Vec3(Vec3::Zero());
    });
  };
  const Vec3 p0 = method->energies().momentum;
  const Vec3 pa0 = bodyMomentum(a);
  double scale = 0.0;
  for (LocalIndex p = 0; p < model.points.owned; ++p) scale += model.points.mass[p] * model.points.v[p].norm();
  double worst = 0.0;
  while (!method->finished()) {
    method->step();
    worst = std::max(worst, (method->energies().momentum - p0).norm() / scale);
  }
  const double exchanged = (bodyMomentum(a) - pa0).norm() / pa0.norm();

  Outcome o;
  o.name = "momentum";
  o.quantity = "max |P(t) - P(0)| / sum m|v|";
  o.measured = exchanged > 0.05 ? worst : std::numeric_limits<double>::infinity();
  o.reference = 0.0;
  o.tolerance = 1e-10;
  o.comparison = Comparison::absolute;
  o.note = fmt::format("{} steps; body A's momentum changed by {:.0f}% through contact", method->clock().steps,
                       100.0 * exchanged);
  return compare(o);
}

}  // namespace kessler::verify
