#pragma once
// RKPM's rigid walls, met by the particles rather than by the kernel coefficients (docs/theory.md
// §12). A particle K is in contact with a wall when, moving with its velocity v_K = sum_I Psi_I(X_K)
// vhat_I, it would end the step closer to the wall than its gap (half its spacing: its cell's reach
// beyond it). The wall's impulses lambda_K act on the particles in contact and reach the
// coefficients as forces do, through the shape functions:
//   vhat_I += 1 / m_I  sum_K Psi_I(X_K) lambda_K n,
// with the lambda_K that bring those particles' normal velocities to the wall's (the velocity
// collocation of Zhao & Song 2010 with the lumped masses as its metric):
//   (P M^-1 P^T) lambda = g - P vhat_n,   P_KI = Psi_I(X_K) for K in contact.
// A wall only pushes: a particle whose impulse would pull leaves the set and the rest is solved
// again. The momentum the coefficients gain is sum_K lambda_K n, the impulse the wall gives.
#include "solver/common/walls.hpp"
#include "solver/rkpm/kernels.hpp"

#include <span>
#include <vector>

namespace kessler::rkpm {

// The coefficients' velocities `coefficient_v` after the walls' impulses for a step dt; x are the
// particles' positions, gap each particle's distance from a wall in contact, mass the lumped masses.
// Returns the number of particles the walls pushed.
std::size_t imposeWalls(std::span<const RigidWall> walls, const Table<double>& psi, std::span<const double> mass,
                        std::span<const Vec3> x, std::span<const double> gap, double dt, std::span<Vec3> coefficient_v);

}  // namespace kessler::rkpm
