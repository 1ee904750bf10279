#include "approx/lme.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::lme {

namespace {

constexpr int max_iterations = 60;
// Newton stops when |r| < tol * h, r = sum_a p_a d_a = x - sum_a p_a x_a (the reproduction error),
// or when it stalls at the round-off floor (~1e-13 for a few hundred nodes) below stall_tolerance.
constexpr double residual_tolerance = 1e-12;
constexpr double stall_tolerance = 1e-10;

// log Z(lambda) and the normalised weights p_a, with the exponent shifted for stability.
double logPartition(std::span<const Vec3> d, double beta, const Vec3& lambda, std::span<double> p) {
  double fmax = -std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < d.size(); ++a) {
    p[a] = -beta * d[a].squaredNorm() + lambda.dot(d[a]);
    fmax = std::max(fmax, p[a]);
  }
  double z = 0.0;
  for (double& pa : p) {
    pa = std::exp(pa - fmax);
    z += pa;
  }
  for (double& pa : p) pa /= z;
  return fmax + std::log(z);
}

// Gradient r = sum p_a d_a and Hessian J = sum p_a d_a d_a^T - r r^T of log Z.
void moments(std::span<const Vec3> d, std::span<const double> p, Vec3& r, Mat3& J) {
  r.setZero();
  J.setZero();
  for (std::size_t a = 0; a < d.size(); ++a) {
    r += p[a] * d[a];
    J.noalias() += p[a] * d[a] * d[a].transpose();
  }
  J -= r * r.transpose();
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
  // lambda is made dimensionless by h: its natural scale is beta * h ~ gamma / h.
  double log_z = logPartition(d, beta, lambda, N);
  Vec3 r;
  Mat3 J;
  moments(d, N, r, J);
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
    double trial_log_z = logPartition(d, beta, trial, N);
    if (result.residual > 1e-6) {
      while (trial_log_z > log_z + 1e-4 * t * r.dot(step) && t > 1e-10) {
        t *= 0.5;
        trial = lambda + t * step;
        trial_log_z = logPartition(d, beta, trial, N);
      }
    }
    lambda = trial;
    log_z = trial_log_z;
    moments(d, N, r, J);
  }
  if (result.status != Status::converged) return result;
  // J is symmetric positive definite here (checked in the iteration): invert it once.
  const Mat3 j_inverse = J.inverse();
  for (std::size_t a = 0; a < d.size(); ++a) dN[a] = -N[a] * (j_inverse * d[a]);
  return result;
}

}  // namespace kessler::lme
