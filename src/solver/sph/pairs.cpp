#include "solver/sph/pairs.hpp"

#include "solver/sph/kernel.hpp"

#include <algorithm>

namespace kessler::sph {

void Pairs::build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count,
                  const std::vector<int>& symmetry_axes) {
  const auto n = static_cast<std::size_t>(count);
  double h_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) h_max = std::max(h_max, h[i]);
  offset.assign(n + 1, 0);
  if (n == 0) return;
  cells_.build(x, count, 2.0 * h_max);
  // The image sets a particle near the planes sees: each non-empty subset of the axes whose planes
  // lie within its reach.
  std::uint8_t axes = 0;
  for (const int a : symmetry_axes) axes |= static_cast<std::uint8_t>(1u << a);
  const auto visit = [&](std::size_t i, auto&& f) {
    const double reach = h[i] + h_max;
    for (std::uint8_t m = 0; m < 8; ++m) {
      if ((m & axes) != m) continue;
      bool near = true;
      for (int a = 0; a < 3; ++a)
        if ((m & (1u << a)) && x[i][a] >= reach) near = false;
      if (!near) continue;
      cells_.forEachWithin(reflect(x[i], m), reach, [&](LocalIndex j, double d2) {
        if (m == 0 && static_cast<std::size_t>(j) == i) return;
        const double support = h[i] + h[static_cast<std::size_t>(j)];
        if (d2 < support * support) f(j, m);
      });
    }
  };
  count_.assign(n, 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    Index c = 0;
    visit(i, [&](LocalIndex, std::uint8_t) { ++c; });
    count_[i] = c;
  }
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + count_[i];
  const auto total = static_cast<std::size_t>(offset[n]);
  other.resize(total);
  mirror.resize(total);
  active.resize(total);
  gradient.resize(total);
  kernel.resize(total);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    auto e = static_cast<std::size_t>(offset[i]);
    visit(i, [&](LocalIndex j, std::uint8_t m) {
      const Vec3 d = x[i] - reflect(x[static_cast<std::size_t>(j)], m);
      const double r = d.norm(), h_ij = 0.5 * (h[i] + h[static_cast<std::size_t>(j)]);
      other[e] = j;
      mirror[e] = m;
      kernel[e] = CubicSpline::value(r, h_ij);
      gradient[e] = r > 0.0 ? Vec3(CubicSpline::slope(r, h_ij) / r * d) : Vec3::Zero();
      ++e;
    });
  }
}

}  // namespace kessler::sph
