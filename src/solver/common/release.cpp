#include "solver/common/release.hpp"

#include <algorithm>
#include <limits>

namespace kessler {

LocalIndex DebrisRelease::apply(ParticleState& model) {
  PointStore& points = model.points;
  const LocalIndex np = points.owned;
  releasing_.assign(static_cast<std::size_t>(np), 0);
  LocalIndex count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (LocalIndex p = 0; p < np; ++p)
    if (points.failed(p) && points.stress[p].trace() == 0.0) {
      releasing_[p] = 1;
      ++count;
    }
  if (count == 0) return 0;
  collect(points);
  for (LocalIndex p = 0; p < np; ++p) {
    if (!releasing_[p]) continue;
    release(points, p, erosion_radius_ * points.spacing(p));
    points.carrier[p] = -1;
    points.stress[p].setZero();
    points.viscous_pressure[p] = 0.0;
  }
  return count;
}

void DebrisRelease::collect(const PointStore& points) {
  const LocalIndex np = points.owned;
  body_releases_.assign(static_cast<std::size_t>(*std::max_element(points.body.begin(), points.body.begin() + np) + 1),
                        0);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double reach = 0.0, eps_sum = 0.0;
  LocalIndex releasing = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (!releasing_[p]) continue;
    const double eps = erosion_radius_ * points.spacing(p);
    lo = lo.cwiseMin(points.x[p]);
    hi = hi.cwiseMax(points.x[p]);
    reach = std::max(reach, eps);
    eps_sum += eps;
    ++releasing;
    body_releases_[static_cast<std::size_t>(points.body[p])] = 1;
  }
  lo.array() -= reach;
  hi.array() += reach;
  body_x_.clear();
  body_points_.clear();
  debris_x_.clear();
  debris_.clear();
  for (LocalIndex q = 0; q < np; ++q) {
    const Vec3& x = points.x[q];
    if (!body_releases_[static_cast<std::size_t>(points.body[q])] || (x.array() < lo.array()).any() ||
        (x.array() > hi.array()).any())
      continue;
    if (points.debris(q)) {
      debris_x_.push_back(x);
      debris_.push_back(q);
    } else {
      body_x_.push_back(x);
      body_points_.push_back(q);
    }
  }
  const double cell = eps_sum / releasing;
  body_cells_.build(body_x_, static_cast<LocalIndex>(body_points_.size()), cell);
  if (!debris_.empty()) debris_cells_.build(debris_x_, static_cast<LocalIndex>(debris_.size()), cell);
}

void DebrisRelease::release(PointStore& points, LocalIndex p, double eps) const {
  const int body = points.body[p];
  struct Sum {
    double mass = 0.0;
    Vec3 momentum = Vec3::Zero();
  };
  auto add = [&](Sum& sum, LocalIndex q, double sign = 1.0) {
    sum.mass += sign * points.mass[q];
    sum.momentum += sign * points.mass[q] * points.v[q];
  };
  // f(q) for the points of p's body in its ball: those still in the body (before this call), or
  // its earlier debris.
  auto forBall = [&](const CellList& cells, const std::vector<LocalIndex>& index, auto&& f) {
    cells.forEachWithin(points.x[p], eps, [&](LocalIndex k, double) {
      if (points.body[index[k]] == body) f(index[k]);
    });
  };
  Sum ball, left;  // the whole ball, and its points that stay in the body
  forBall(body_cells_, body_points_, [&](LocalIndex q) {
    add(ball, q);
    if (!releasing_[q]) add(left, q);
  });
  // Who takes the difference: the points that stay; if none does (the last of a region released
  // at once), the ball's other points, released now or debris already, with the debris in the mean.
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
  // the release conserves the total energy as well as the momentum.
  const double heat = 0.5 * points.mass[p] * (points.v[p].squaredNorm() - mean.squaredNorm()) -
                      receivers.momentum.dot(dv) - 0.5 * receivers.mass * dv.squaredNorm();
  points.energy[p] += heat / points.mass[p];
  points.v[p] = mean;
  forBall(body_cells_, body_points_, [&](LocalIndex q) {
    if (lone ? q != p : !releasing_[q]) points.v[q] += dv;
  });
  if (lone && !debris_.empty()) forBall(debris_cells_, debris_, [&](LocalIndex q) { points.v[q] += dv; });
}

}  // namespace kessler
