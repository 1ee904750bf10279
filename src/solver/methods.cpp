#include "solver/methods.hpp"

#include "core/error.hpp"
#include "solver/otm/otm_method.hpp"
#include "solver/otm/setup.hpp"
#include "solver/rkpm/rkpm_method.hpp"
#include "solver/rkpm/setup.hpp"
#include "solver/sph/setup.hpp"
#include "solver/sph/sph_method.hpp"

#include <fmt/ranges.h>

#include <algorithm>

namespace kessler {

namespace {

void requireKnown(const Problem& problem) {
  const std::vector<std::string>& known = methodNames();
  if (std::find(known.begin(), known.end(), problem.method) == known.end())
    throw Error(fmt::format("solver.method '{}' is not a method of this Kessler (known: {})", problem.method,
                            fmt::join(known, ", ")));
  if (problem.method == "sph" && problem.settings.solver.contact.sliding())
    throw InputError(
        "solver.contact: a sliding contact is OTM's and RKPM's for now; SPH's bodies meet through their particle "
        "pairs (give type: seizing, or solver.method: otm)");
}

void refuseRanks(const parallel::Communicator* ranks) {
  if (ranks && ranks->size() > 1)
    throw InputError(
        fmt::format("solver.method: RKPM runs on one process for now; this run has {} ranks", ranks->size()));
}

}  // namespace

const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names{"otm", "sph", "rkpm"};
  return names;
}

std::unique_ptr<Method> makeMethod(const Problem& problem, const parallel::Communicator* ranks) {
  requireKnown(problem);
  if (problem.method == "sph") return std::make_unique<sph::SphMethod>(sph::buildModel(problem), problem, ranks);
  if (problem.method == "rkpm") {
    refuseRanks(ranks);
    return std::make_unique<rkpm::RkpmMethod>(rkpm::buildModel(problem), problem);
  }
  return std::make_unique<otm::OtmMethod>(otm::buildModel(problem), problem, ranks);
}

std::unique_ptr<Method> makeMethod(const Problem& problem, ParticleState&& restored,
                                   const parallel::Communicator* ranks) {
  requireKnown(problem);
  if (problem.method == "sph") {
    sph::Model model;
    static_cast<ParticleState&>(model) = std::move(restored);
    model.constrained.resize(model.points.x.size(), 0);  // SphMethod::load reads them
    model.prescribed_v.resize(model.points.x.size(), Vec3::Zero());
    model.viscosity.resize(model.points.x.size(), 0.0);
    model.element.resize(model.points.x.size(), {-1, -1, -1});
    model.lattices.resize(model.bodies.size());
    return std::make_unique<sph::SphMethod>(std::move(model), sph::settingsFor(problem), ranks);
  }
  if (problem.method == "rkpm") {
    refuseRanks(ranks);
    rkpm::Model model;
    static_cast<ParticleState&>(model) = std::move(restored);  // RkpmMethod::load reads the rest
    const std::size_t n = model.points.x.size();
    model.constrained.resize(n, 0);
    model.prescribed_v.resize(n, Vec3::Zero());
    model.reference.resize(n, Vec3::Zero());
    model.coefficient_x.resize(n, Vec3::Zero());
    model.coefficient_v.resize(n, Vec3::Zero());
    model.cell_volume.resize(n, 0.0);
    model.element.resize(n, {-1, -1, -1});
    return std::make_unique<rkpm::RkpmMethod>(std::move(model), rkpm::settingsFor(problem));
  }
  otm::Model model;
  static_cast<ParticleState&>(model) = std::move(restored);
  return std::make_unique<otm::OtmMethod>(std::move(model), problem, ranks);
}

}  // namespace kessler
