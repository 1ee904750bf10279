#include "approx/reproducing_kernel.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

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
  Mat4 M = Mat4::Zero();
  for (const Sample& s : samples) {
    const double w = cubicWindow(s.offset.norm() / s.support) * s.volume;
    if (w <= 0.0) continue;
    const Vec4 h = basis(s.offset, scale);
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
    const Sample& s = samples[k];
    const double w = cubicWindow(s.offset.norm() / s.support) * s.volume;
    psi[k] = w > 0.0 ? c.dot(basis(s.offset, scale)) * w : 0.0;
  }
  return rcond;
}

}  // namespace kessler::rk
