#include "solver/methods.hpp"

#include "core/error.hpp"
#include "solver/otm/otm_method.hpp"
#include "solver/otm/setup.hpp"

#include <fmt/ranges.h>

#include <algorithm>

namespace kessler {

namespace {

void requireKnown(const Problem& problem) {
  const std::vector<std::string>& known = methodNames();
  if (std::find(known.begin(), known.end(), problem.method) == known.end())
    throw Error(fmt::format("solver.method '{}' is not a method of this Kessler (known: {})", problem.method,
                            fmt::join(known, ", ")));
}

}  // namespace

const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names{"otm"};
  return names;
}

std::unique_ptr<Method> makeMethod(const Problem& problem, const parallel::Communicator* ranks) {
  requireKnown(problem);
  return std::make_unique<otm::OtmMethod>(otm::buildModel(problem), problem, ranks);
}

std::unique_ptr<Method> makeMethod(const Problem& problem, ParticleState&& restored,
                                   const parallel::Communicator* ranks) {
  requireKnown(problem);
  otm::Model model;
  static_cast<ParticleState&>(model) = std::move(restored);
  return std::make_unique<otm::OtmMethod>(std::move(model), problem, ranks);
}

}  // namespace kessler
