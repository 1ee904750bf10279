#pragma once
// The cubic B-spline kernel in three dimensions (Monaghan & Lattanzio, A&A 149:135, 1985; Monaghan,
// Rep. Prog. Phys. 68:1703, 2005), with support 2h: q = r / h,
//   W = 1/(pi h^3) (1 - 3/2 q^2 + 3/4 q^3)   for q < 1,
//   W = 1/(pi h^3) (2 - q)^3 / 4             for 1 <= q < 2,   0 beyond.
#include <Eigen/Core>

#include <algorithm>
#include <numbers>

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace kessler::sph {

struct CubicSpline {
  static constexpr double support = 2.0;  // in units of h

  static double value(double r, double h) {
    const double q = r / h, sigma = 1.0 / (std::numbers::pi * h * h * h);
    if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) return sigma * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return 0.0;
  }
  // dW/dr (never positive).
  static double slope(double r, double h) {
    const double q = r / h, sigma = 1.0 / (std::numbers::pi * h * h * h * h);
    if (q < 1.0) return sigma * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) return -sigma * 0.75 * (2.0 - q) * (2.0 - q);
    return 0.0;
  }
  // (dW/dr) / r, the factor of d in grad W(d) = (dW/dr) d / r (0 at and beyond 2h): the pair loop's
  // form, with the reciprocals of h and r taken together in one packed division where slope(r, h) / r
  // takes three. Within q < 1 it needs no 1/r, so at r = 0 it is finite (and d = 0 makes the gradient
  // 0); the outer piece, which r = 0 would make infinite, is then not the one selected.
  static double slopeOverDistance(double r, double h) {
    const Eigen::Array2d inverse = Eigen::Array2d(h, r).inverse();
    const double inv_h = inverse[0], inv_r = inverse[1], q = r * inv_h;
    const double sigma = inv_h * inv_h * inv_h * inv_h * std::numbers::inv_pi, t = std::max(2.0 - q, 0.0);
    const double inner = sigma * inv_h * (-3.0 + 2.25 * q), outer = -0.75 * sigma * t * t * inv_r;
#if defined(__AVX__)
    // (A select, not a jump: the pairs come in no order of their distance.)
    const __m128d within = _mm_cmplt_sd(_mm_set_sd(q), _mm_set_sd(1.0));
    return _mm_cvtsd_f64(_mm_blendv_pd(_mm_set_sd(outer), _mm_set_sd(inner), within));
#else
    return q < 1.0 ? inner : outer;
#endif
  }
};

}  // namespace kessler::sph
