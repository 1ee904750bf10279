#include "solver/sph/sph_method.hpp"

#include "core/error.hpp"
#include "solver/common/particle_bodies.hpp"
#include "solver/sph/setup.hpp"

#include <fmt/format.h>

namespace kessler::sph {

Settings settingsFor(const Problem& problem) {
  return Settings{problem.settings.solver, problem.settings.sph, problem.walls, mirrorBox(problem)};
}

namespace {

std::unique_ptr<Distribution> distributionFor(const parallel::Communicator* ranks, const Settings& settings) {
  return ranks && ranks->size() > 1 ? std::make_unique<Distribution>(*ranks, settings.mirrors) : nullptr;
}

}  // namespace

SphMethod::SphMethod(Model model, const Settings& settings, const parallel::Communicator* ranks)
    : model_(std::move(model)),
      distribution_(distributionFor(ranks, settings)),
      integrator_(model_, settings, distribution_.get()),
      diagnostics_(settings.solver) {}

SphMethod::SphMethod(Model model, const Problem& problem, const parallel::Communicator* ranks)
    : SphMethod(std::move(model), settingsFor(problem), ranks) {
  for (const PlaneConstraint& plane : problem.planes) {
    if (!plane.history) continue;
    std::vector<Index> ids;
    for (const LocalIndex p : particlesOnPlane(model_.points, plane)) ids.push_back(model_.points.id[p]);
    histories_.add(plane, std::move(ids));
  }
}

void SphMethod::initialise() {
  integrator_.initialise();
  locateHistories();
}

void SphMethod::locateHistories() {
  histories_.locate(model_.points.id, distribution_ != nullptr);  // a distributed run's rank holds some
  located_ = distribution_ ? distribution_->layout() : 0;
}

void SphMethod::step() {
  // The histories at the middle of the step, as OTM's, on the particles where they are now.
  if (distribution_ && distribution_->layout() != located_) locateHistories();
  const Clock c = integrator_.clock();
  histories_.apply(c.time + 0.5 * c.dt_next, model_.prescribed_v);
  integrator_.step();
}

void SphMethod::check(double initial_total_energy) {
  const Clock c = integrator_.clock();
  const StepInfo at{c.steps, c.time, c.dt_next, c.dt_initial};
  // A piston does work (the same answer on every rank of a distributed run: a velocity history, or
  // a prescribed velocity held by any rank).
  auto driven = [&] {
    return prescribedWork(histories_, model_.constrained, model_.prescribed_v, model_.points.owned);
  };
  const StepLengthRule rule{[&](LocalIndex p) { return integrator_.smoothingLength(p); },
                            [&](LocalIndex) { return std::string("its smoothing length"); }};
  if (!distribution_) {
    diagnostics_.check(model_, at, initial_total_energy, rule, driven);
    return;
  }
  // Every rank stops if one does (the others would wait for it).
  const Share share = distribution_->share();
  const bool piston = share.any(driven());
  std::optional<NumericalError> failure;
  try {
    diagnostics_.check(
        model_, at, initial_total_energy, rule, [&] { return piston; }, share);
  } catch (const NumericalError& e) {
    failure = e;
  }
  const std::string elsewhere = fmt::format("{}: another rank's health check failed", describeStep(at));
  share.stopTogether(
      failure.has_value(), [&] { throw *failure; }, elsewhere.c_str());
}

std::vector<std::pair<std::string, double>> SphMethod::sizes() const {
  if (report_) return report_->sizes;
  std::vector<std::pair<std::string, double>> sizes{{"mean_neighbours", integrator_.meanNeighbours()}};
  if (!distribution_) return sizes;
  const Distribution& d = *distribution_;
  const std::vector<std::pair<std::string, double>> ranks{{"ranks", d.comm().size()},
                                                          {"imbalance", d.imbalance()},
                                                          {"largest_imbalance", d.largestImbalance()},
                                                          {"rebalances", d.rebalances()},
                                                          {"rank0_own_particles", d.ownParticles()},
                                                          {"rank0_ghost_particles", d.ghostParticles()},
                                                          {"halo_fetches", static_cast<double>(d.haloFetches())},
                                                          {"halo_keeps", static_cast<double>(d.haloKeeps())}};
  sizes.insert(sizes.end(), ranks.begin(), ranks.end());
  return sizes;
}

std::unique_ptr<Method> SphMethod::gathered(bool) const {
  if (!distribution_) return nullptr;
  std::vector<std::pair<std::string, double>> sizes = this->sizes();  // collective
  std::optional<Model> whole = distribution_->gather(model_);
  if (!whole) return nullptr;
  auto method = std::make_unique<SphMethod>(std::move(*whole), integrator_.settings());
  method->integrator_.adopt(integrator_.clock(), integrator_.distorted(), integrator_.stored());
  method->report_ = GatheredReport{integrator_.timers(), std::move(sizes), notes()};
  return method;
}

std::vector<std::string> SphMethod::notes() const {
  if (report_) return report_->notes;
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
  saveClock(out, "sph_", integrator_.clock());
  out.group("/sph");
  out.array("/sph/constrained", model_.constrained);
  out.array("/sph/prescribed_v", model_.prescribed_v);
  out.array("/sph/viscosity", model_.viscosity);
  out.scalar("sph_distorted", static_cast<std::int64_t>(integrator_.distorted()));
  out.scalar("sph_dissipated", integrator_.stored());  // (the stabilisation's store, by its first name)
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
  integrator_.restore(loadClock(in, "sph_"),
                      static_cast<LocalIndex>(in.intScalar("sph_distorted")), in.doubleScalar("sph_dissipated"));
}

}  // namespace kessler::sph
