#include "solver/rkpm/wall_contact.hpp"

#include "core/error.hpp"

#include <Eigen/SparseCholesky>

#include <fmt/format.h>

namespace kessler::rkpm {

namespace {

// One wall's impulses on the particles `touching`, each to its normal velocity `target`; returns the
// impulses (positive: pushing along the wall's side).
Eigen::VectorXd solveImpulses(const RigidWall& wall, const Table<double>& psi, std::span<const double> mass,
                              std::span<const LocalIndex> touching, std::span<const double> target,
                              std::span<const Vec3> coefficient_v) {
  const auto m = static_cast<Eigen::Index>(touching.size());
  const auto n = static_cast<Eigen::Index>(mass.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const LocalIndex k = touching[static_cast<std::size_t>(r)];
    for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      const double sign = psi.mirror[slot] & (1u << wall.axis) ? -1.0 : 1.0;
      entries.emplace_back(static_cast<int>(r), static_cast<int>(psi.column[slot]), sign * psi.value[slot]);
    }
    rhs[r] = target[static_cast<std::size_t>(r)] - valueAt(psi, coefficient_v, k)[wall.axis];
  }
  Eigen::SparseMatrix<double> P(m, n);
  P.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd inverse_mass(n);
  for (Eigen::Index i = 0; i < n; ++i) inverse_mass[i] = 1.0 / mass[static_cast<std::size_t>(i)];
  const Eigen::SparseMatrix<double> A = P * inverse_mass.asDiagonal() * Eigen::SparseMatrix<double>(P.transpose());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success)
    throw NumericalError(fmt::format(
        "RKPM wall contact: the {} particles touching the wall {} = {:.6g} m have shape functions that form a "
        "singular system (docs/theory.md §12)",
        m, "xyz"[wall.axis], wall.position));
  return solver.solve(rhs);
}

}  // namespace

std::size_t imposeWalls(std::span<const RigidWall> walls, const Table<double>& psi, std::span<const double> mass,
                        std::span<const Vec3> x, std::span<const double> gap, double dt,
                        std::span<Vec3> coefficient_v) {
  std::size_t pushed = 0;
  const LocalIndex n = psi.rows();
  for (const RigidWall& wall : walls) {
    // The particles that would end the step within their gap of the wall, and the normal velocity
    // that brings each to its gap at the end of the step.
    std::vector<LocalIndex> touching;
    std::vector<double> target;
    for (LocalIndex k = 0; k < n; ++k) {
      const double distance = wall.side * (x[static_cast<std::size_t>(k)][wall.axis] - wall.position) - gap[k];
      const double normal = wall.side * valueAt(psi, coefficient_v, k)[wall.axis];
      if (distance + dt * normal >= 0.0) continue;
      touching.push_back(k);
      target.push_back(-wall.side * distance / dt);
    }
    // A wall only pushes: the particles it would pull leave the set (a few rounds settle it).
    Eigen::VectorXd impulse;
    for (int round = 0; round < 8 && !touching.empty(); ++round) {
      impulse = solveImpulses(wall, psi, mass, touching, target, coefficient_v);
      std::size_t kept = 0;
      for (std::size_t r = 0; r < touching.size(); ++r)
        if (wall.side * impulse[static_cast<Eigen::Index>(r)] >= 0.0) {
          touching[kept] = touching[r];
          target[kept] = target[r];
          ++kept;
        }
      if (kept == touching.size() || round == 7) break;
      touching.resize(kept);
      target.resize(kept);
      impulse.resize(0);
    }
    if (impulse.size() == 0) continue;
    for (std::size_t r = 0; r < touching.size(); ++r) {
      Vec3 push = Vec3::Zero();
      push[wall.axis] = impulse[static_cast<Eigen::Index>(r)];
      spreadImpulse(psi, mass, touching[r], push, coefficient_v);
    }
    pushed += touching.size();
  }
  return pushed;
}

}  // namespace kessler::rkpm
