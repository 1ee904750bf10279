#pragma once
// Essential boundary conditions by velocity collocation (docs/theory.md §12; Zhao & Song, Explosion
// and Shock Waves 30, 2010). RK shape functions do not interpolate:
// a particle's velocity is sum_I Psi_I(X_K) vhat_I over the coefficients vhat_I, not its own
// coefficient. A velocity g prescribed at the boundary particles B is met by choosing their
// coefficients: with J_KI = Psi_I(X_K) (K, I in B) and G_KI = Psi_I(X_K) (K in B, I not in B),
//   J vhat_B = g - G vhat_N,
// solved each step with J factorised once (the kernels do not change in a total-Lagrangian run).
// Each velocity component has its own set B: the particles that prescribe it.
#include "solver/rkpm/kernels.hpp"

#include <Eigen/SparseLU>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace kessler::rkpm {

class VelocityCollocation {
 public:
  VelocityCollocation() = default;
  // Bit a of constrained[K] set: particle K prescribes component a. Throws kessler::Error if a
  // component's J is singular.
  VelocityCollocation(const Table<double>& psi, std::span<const std::uint8_t> constrained);

  // Sets the constrained particles' coefficients so that their velocities are `prescribed`.
  void impose(std::span<const Vec3> prescribed, std::span<Vec3> coefficients) const;

 private:
  struct Component {
    std::vector<LocalIndex> particles;     // B, in index order
    Eigen::SparseMatrix<double> coupling;  // G over every particle (columns in B are zero)
    std::shared_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> solver;  // J's factors
  };
  std::array<Component, 3> components_;
};

}  // namespace kessler::rkpm
