#include "solver/otm/eigenerosion.hpp"

#include <algorithm>
#include <limits>

namespace kessler::otm {

double erosionCalibration(double eps, double nu) {
  return 64.0 * eps / (3.0 * (5.0 - 3.0 * nu));
}

bool Eigenerosion::active(const Model& model) const {
  return std::any_of(model.materials.begin(), model.materials.end(),
                     [](const MaterialPtr& m) { return m->fractureEnergy() > 0.0; });
}

LocalIndex Eigenerosion::apply(Model& model) {
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
  double eps_sum = 0.0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (points.eroded[p] || gc[points.body[p]] <= 0.0) continue;
    candidate_x_.push_back(points.x[p]);
    candidate_.push_back(p);
    eps_sum += settings_.erosion_radius * points.spacing(p);
  }
  const auto count = static_cast<LocalIndex>(candidate_.size());
  if (count == 0) return 0;
  cells_.build(candidate_x_, count, eps_sum / count);
  // G_p is C_eps times a mass-weighted mean of W over the ball, so it cannot exceed C_eps times
  // the largest W in the cells the ball touches. Points whose bound stays below G_c (most of a
  // target away from the impact) skip the ball sum; the decisions are exactly the same.
  const long cells = cells_.cellCount();
  cell_max_.assign(static_cast<std::size_t>(cells), 0.0);
#pragma omp parallel for schedule(static)
  for (long cell = 0; cell < cells; ++cell)
    for (LocalIndex s = cells_.cellBegin(cell); s < cells_.cellEnd(cell); ++s)
      cell_max_[cell] = std::max(cell_max_[cell], points.strain_energy[candidate_[cells_.indexAt(s)]]);

  erode_.assign(static_cast<std::size_t>(np), 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (LocalIndex c = 0; c < count; ++c) {
    const LocalIndex p = candidate_[c];
    const int body = points.body[p];
    const double eps = settings_.erosion_radius * points.spacing(p);
    double bound = 0.0;
    cells_.forEachCellNear(points.x[p], eps, [&](long cell) { bound = std::max(bound, cell_max_[cell]); });
    // The margin covers the rounding of the weighted mean below.
    if (erosionCalibration(eps, nu[body]) * bound * (1.0 + 1e-12) < gc[body]) continue;
    double mass = 0.0, energy = 0.0;
    cells_.forEachWithin(points.x[p], eps, [&](LocalIndex k, double) {
      const LocalIndex q = candidate_[k];
      if (points.body[q] != body) return;
      mass += points.mass[q];
      energy += points.mass[q] * points.strain_energy[q];
    });
    const double release_rate = erosionCalibration(eps, nu[body]) * energy / mass;
    if (release_rate >= gc[body]) erode_[p] = 1;
  }
  collectDebris(points, gc);
  LocalIndex eroded = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (!erode_[p]) continue;
    releaseDebris(points, p, settings_.erosion_radius * points.spacing(p));
    points.eroded[p] = 1;
    points.stress[p].setZero();
    points.viscous_pressure[p] = 0.0;
    ++eroded;
  }
  return eroded;
}

void Eigenerosion::collectDebris(const PointStore& points, const std::vector<double>& gc) {
  debris_x_.clear();
  debris_.clear();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double reach = 0.0, eps_sum = 0.0;
  LocalIndex eroding = 0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!erode_[p]) continue;
    const double eps = settings_.erosion_radius * points.spacing(p);
    lo = lo.cwiseMin(points.x[p]);
    hi = hi.cwiseMax(points.x[p]);
    reach = std::max(reach, eps);
    eps_sum += eps;
    ++eroding;
  }
  if (eroding == 0) return;
  lo.array() -= reach;
  hi.array() += reach;
  for (LocalIndex q = 0; q < points.owned; ++q) {
    const Vec3& x = points.x[q];
    if (!points.eroded[q] || gc[points.body[q]] <= 0.0 || (x.array() < lo.array()).any() ||
        (x.array() > hi.array()).any())
      continue;
    debris_x_.push_back(x);
    debris_.push_back(q);
  }
  if (!debris_.empty()) debris_cells_.build(debris_x_, static_cast<LocalIndex>(debris_.size()), eps_sum / eroding);
}

// Serial, in point order, so the result does not depend on the thread count.
void Eigenerosion::releaseDebris(PointStore& points, LocalIndex p, double eps) const {
  const int body = points.body[p];
  struct Sum {
    double mass = 0.0;
    Vec3 momentum = Vec3::Zero();
  };
  auto add = [&](Sum& sum, LocalIndex q, double sign = 1.0) {
    sum.mass += sign * points.mass[q];
    sum.momentum += sign * points.mass[q] * points.v[q];
  };
  // f(q) for the points of p's body in its ball: the candidates (intact before this step), or the
  // debris near the eroding points.
  auto forBall = [&](const CellList& cells, const std::vector<LocalIndex>& index, auto&& f) {
    cells.forEachWithin(points.x[p], eps, [&](LocalIndex k, double) {
      if (points.body[index[k]] == body) f(index[k]);
    });
  };
  Sum ball, left;  // the whole ball, and its points that stay intact
  forBall(cells_, candidate_, [&](LocalIndex q) {
    add(ball, q);
    if (!erode_[q]) add(left, q);
  });
  // Who takes the difference: the points that stay intact; if none does (the last of an eroding
  // region), the ball's other points, eroding now or debris already, with the debris in the mean.
  const bool lone = left.mass <= 0.0;
  Sum receivers = left;
  if (lone) {
    if (!debris_.empty()) forBall(debris_cells_, debris_, [&](LocalIndex q) { add(ball, q); });
    receivers = ball;
    add(receivers, p, -1.0);
    if (!(receivers.mass > 1e-12 * points.mass[p])) return;  // nothing near: keep v_p
  }
  const Vec3 mean = ball.momentum / ball.mass;
  const Vec3 dv = points.mass[p] * (points.v[p] - mean) / receivers.mass;
  // The kinetic energy this exchange takes (or gives) stays in the debris as internal energy, so
  // erosion conserves the total energy as well as the momentum.
  const double heat = 0.5 * points.mass[p] * (points.v[p].squaredNorm() - mean.squaredNorm()) -
                      receivers.momentum.dot(dv) - 0.5 * receivers.mass * dv.squaredNorm();
  points.energy[p] += heat / points.mass[p];
  points.v[p] = mean;
  forBall(cells_, candidate_, [&](LocalIndex q) {
    if (lone ? q != p : !erode_[q]) points.v[q] += dv;
  });
  if (lone && !debris_.empty()) forBall(debris_cells_, debris_, [&](LocalIndex q) { points.v[q] += dv; });
}

}  // namespace kessler::otm
