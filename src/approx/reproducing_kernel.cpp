#include "approx/reproducing_kernel.hpp"

#include <Eigen/Cholesky>
#include <Eigen/StdVector>

#include <algorithm>
#include <cmath>
#include <vector>

namespace kessler::rk {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

Vec4 basis(const Vec3& offset, double scale) {
  // H(x - x_I), scaled.
  return Vec4(1.0, offset.x() / scale, offset.y() / scale, offset.z() / scale);
}

}  // namespace

double shapeValues(std::span<const Sample> samples, double scale, std::span<double> psi) {
  // Each sample's weight and basis, kept from the moment matrix's pass for the values' pass: they
  // cost a root and four divisions each, most of the work (kept apart from psi, which a refused
  // matrix must leave untouched).
  thread_local std::vector<Vec4, Eigen::aligned_allocator<Vec4>> kept_h;
  thread_local std::vector<double> kept_w;
  kept_h.resize(samples.size());
  kept_w.resize(samples.size());
  Mat4 M = Mat4::Zero();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    const double w = cubicWindow(s.offset.norm() / s.support) * s.volume;
    kept_w[k] = w;
    if (w <= 0.0) continue;
    const Vec4 h = basis(s.offset, scale);
    kept_h[k] = h;
    M.noalias() += w * h * h.transpose();
  }
  // The pivoted LDL^T's pivots: their spread measures the conditioning (a direction that no particle
  // spans, as across a plane of them, leaves a zero pivot, which LDL^T would pass over).
  const Eigen::LDLT<Mat4> ldlt(M);
  const Vec4 d = ldlt.vectorD();
  const double rcond = d.maxCoeff() > 0.0 ? std::max(d.minCoeff(), 0.0) / d.maxCoeff() : 0.0;
  if (ldlt.info() != Eigen::Success || !(rcond >= min_rcond)) return rcond;
  const Vec4 c = ldlt.solve(Vec4::UnitX());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double w = kept_w[k];
    psi[k] = w > 0.0 ? c.dot(kept_h[k]) * w : 0.0;
  }
  return rcond;
}

}  // namespace kessler::rk
