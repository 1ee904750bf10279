#include "approx/lme.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/StdVector>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

namespace kessler::lme {

namespace {

constexpr int max_iterations = 60;
// Newton stops when |r| < tol * h, r = sum_a p_a d_a = x - sum_a p_a x_a (the reproduction error),
// or when it stalls at the round-off floor (~1e-13 for a few hundred nodes) below stall_tolerance.
constexpr double residual_tolerance = 1e-12;
constexpr double stall_tolerance = 1e-10;

// The offsets d_a = x - x_a one coordinate per array and -beta |d_a|^2, set once per solve, so
// that a pass over the nodes runs four (AVX2) or two exponentials at a time (Eigen's packet exp).
struct Offsets {
  // Every array starts on a maximally aligned address: Eigen's vectorised sums peel elements up to
  // the first aligned one, so an address-dependent start would make the summation order, and the
  // last bits of the result, depend on which thread's buffer a point lands in.
  using Array = Eigen::Map<Eigen::ArrayXd, Eigen::AlignedMax>;
  static constexpr Eigen::Index pad = 8;                          // doubles: 64 bytes
  std::vector<double, Eigen::aligned_allocator<double>> storage;  // only grows: no allocation per call
  Eigen::Index n = 0;
  Array x{nullptr, 0}, y{nullptr, 0}, z{nullptr, 0}, base{nullptr, 0}, w{nullptr, 0};
  void set(std::span<const Vec3> d, double beta) {
    n = static_cast<Eigen::Index>(d.size());
    const Eigen::Index stride = (n + pad - 1) / pad * pad;
    storage.resize(static_cast<std::size_t>(5 * stride));
    double* data = storage.data();
    for (Array* a : {&x, &y, &z, &base, &w}) {
      new (a) Array(data, n);  // Eigen's documented way to re-point a Map
      data += stride;
    }
    for (Eigen::Index a = 0; a < n; ++a) {
      x[a] = d[static_cast<std::size_t>(a)][0];
      y[a] = d[static_cast<std::size_t>(a)][1];
      z[a] = d[static_cast<std::size_t>(a)][2];
    }
    base = -beta * (x.square() + y.square() + z.square());
  }
};

// One pass over the nodes at a given lambda: the normalised weights p_a, log Z, and its
// gradient r = sum p_a d_a and Hessian J = sum p_a d_a d_a^T - r r^T. The exponent is shifted
// by an upper bound (beta |d|^2 >= 0, so f_a <= |lambda| max|d|) to avoid a separate max pass.
double evaluate(Offsets& o, const Vec3& lambda, double shift, std::span<double> p, Vec3& r, Mat3& J) {
  o.w = (o.base + lambda[0] * o.x + lambda[1] * o.y + lambda[2] * o.z - shift).exp();
  const double z = o.w.sum();
  if (!(z > 1e-250)) {
    // The bound was far above every exponent (a huge lambda): shift by the true maximum.
    const double fmax = (o.base + lambda[0] * o.x + lambda[1] * o.y + lambda[2] * o.z).maxCoeff();
    return evaluate(o, lambda, fmax, p, r, J);
  }
  const double inv = 1.0 / z;
  // Fused expressions: no temporaries, each sum one vectorised pass over the few dozen nodes.
  r = Vec3((o.w * o.x).sum(), (o.w * o.y).sum(), (o.w * o.z).sum()) * inv;
  const double xx = (o.w * o.x.square()).sum(), xy = (o.w * o.x * o.y).sum(), xz = (o.w * o.x * o.z).sum();
  const double yy = (o.w * o.y.square()).sum(), yz = (o.w * o.y * o.z).sum(), zz = (o.w * o.z.square()).sum();
  J << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  J = J * inv - r * r.transpose();
  Eigen::Map<Eigen::ArrayXd>(p.data(), static_cast<Eigen::Index>(p.size())) = o.w * inv;
  return shift + std::log(z);
}

}  // namespace

double cutoffRadius(double gamma, double h, double tolerance) {
  return h * std::sqrt(-std::log(tolerance) / gamma);
}

const char* describe(Status status) {
  switch (status) {
    case Status::converged:
      return "converged";
    case Status::not_converged:
      return "Newton iteration did not converge";
    case Status::outside_hull:
      return "point outside the convex hull of its nodes";
    case Status::ill_conditioned:
      return "nodes nearly coplanar as seen from the point (ill-conditioned gradients)";
    case Status::no_nodes:
      return "no nodes within the point's support";
    case Status::not_finite:
      return "the point or one of its nodes has a non-finite position";
  }
  return "unknown";
}

Result shapeFunctions(std::span<const Vec3> d, double beta, double h, Vec3& lambda, std::span<double> N,
                      std::span<Vec3> dN, bool check_conditioning) {
  Result result;
  // Refused before the solve, which would otherwise never end: with no offsets, or a non-finite one,
  // the sum Z is zero or NaN and the shift that guards it against underflow finds no maximum.
  if (d.empty()) {
    result.status = Status::no_nodes;
    return result;
  }
  for (const Vec3& da : d)
    if (!da.allFinite()) {
      result.status = Status::not_finite;
      return result;
    }
  if (!lambda.allFinite()) lambda.setZero();
  // The offsets and -beta |d_a|^2 once per call (per thread, so the time loop does not allocate
  // after the first steps).
  thread_local Offsets offsets;
  offsets.set(d, beta);
  double max_d2 = 0.0;
  for (const Vec3& da : d) max_d2 = std::max(max_d2, da.squaredNorm());
  const double max_d = std::sqrt(max_d2);
  Vec3 r;
  Mat3 J;
  double log_z = evaluate(offsets, lambda, lambda.norm() * max_d, N, r, J);
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
    double trial_log_z = evaluate(offsets, trial, trial.norm() * max_d, N, trial_r, trial_J);
    if (result.residual > 1e-6) {
      while (trial_log_z > log_z + 1e-4 * t * r.dot(step) && t > 1e-10) {
        t *= 0.5;
        trial = lambda + t * step;
        trial_log_z = evaluate(offsets, trial, trial.norm() * max_d, N, trial_r, trial_J);
      }
    }
    lambda = trial;
    log_z = trial_log_z;
    r = trial_r;
    J = trial_J;
  }
  if (result.status != Status::converged) return result;
  if (check_conditioning) {
    // The smallest eigenvalue of J / h^2 reaches min_covariance if and only if J / h^2 - min_covariance I
    // is positive semi-definite: its leading principal minors (Sylvester), without an eigensolver.
    const Mat3 b = J / h2 - min_covariance * Mat3::Identity();
    const double minor2 = b(0, 0) * b(1, 1) - b(0, 1) * b(0, 1);
    if (!(b(0, 0) > 0.0 && minor2 > 0.0 && b.determinant() > 0.0)) {
      result.status = Status::ill_conditioned;
      Eigen::SelfAdjointEigenSolver<Mat3> eigen;
      eigen.computeDirect(J / h2, Eigen::EigenvaluesOnly);
      result.covariance = eigen.eigenvalues()[0];
    }
  }
  // J is symmetric positive definite here (checked in the iteration): invert it once.
  // grad N_a = -N_a J^-1 d_a, one component at a time over all nodes (vectorised), then interleaved.
  // The solve is done, so its arrays hold the components: base and w the first two, and x the
  // third, computed last because it reads x.
  const Mat3 j_inverse = J.inverse();
  const Eigen::Map<const Eigen::ArrayXd> n_a(N.data(), offsets.n);
  Offsets& o = offsets;
  Offsets::Array &grad_x = o.base, &grad_y = o.w, &grad_z = o.x;
  grad_x = -n_a * (j_inverse(0, 0) * o.x + j_inverse(0, 1) * o.y + j_inverse(0, 2) * o.z);
  grad_y = -n_a * (j_inverse(1, 0) * o.x + j_inverse(1, 1) * o.y + j_inverse(1, 2) * o.z);
  grad_z = -n_a * (j_inverse(2, 0) * o.x + j_inverse(2, 1) * o.y + j_inverse(2, 2) * o.z);
  for (Eigen::Index a = 0; a < o.n; ++a) dN[static_cast<std::size_t>(a)] = Vec3(grad_x[a], grad_y[a], grad_z[a]);
  return result;
}

}  // namespace kessler::lme
