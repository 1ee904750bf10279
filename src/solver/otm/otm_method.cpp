#include "solver/otm/otm_method.hpp"

#include <fmt/format.h>

namespace kessler::otm {

void OtmMethod::check(double initial_total_energy) {
  const StepInfo at{integrator_.steps(), integrator_.time(), integrator_.nextStep(), integrator_.initialStep()};
  diagnostics_.check(model_, at, initial_total_energy);
}

Clock OtmMethod::clock() const {
  return {integrator_.time(), integrator_.steps(), integrator_.lastStep(), integrator_.nextStep(),
          integrator_.initialStep()};
}

std::vector<std::pair<std::string, double>> OtmMethod::sizes() const {
  const double points = model_.points.owned;
  return {{"mean_neighbours", points > 0 ? static_cast<double>(model_.connectivity.node.size()) / points : 0.0}};
}

std::vector<std::string> OtmMethod::notes() const {
  if (integrator_.tornPoints() == 0) return {};
  return {
      fmt::format("torn from their bodies: {} intact point(s), {:.3g} g, outside the hull of every neighbourhood of "
                  "their nodes, released as debris (docs/theory.md §8)",
                  integrator_.tornPoints(), 1e3 * integrator_.tornMass())};
}

}  // namespace kessler::otm
