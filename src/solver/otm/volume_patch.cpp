#include "solver/otm/volume_patch.hpp"

#include "core/exact_sum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::otm {

double stabilisationPressure(const PointStore& points, LocalIndex p, double alpha, double tensile_limit) {
  const double c = points.sound_speed[p];
  const double pressure = -alpha * points.density(p) * c * c * points.volume_defect[p];
  // Failed material bears compression only (docs/theory.md §8): its stabilisation too.
  if (points.broken[p]) return std::max(pressure, 0.0);
  if (!(tensile_limit < std::numeric_limits<double>::infinity())) return pressure;
  const double own = -points.stress[p].trace() / 3.0;  // the point's pressure, its viscosity included
  return std::max(pressure, -(own + tensile_limit));
}

double VolumePatch::pressure(const PointStore& points, LocalIndex p, double alpha) const {
  const auto body = static_cast<std::size_t>(points.body[p]);
  return stabilisationPressure(points, p, alpha,
                               body < limits_.size() ? limits_[body] : std::numeric_limits<double>::infinity());
}

// The defect relaxes as exp(-t c / (k h)), over k transits of a wave across the point's spacing h
// (docs/theory.md §4): the stabilisation resists a mode that builds up over many steps, not a
// volume change the patch has kept for k transits. The energy the relaxed defect stored, -S V d / 2
// before less after, is released (the compatible energy update makes it the point's heat).
double VolumePatch::relax(PointStore& points, LocalIndex p, double alpha, double dt_per_transits) const {
  double& defect = points.volume_defect[p];
  const double h = points.spacing(p);
  if (defect == 0.0 || !(h > 0.0)) return 0.0;
  const double before = -0.5 * pressure(points, p, alpha) * points.volume[p] * defect;
  defect *= std::exp(-dt_per_transits * points.sound_speed[p] / h);
  const double after = -0.5 * pressure(points, p, alpha) * points.volume[p] * defect;
  return before - after;
}

