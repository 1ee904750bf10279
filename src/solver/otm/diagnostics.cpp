#include "solver/otm/diagnostics.hpp"

#include "core/error.hpp"
#include "solver/otm/integrator.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace kessler::otm {

std::string describeNode(const Model& model, const StepInfo& at, LocalIndex a, const std::string& what) {
  const NodeStore& s = model.nodes;
  const auto body = static_cast<std::size_t>(s.body[a]);
  return fmt::format("{}: node {} of body '{}' at {} m: {}", describeStep(at), s.id[a],
                     body < model.bodies.size() ? model.bodies[body].name : "?", describeVector(s.x[a]), what);
}

void Diagnostics::check(const Model& model, const StepInfo& at, double reference_energy, const Share& share) {
  const NodeStore& nodes = model.nodes;
  LocalIndex bad = nodes.owned;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex a = 0; a < nodes.owned; ++a)
    if (!nodes.x[a].allFinite() || !nodes.v[a].allFinite()) bad = std::min(bad, a);
  if (bad < nodes.owned) {
    const std::string what = nodes.x[bad].allFinite()
                                 ? fmt::format("non-finite velocity v = {} m/s", describeVector(nodes.v[bad]))
                                 : fmt::format("non-finite position {}", describeVector(nodes.x[bad]));
    throw NumericalError(describeNode(model, at, bad, what));
  }
  auto driven = [&] {  // a piston does work (asked on every rank alike)
    bool here = false;
    for (LocalIndex a = 0; a < nodes.owned && !here; ++a)
      here = nodes.constrained[a] != 0 && nodes.prescribed_v[a].squaredNorm() > 0.0;
    return share.any(here);
  };
  const StepLengthRule rule{
      [&](LocalIndex p) { return stepLength(model, p); },
      [&](LocalIndex p) {
        return fmt::format(
            "from h0 times its smallest principal stretch lambda_min = {:.6g} or, where that is below "
            "half its spacing, from its support's spread",
            smallestStretch(model.points.F[p]));
      }};
  points_.check(model, at, reference_energy, rule, driven, share);
}

}  // namespace kessler::otm
