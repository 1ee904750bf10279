#pragma once
// The stable (CFL) time step over material points (docs/theory.md §4 step 7).
#include "core/error.hpp"
#include "particles/store.hpp"
#include "solver/common/own_sums.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace kessler {

// The square root of the smallest eigenvalue of a symmetric positive semi-definite matrix (closed
// form).
double smallestRootEigenvalue(const Mat3& symmetric);
// The smallest principal stretch of F (the square root of the smallest eigenvalue of F^T F): a
// point's length scale is its reference spacing times it (plastic flow keeps the volume, so
// h0 J^(1/3) would not shrink, while it can flatten the material to a fraction of its spacing).
double smallestStretch(const Mat3& F);
// The largest principal stretch of F (the square root of the largest eigenvalue of F^T F).
double largestStretch(const Mat3& F);

// cfl times the smallest, over the points that are not debris, of length(p) / c_p (where c_p > 0)
// and 1 / (3 |volume_rate_p|), and of `bound` (the limits of other parts of the step, such as
// debris contact's; infinity if none). The volume bound keeps any point from changing its volume
// by more than cfl/3 (10% at the default) in a step, |div v| dt <= cfl/3, as LULESH's dvovmax
// bounds it: the bound that sets the step where there is no sound speed (a cold gas, p = 0);
// elsewhere the viscosity's share of the signal speed makes it redundant. length(p): the method's
// length scale of point p. With `share`, over a rank's own points and every rank. The minimum is exact, so any thread
// count gives the same step. Throws if nothing bounds the step.
template <typename Length>
double stableStep(const PointStore& points, std::span<const double> volume_rate, double bound, double cfl,
                  Length&& length, const Share& share = {}) {
  double dt = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p) || !share.own(p)) continue;
    if (points.sound_speed[p] > 0.0) dt = std::min(dt, length(p) / points.sound_speed[p]);
    if (volume_rate[p] != 0.0) dt = std::min(dt, 1.0 / (3.0 * std::abs(volume_rate[p])));
  }
  dt = share.min(std::min(dt, bound));
  // Nothing bounded the step if dt is still infinite, or the largest double: an OpenMP min
  // reduction starts each thread's copy there, not at infinity, under LLVM's libomp.
  KESSLER_VERIFY(std::isfinite(dt) && dt > 0.0 && dt < std::numeric_limits<double>::max(),
                 "no stable time step: every point is debris or at rest without a sound speed, or the model is empty");
  return cfl * dt;
}

}  // namespace kessler
