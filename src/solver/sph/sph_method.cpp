#include "solver/sph/sph_method.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

namespace kessler::sph {

Settings settingsFor(const Problem& problem) {
  for (const PlaneConstraint& plane : problem.planes)
    if (plane.history) throw Error("SPH does not yet take a prescribed velocity history (a verification problem's)");
  return Settings{problem.settings.solver, problem.settings.sph, problem.walls, problem.symmetry_axes};
}

SphMethod::SphMethod(Model model, const Settings& settings)
    : model_(std::move(model)), integrator_(model_, settings), diagnostics_(settings.solver) {}

void SphMethod::check(double initial_total_energy) {
  const Clock c = integrator_.clock();
  const StepInfo at{c.steps, c.time, c.dt_next, c.dt_initial};
  auto driven = [&] {  // a piston does work
    for (LocalIndex p = 0; p < model_.points.owned; ++p)
      if (model_.constrained[p] != 0 && model_.prescribed_v[p].squaredNorm() > 0.0) return true;
    return false;
  };
  const StepLengthRule rule{[&](LocalIndex p) { return integrator_.smoothingLength(p); },
                            [&](LocalIndex) { return std::string("its smoothing length"); }};
  diagnostics_.check(model_, at, initial_total_energy, rule, driven);
}

std::vector<std::pair<std::string, double>> SphMethod::sizes() const {
  return {{"mean_neighbours", integrator_.meanNeighbours()}};
}

std::vector<std::string> SphMethod::notes() const {
  const LocalIndex n = integrator_.uncorrected();
  if (n == 0) return {};
  return {
      fmt::format("{} particle(s) had too few neighbours for the kernel correction at the last step and took the "
                  "plain kernel gradient (docs/theory.md §10)",
                  n)};
}

void SphMethod::save(StateWriter& out) const {
  const Clock c = integrator_.clock();
  out.scalar("sph_time", c.time);
  out.scalar("sph_dt_last", c.dt_last);
  out.scalar("sph_dt_next", c.dt_next);
  out.scalar("sph_dt_initial", c.dt_initial);
  out.scalar("sph_steps", static_cast<std::int64_t>(c.steps));
  out.group("/sph");
  out.array("/sph/constrained", model_.constrained);
  out.array("/sph/prescribed_v", model_.prescribed_v);
  out.array("/sph/viscosity", model_.viscosity);
}

void SphMethod::load(const StateReader& in) {
  const auto n = static_cast<std::size_t>(model_.points.size());
  in.array("/sph/constrained", model_.constrained, n);
  in.array("/sph/prescribed_v", model_.prescribed_v, n);
  in.array("/sph/viscosity", model_.viscosity, n);
  integrator_.restore(Clock{in.doubleScalar("sph_time"), in.intScalar("sph_steps"), in.doubleScalar("sph_dt_last"),
                            in.doubleScalar("sph_dt_next"), in.doubleScalar("sph_dt_initial")});
}

}  // namespace kessler::sph
