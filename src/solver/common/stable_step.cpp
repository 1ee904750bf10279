#include "solver/common/stable_step.hpp"

#include <Eigen/Eigenvalues>

namespace kessler {

double smallestRootEigenvalue(const Mat3& symmetric) {
  Eigen::SelfAdjointEigenSolver<Mat3> eigen;
  eigen.computeDirect(symmetric, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eigen.eigenvalues()[0], 0.0));
}

double smallestStretch(const Mat3& F) {
  return smallestRootEigenvalue(F.transpose() * F);
}

double largestStretch(const Mat3& F) {
  Eigen::SelfAdjointEigenSolver<Mat3> eigen;
  eigen.computeDirect(F.transpose() * F, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eigen.eigenvalues()[2], 0.0));
}

}  // namespace kessler
