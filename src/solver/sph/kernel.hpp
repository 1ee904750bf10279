#pragma once
// The cubic B-spline kernel in three dimensions (Monaghan & Lattanzio, A&A 149:135, 1985; Monaghan,
// Rep. Prog. Phys. 68:1703, 2005), with support 2h: q = r / h,
//   W = 1/(pi h^3) (1 - 3/2 q^2 + 3/4 q^3)   for q < 1,
//   W = 1/(pi h^3) (2 - q)^3 / 4             for 1 <= q < 2,   0 beyond.
#include <numbers>

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
};

}  // namespace kessler::sph
