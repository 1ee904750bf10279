#include "solver/common/eigenerosion.hpp"

#include "solver/common/own_sums.hpp"

#include <algorithm>
#include <limits>

namespace kessler {

double erosionCalibration(double eps, double nu) {
  return 64.0 * eps / (3.0 * (5.0 - 3.0 * nu));
}

bool Eigenerosion::active(const ParticleState& model) const {
  return std::any_of(model.materials.begin(), model.materials.end(),
                     [](const MaterialPtr& m) { return m->fractureEnergy() > 0.0; });
}

LocalIndex Eigenerosion::apply(ParticleState& model, const Share& share) {
  if (!active(model)) return 0;
  PointStore& points = model.points;
  const LocalIndex np = points.owned;
  std::vector<double> gc(model.bodies.size()), nu(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Material& material = *model.materials[model.bodies[b].material];
    gc[b] = material.fractureEnergy();
    nu[b] = material.poissonRatio();
  }

  // Only intact points of eroding bodies take part (as candidates and as ball members), so the
  // cell list holds just those: eroded debris spread over a large cloud would otherwise stretch
  // the grid, and so every query. Cells of the mean ball radius, as in the neighbour search: a
  // few strongly expanded points must not make every cell large.
  candidate_x_.clear();
  candidate_.clear();
  for (LocalIndex p = 0; p < np; ++p) {
    if (points.broken[p] || gc[points.body[p]] <= 0.0) continue;
    candidate_x_.push_back(points.x[p]);
    candidate_.push_back(p);
  }
  const auto count = static_cast<LocalIndex>(candidate_.size());
  candidate_eps_.resize(static_cast<std::size_t>(count));
  // Over a distributed run's own candidates and every rank, and enlarged alike: the cells order each
  // ball's sum, which must be the same bits on every rank.
  // (Every rank takes part, with candidates or without.)
  const Eigen::Vector2d eps_sum = ownSums<2>(Share{{}, share.comm}, count, [&](LocalIndex k) {
    candidate_eps_[k] = erosion_radius_ * points.spacing(candidate_[k]);
    return share.own(candidate_[k]) ? Eigen::Vector2d(candidate_eps_[k], 1.0) : Eigen::Vector2d(0.0, 0.0);
  });
  if (!(eps_sum[1] > 0.0)) return 0;
  double cell_size = eps_sum[0] / eps_sum[1];
  if (share.comm) {
    std::int64_t own = 0;
    for (const LocalIndex p : candidate_) own += share.own(p) ? 1 : 0;
    cell_size = agreedCellSize(candidate_x_, count, own, cell_size, share);
  }
  if (count == 0) return 0;
  cells_.build(candidate_x_, count, cell_size, /*enlarge=*/!share.comm);
  // G_p is C_eps times a mass-weighted mean of W over the ball, so it cannot exceed C_eps times
  // the largest W in the cells the ball touches. Points whose bound stays below G_c (most of a
  // target away from the impact) skip the ball sum; the decisions are exactly the same.
  const long cells = cells_.cellCount();
  cell_max_.assign(static_cast<std::size_t>(cells), 0.0);
#pragma omp parallel for schedule(static)
  for (long cell = 0; cell < cells; ++cell)
    for (LocalIndex s = cells_.cellBegin(cell); s < cells_.cellEnd(cell); ++s)
      cell_max_[cell] = std::max(cell_max_[cell], points.strain_energy[candidate_[cells_.indexAt(s)]]);

  // And the largest W around each cell: a ball no wider than a cell lies in the cells around its
  // centre's, so one lookup bounds it.
  cell_bound_.assign(static_cast<std::size_t>(cells), 0.0);
#pragma omp parallel for schedule(static)
  for (long cell = 0; cell < cells; ++cell)
    cells_.forEachCellAround(cell,
                             [&](long near) { cell_bound_[cell] = std::max(cell_bound_[cell], cell_max_[near]); });

  erode_.assign(static_cast<std::size_t>(np), 0);
#pragma omp parallel for schedule(dynamic, 8)
  for (long cell = 0; cell < cells; ++cell)
    for (LocalIndex slot = cells_.cellBegin(cell); slot < cells_.cellEnd(cell); ++slot) {
      const LocalIndex k = cells_.indexAt(slot);
      const LocalIndex p = candidate_[k];
      const int body = points.body[p];
      const double eps = candidate_eps_[k];
      double bound = cell_bound_[cell];
      if (eps > cells_.cellSize()) {
        bound = 0.0;
        cells_.forEachCellNear(points.x[p], eps, [&](long near) { bound = std::max(bound, cell_max_[near]); });
      }
      // The margin covers the rounding of the weighted mean below.
      if (erosionCalibration(eps, nu[body]) * bound * (1.0 + 1e-12) < gc[body]) continue;
      erode_[p] = releaseRate(points, p, eps, nu[body]) >= gc[body];
    }
  LocalIndex failed = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (!erode_[p]) continue;
    // Fractured: no strength and no tension from now on, but the pressure it is under stays
    // (released as debris once it bears none: solver/common/release.hpp).
    const double q = points.viscous_pressure[p];
    const double pressure = std::max(-points.stress[p].trace() / 3.0 - q, 0.0);
    points.fail(p);
    points.stress[p] = -(pressure + q) * Mat3::Identity();
    if (share.own(p)) ++failed;
  }
  return failed;
}

double Eigenerosion::releaseRate(const PointStore& points, LocalIndex p, double eps, double nu) const {
  const int body = points.body[p];
  double mass = 0.0, energy = 0.0;
  cells_.forEachWithin(points.x[p], eps, [&](LocalIndex k, double) {
    const LocalIndex q = candidate_[k];
    if (points.body[q] != body) return;
    mass += points.mass[q];
    energy += points.mass[q] * points.strain_energy[q];
  });
  return erosionCalibration(eps, nu) * energy / mass;
}

}  // namespace kessler
