// lme-consistency: the LME reproducing identities (Arroyo & Ortiz 2006, §2 and §4) on a
// randomly distorted cloud of nodes: sum N_a = 1, sum N_a x_a = x, sum grad N_a = 0 and
// sum x_a (x) grad N_a = I. The measured value is the largest violation, made dimensionless
// with the nodal spacing h; the reference is 0 with an absolute tolerance of 1e-10.
#include "approx/lme.hpp"
#include "verify/problems.hpp"

#include <algorithm>
#include <random>

namespace kessler::verify {

Outcome lmeConsistency() {
  const double h = 2e-3;  // a millimetre-scale mesh, as in impact problems
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> jitter(-0.35 * h, 0.35 * h);
  std::vector<Vec3> nodes;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = -4; k <= 4; ++k) nodes.emplace_back(i * h + jitter(rng), j * h + jitter(rng), k * h + jitter(rng));

  std::uniform_real_distribution<double> inside(-2.0 * h, 2.0 * h);
  double worst = 0.0;
  int samples = 0;
  for (double gamma : {0.8, 1.8, 4.0}) {
    for (int trial = 0; trial < 200; ++trial, ++samples) {
      const Vec3 x(inside(rng), inside(rng), inside(rng));
      std::vector<Vec3> d;
      for (const Vec3& xa : nodes) d.push_back(x - xa);
      std::vector<double> N(d.size());
      std::vector<Vec3> dN(d.size());
      Vec3 lambda = Vec3::Zero();
      const lme::Result r = lme::shapeFunctions(d, lme::beta(gamma, h), h, lambda, N, dN);
      if (r.status != lme::Status::converged) {
        worst = std::numeric_limits<double>::infinity();
        continue;
      }
      double sum = 0.0;
      Vec3 first = Vec3::Zero(), grad_sum = Vec3::Zero();
      Mat3 grad_first = Mat3::Zero();
      for (std::size_t a = 0; a < nodes.size(); ++a) {
        sum += N[a];
        first += N[a] * nodes[a];
        grad_sum += dN[a];
        grad_first += nodes[a] * dN[a].transpose();
      }
      worst = std::max({worst, std::abs(sum - 1.0), (first - x).norm() / h, grad_sum.norm() * h,
                        (grad_first - Mat3::Identity()).cwiseAbs().maxCoeff()});
    }
  }
  Outcome o;
  o.name = "lme-consistency";
  o.quantity = "max identity violation (dimensionless)";
  o.measured = worst;
  o.reference = 0.0;
  o.tolerance = 1e-10;
  o.comparison = Comparison::absolute;
  o.note = fmt::format("{} nodes jittered by 35% of h, {} points, gamma 0.8/1.8/4", nodes.size(), samples);
  return compare(o);
}

}  // namespace kessler::verify
