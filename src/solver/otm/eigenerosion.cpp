#include "solver/otm/eigenerosion.hpp"

#include <algorithm>

namespace kessler::otm {

double erosionCalibration(double eps, double nu) { return 64.0 * eps / (3.0 * (5.0 - 3.0 * nu)); }

bool Eigenerosion::active(const Model& model) const {
  return std::any_of(model.materials.begin(), model.materials.end(),
                     [](const MaterialPtr& m) { return m->fractureEnergy() > 0.0; });
}

LocalIndex Eigenerosion::apply(Model& model) {
  if (!active(model)) return 0;
  PointStore& points = model.points;
  const LocalIndex np = points.owned;
  double max_eps = 0.0;
  for (LocalIndex p = 0; p < np; ++p) max_eps = std::max(max_eps, settings_.erosion_radius * points.spacing(p));
  cells_.build(points.x, np, max_eps);

  std::vector<double> gc(model.bodies.size()), nu(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Material& material = *model.materials[model.bodies[b].material];
    gc[b] = material.fractureEnergy();
    nu[b] = material.poissonRatio();
  }
  erode_.assign(static_cast<std::size_t>(np), 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (LocalIndex p = 0; p < np; ++p) {
    const int body = points.body[p];
    if (points.eroded[p] || gc[body] <= 0.0) continue;
    const double eps = settings_.erosion_radius * points.spacing(p);
    double mass = 0.0, energy = 0.0;
    cells_.forEachWithin(points.x[p], eps, [&](LocalIndex q, double) {
      if (points.eroded[q] || points.body[q] != body) return;
      mass += points.mass[q];
      energy += points.mass[q] * points.strain_energy[q];
    });
    const double release_rate = erosionCalibration(eps, nu[body]) * energy / mass;
    if (release_rate >= gc[body]) erode_[p] = 1;
  }
  LocalIndex count = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (!erode_[p]) continue;
    points.eroded[p] = 1;
    points.stress[p].setZero();
    points.viscous_pressure[p] = 0.0;
    ++count;
  }
  return count;
}

}  // namespace kessler::otm
