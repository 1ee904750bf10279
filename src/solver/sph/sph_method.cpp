#include "solver/sph/sph_method.hpp"

#include "core/error.hpp"
#include "solver/sph/setup.hpp"

#include <fmt/format.h>

namespace kessler::sph {

Settings settingsFor(const Problem& problem) {
  return Settings{problem.settings.solver, problem.settings.sph, problem.walls, problem.symmetry_axes};
}

SphMethod::SphMethod(Model model, const Settings& settings)
    : model_(std::move(model)), integrator_(model_, settings), diagnostics_(settings.solver) {}

SphMethod::SphMethod(Model model, const Problem& problem) : SphMethod(std::move(model), settingsFor(problem)) {
  // The particles never move between stores or ranks: their indices hold for the run.
  for (const PlaneConstraint& plane : problem.planes)
    if (plane.history) histories_.push_back({plane.axis, plane.history, particlesOnPlane(model_, plane)});
}

void SphMethod::step() {
  // The histories at the middle of the step, as OTM's.
  const Clock c = integrator_.clock();
  for (const History& h : histories_) {
    const double v = h.velocity(c.time + 0.5 * c.dt_next);
    for (const LocalIndex p : h.particles) model_.prescribed_v[p][h.axis] = v;
  }
  integrator_.step();
}

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
  std::vector<std::string> notes;
  if (const LocalIndex n = integrator_.distorted(); n > 0)
    notes.push_back(
        fmt::format("{} element(s) failed by their distortion (reconstructed corner angle below the "
                    "threshold; docs/theory.md §10)",
                    n));
  if (const LocalIndex n = integrator_.uncorrected(); n > 0)
    notes.push_back(
        fmt::format("{} particle(s) had too few neighbours for the kernel correction at the last step and "
                    "took the plain kernel gradient (docs/theory.md §10)",
                    n));
  return notes;
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
  out.scalar("sph_distorted", static_cast<std::int64_t>(integrator_.distorted()));
  std::vector<std::int32_t> element;
  for (const std::array<int, 3>& e : model_.element) element.insert(element.end(), e.begin(), e.end());
  out.array("/sph/element", element);
  std::vector<Vec3> lattices;
  for (const LatticeFrame& f : model_.lattices) {
    lattices.push_back(f.origin);
    lattices.push_back(f.cell);
  }
  out.array("/sph/lattices", lattices);
}

void SphMethod::load(const StateReader& in) {
  const auto n = static_cast<std::size_t>(model_.points.size());
  in.array("/sph/constrained", model_.constrained, n);
  in.array("/sph/prescribed_v", model_.prescribed_v, n);
  in.array("/sph/viscosity", model_.viscosity, n);
  std::vector<std::int32_t> element;
  in.array("/sph/element", element, 3 * n);
  for (std::size_t p = 0; p < n; ++p) model_.element[p] = {element[3 * p], element[3 * p + 1], element[3 * p + 2]};
  std::vector<Vec3> lattices;
  in.array("/sph/lattices", lattices, 2 * model_.bodies.size());
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) model_.lattices[b] = {lattices[2 * b], lattices[2 * b + 1]};
  integrator_.restore(Clock{in.doubleScalar("sph_time"), in.intScalar("sph_steps"), in.doubleScalar("sph_dt_last"),
                            in.doubleScalar("sph_dt_next"), in.doubleScalar("sph_dt_initial")},
                      static_cast<LocalIndex>(in.intScalar("sph_distorted")));
}

}  // namespace kessler::sph
