#include "material/strength/radial_return.hpp"

#include "core/error.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace kessler::strength {
namespace detail {

TrialState trialState(const Mat3& dF, const Mat3& be, double shear_modulus) {
  TrialState t;
  const Mat3 pushed = dF * be * dF.transpose();
  // Symmetrise so that a rotation dF = R gives exactly R b_e R^T up to rounding in each entry.
  t.be_trial = 0.5 * (pushed + pushed.transpose());
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(t.be_trial);
  t.directions = eigen.eigenvectors();
  const Vec3 lambda = eigen.eigenvalues();
  KESSLER_ASSERT(lambda.minCoeff() > 0.0, "b_e^trial is not positive definite (smallest eigenvalue {})",
                 lambda.minCoeff());
  // Logarithmic principal elastic strains (Simo 1992): eps_i = 1/2 ln lambda_i.
  const Vec3 eps = 0.5 * lambda.array().log().matrix();
  t.volumetric = eps.sum();
  t.J = std::exp(t.volumetric);
  t.deviator = eps - Vec3::Constant(t.volumetric / 3.0);
  t.q_trial = std::sqrt(1.5) * 2.0 * shear_modulus * t.deviator.norm();
  return t;
}

void finishReturn(const TrialState& trial, double shear_modulus, double scale, Mat3& be, ReturnResult& result) {
  const Mat3& n = trial.directions;
  const Vec3 s_principal = (2.0 * shear_modulus * scale / trial.J) * trial.deviator;
  result.deviatoric_stress = n * s_principal.asDiagonal() * n.transpose();
  if (scale == 1.0) {
    be = trial.be_trial;
    return;
  }
  if (scale == 0.0) {  // melted: b_e relaxes to its volumetric part J^(2/3) I
    be = std::exp(2.0 * trial.volumetric / 3.0) * Mat3::Identity();
    return;
  }
  // Plastic flow is isochoric: the volumetric log strain is kept, so det b_e does not change.
  const Vec3 eps = Vec3::Constant(trial.volumetric / 3.0) + scale * trial.deviator;
  const Vec3 stretch2 = (2.0 * eps).array().exp().matrix();
  be = n * stretch2.asDiagonal() * n.transpose();
}

}  // namespace detail

ReturnResult radialReturn(const Yield& yield, const ReturnInput& in, Mat3& be, double& eps_p) {
  return std::visit([&](const auto& law) { return radialReturnWith(law, in, be, eps_p); }, yield);
}

}  // namespace kessler::strength