double VolumePatch::apply(const Connectivity& conn, LocalIndex owned_nodes, bool averaging, double alpha,
                          double relaxation, double dt, PointStore& points, std::vector<double>& j, const Share& share,
                          const std::function<void(NodeMeans&)>& refresh_nodes) {
  work_.assign(static_cast<std::size_t>(points.owned), 0.0);
  defect_step_.assign(static_cast<std::size_t>(points.owned), 0.0);
  signal2_.assign(static_cast<std::size_t>(points.owned), 0.0);
  rebook_ = averaging && alpha > 0.0 && relaxation > 0.0;
  node_.resize(static_cast<std::size_t>(owned_nodes));
  record_.resize(static_cast<std::size_t>(points.owned));
#pragma omp parallel
  {
    // The weights packed per point first, so that the gather reads one record per entry.
#pragma omp for schedule(static)
    for (LocalIndex p = 0; p < points.owned; ++p) {
      const double m = points.mass[p];
      // Debris has no volume change of its own (and `j` holds nothing for it).
      record_[p] = points.debris(p) ? std::array<double, 3>{0.0, 0.0, 0.0}
                                    : std::array<double, 3>{m, m * std::log(j[p]), m * (points.dF[p].trace() - 3.0)};
    }
#pragma omp for schedule(static)
    for (LocalIndex a = 0; a < owned_nodes; ++a) {
      double m = 0.0, log_j = 0.0, trace = 0.0;
      for (Index k = conn.node_offset[a]; k < conn.node_offset[a + 1]; ++k) {
        const Connectivity::NodeSlot slot = conn.node_slot[k];
        const double N = conn.N[slot.entry];
        const std::array<double, 3>& w = record_[slot.point];
        m += N * w[0];
        log_j += N * w[1];
        trace += N * w[2];
      }
      node_[a] = m > 0.0 ? std::array<double, 2>{log_j / m, trace / m} : std::array<double, 2>{0.0, 0.0};
    }
  }
  if (refresh_nodes) refresh_nodes(node_);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    points.viscosity_limiter[p] = 0.0;
    if (points.debris(p)) continue;
    // Compression of the point and of the nodal means around it, as logarithmic volume changes: a
    // linear velocity field (uniform or linearly varying compression) gives ratios near 1 and no
    // viscosity; a shock, where the point compresses far more than the patch beside it, small ones.
    const double own = std::log(j[p]);
    double weight = 0.0, average = 0.0, average_trace = 0.0, mean_ratio = 0.0;
    double min_ratio = std::numeric_limits<double>::infinity();
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
      const double N = conn.N[e];
      if (N <= 0.0) continue;  // hidden behind a crack (docs/theory.md §8)
      const double log_j_a = node_[conn.node[e]][0];
      weight += N;
      average += N * log_j_a;
      average_trace += N * node_[conn.node[e]][1];
      if (own < 0.0) {
        const double ratio = log_j_a / own;
        mean_ratio += N * ratio;
        min_ratio = std::min(min_ratio, ratio);
      }
    }
    if (!(weight > 0.0)) continue;
    if (own < 0.0) points.viscosity_limiter[p] = christensenLimiter(mean_ratio / weight, min_ratio);
    average /= weight;
    average_trace /= weight;
    if (!averaging) continue;
    // What the average takes away is kept: the stabilisation pressure resists it (docs/theory.md §4).
    // The defect grows by the part of the step's volume strain tr(dF - I) that the average leaves
    // out. The stabilisation's work on it is stored energy, booked with the mean of the pressures
    // before and after the step, -(S_old V_old + S_new V_new)/2 d(defect), as the leapfrog's kinetic
    // energy sees it; here the first half, closeStep() the second.
    const double defect_step = points.dF[p].trace() - 3.0 - average_trace;
    defect_step_[p] = defect_step;
    // Intact points only: a failed point's compression-only stabilisation keeps the debris at a
    // contact from overcompressing (docs/theory.md §4), and relaxed it let them heat and overshoot.
    if (alpha > 0.0 && relaxation > 0.0 && !points.broken[p]) work_[p] = -relax(points, p, alpha, dt / relaxation);
    if (alpha > 0.0) work_[p] += -0.5 * pressure(points, p, alpha) * points.volume[p] * defect_step;
    points.volume_defect[p] += defect_step;
    signal2_[p] = points.sound_speed[p] * points.sound_speed[p];
    points.dF[p] *= std::exp((average - own) / 3.0);
    j[p] = points.dF[p].determinant();
  }
  return ownSum(share, points.owned, [&](LocalIndex p) { return work_[p]; });
}

double VolumePatch::closeStep(const PointStore& points, double alpha, const Share& share) {
  if (!(alpha > 0.0) || defect_step_.size() != static_cast<std::size_t>(points.owned)) return 0.0;
  return ownSum(share, points.owned, [&](LocalIndex p) {
    if (points.debris(p)) return 0.0;
    const double S = pressure(points, p, alpha);
    double second = -0.5 * S * points.volume[p] * defect_step_[p];
    // The material update changed the stiffness alpha m c^2 under the defect it stores: the stored
    // energy -S V d / 2 = alpha m c^2 d^2 / 2 changes by alpha m d^2 (c_new^2 - c_old^2) / 2, booked
    // as stored and so taken from the point's heat (the compatible energy update). Unbooked, a point
    // heated at a fixed defect gives back more than it stored (docs/theory.md §4). Only with the
    // relaxation: alone it takes hugoniot-3d from P -2.79% to -3.00% (docs/validation.md).
    const double d = points.volume_defect[p];
    // Not for a point its tensile limit holds: its stored energy, -S V d / 2, follows its own
    // pressure there, not c^2.
    if (rebook_ && signal2_[p] > 0.0 && !points.broken[p] && S == stabilisationPressure(points, p, alpha)) {
      const double c = points.sound_speed[p];
      second += 0.5 * alpha * points.mass[p] * d * d * (c * c - signal2_[p]);
    }
    work_[p] += second;
    return second;
  });
}

void VolumePatch::stabilisationPressures(const PointStore& points, double alpha, std::vector<double>& s) const {
  s.resize(static_cast<std::size_t>(points.owned));
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p)
    s[p] = alpha > 0.0 && !points.debris(p) ? pressure(points, p, alpha) : 0.0;
}

}  // namespace kessler::otm
