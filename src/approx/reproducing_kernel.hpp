#pragma once
// Reproducing kernel shape functions with a linear basis (Liu, Jun & Zhang, IJNMF 20:1081, 1995;
// Chen, Pan, Wu & Liu, CMAME 139:195, 1996; docs/theory.md §12):
//   Psi_I(x) = H^T(0) M^-1(x) H(x - x_I) phi_a(x - x_I) V_I,
//   M(x) = sum_I H(x - x_I) H^T(x - x_I) phi_a(x - x_I) V_I,
// with H(y) = [1, y / s] (s a length that scales the basis, so that M is well conditioned) and phi_a
// the cubic B-spline window of support radius a. They reproduce every linear field exactly:
// sum_I Psi_I(x) = 1 and sum_I Psi_I(x) x_I = x, on any particle set that gives a regular M (at
// least four particles, not coplanar, within reach of x).
#include "core/types.hpp"

#include <span>

namespace kessler::rk {

// The cubic B-spline window of z = r / a (Chen et al. 1996): 0 for z >= 1.
inline double cubicWindow(double z) {
  if (z >= 1.0) return 0.0;
  if (z <= 0.5) return 2.0 / 3.0 - 4.0 * z * z + 4.0 * z * z * z;
  const double w = 1.0 - z;
  return 4.0 / 3.0 * w * w * w;
}

// One particle seen from the evaluation point x.
struct Sample {
  Vec3 offset;     // x - x_I, m
  double support;  // a_I, m
  double volume;   // V_I, m^3
};

// The smallest over the largest pivot of the scaled moment matrix's LDL^T (an estimate of its
// reciprocal condition number) below which it is refused as singular.
inline constexpr double min_rcond = 1e-10;

// Fills psi[k] = Psi of samples[k] at x, with `scale` the basis length s. Returns the smallest over
// the largest pivot of the scaled moment matrix; below min_rcond (too few particles in reach of x, or
// all of them in a plane) psi is left untouched and the caller reports where.
double shapeValues(std::span<const Sample> samples, double scale, std::span<double> psi);

}  // namespace kessler::rk
