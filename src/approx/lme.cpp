#include "approx/lme.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace kessler::lme {

namespace {

constexpr int max_iterations = 60;
// Newton stops when |r| < tol * h, r = sum_a p_a d_a = x - sum_a p_a x_a (the reproduction error),
// or when it stalls at the round-off floor (~1e-13 for a few hundred nodes) below stall_tolerance.
constexpr double residual_tolerance = 1e-12;
constexpr double stall_tolerance = 1e-10;

// One pass over the nodes at a given lambda: the normalised weights p_a, log Z, and its
// gradient r = sum p_a d_a and Hessian J = sum p_a d_a d_a^T - r r^T. The exponent is shifted
// by an upper bound (beta |d|^2 >= 0, so f_a <= |lambda| max|d|) to avoid a separate max pass.
// `base` holds -beta |d_a|^2, which does not change during the iteration.
double evaluate(std::span<const Vec3> d, std::span<const double> base, const Vec3& lambda, double shift,
                std::span<double> p, Vec3& r, Mat3& J) {
  double z = 0.0;
  Vec3 s1 = Vec3::Zero();
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
  for (std::size_t a = 0; a < d.size(); ++a) {
    const Vec3& da = d[a];
    const double w = std::exp(base[a] + lambda.dot(da) - shift);
    p[a] = w;
    z += w;
    s1 += w * da;
    xx += w * da[0] * da[0];
    xy += w * da[0] * da[1];
    xz += w * da[0] * da[2];
    yy += w * da[1] * da[1];
    yz += w * da[1] * da[2];
    zz += w * da[2] * da[2];
  }
  if (!(z > 1e-250)) {
    // The bound was far above every exponent (a huge lambda): shift by the true maximum.
    double fmax = -std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < d.size(); ++a) fmax = std::max(fmax, base[a] + lambda.dot(d[a]));
    return evaluate(d, base, lambda, fmax, p, r, J);
  }
  const double inv = 1.0 / z;
  for (double& pa : p) pa *= inv;
  r = s1 * inv;
  J << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  J = J * inv - r * r.transpose();
  return shift + std::log(z);
}

}  // namespace

double cutoffRadius(double gamma, double h, double tolerance) { return h * std::sqrt(-std::log(tolerance) / gamma); }

const char* describe(Status status) {
  switch (status) {
    case Status::converged: return "converged";
    case Status::not_converged: return "Newton iteration did not converge";
    case Status::outside_hull: return "point outside the convex hull of its nodes";
  }
  return "unknown";
}

Result shapeFunctions(std::span<const Vec3> d, double beta, double h, Vec3& lambda, std::span<double> N,
                      std::span<Vec3> dN) {
  Result result;
  if (!lambda.allFinite()) lambda.setZero();
  // -beta |d_a|^2 once per call (per thread, so the time loop does not allocate after the first steps).
  thread_local std::vector<double> base_storage;
  base_storage.resize(d.size());
  const std::span<const double> base(base_storage.data(), d.size());
  double max_d2 = 0.0;
  for (std::size_t a = 0; a < d.size(); ++a) {
    const double d2 = d[a].squaredNorm();
    max_d2 = std::max(max_d2, d2);
    base_storage[a] = -beta * d2;
  }
  const double max_d = std::sqrt(max_d2);
  Vec3 r;
  Mat3 J;
  double log_z = evaluate(d, base, lambda, lambda.norm() * max_d, N, r, J);
  const double h2 = h * h;
  double previous = std::numeric_limits<double>::infinity();
  for (;;) {
    result.residual = r.norm() / h;
    if (result.residual < residual_tolerance) break;
    if (result.residual < stall_tolerance && result.residual > 0.5 * previous) break;
    previous = result.residual;
    if (result.iterations == max_iterations) {
      result.status = Status::not_converged;
      break;
    }
    ++result.iterations;
    // A singular covariance means the nodes are (nearly) coplanar as seen from the point, and a
    // multiplier that runs away means the point is outside their hull: log Z has no minimum.
    Eigen::LDLT<Mat3> ldlt(J / h2);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() < 1e-14 ||
        lambda.norm() * h > 1e4) {
      result.status = Status::outside_hull;
      break;
    }
    const Vec3 step = -ldlt.solve(r) / h2;
    // Backtracking: accept the first step length that decreases log Z (it is convex). Close to
    // the minimum the decrease (~|r|^2) drops below the round-off of log Z, so there the full
    // Newton step is taken: it converges quadratically.
    double t = 1.0;
    Vec3 trial = lambda + step;
    Vec3 trial_r;
    Mat3 trial_J;
    double trial_log_z = evaluate(d, base, trial, trial.norm() * max_d, N, trial_r, trial_J);
    if (result.residual > 1e-6) {
      while (trial_log_z > log_z + 1e-4 * t * r.dot(step) && t > 1e-10) {
        t *= 0.5;
        trial = lambda + t * step;
        trial_log_z = evaluate(d, base, trial, trial.norm() * max_d, N, trial_r, trial_J);
      }
    }
    lambda = trial;
    log_z = trial_log_z;
    r = trial_r;
    J = trial_J;
  }
  if (result.status != Status::converged) return result;
  // J is symmetric positive definite here (checked in the iteration): invert it once.
  const Mat3 j_inverse = J.inverse();
  for (std::size_t a = 0; a < d.size(); ++a) dN[a] = -N[a] * (j_inverse * d[a]);
  return result;
}

}  // namespace kessler::lme
