#pragma once
// Essential boundary conditions by velocity collocation (docs/theory.md §12; Zhao & Song, Explosion
// and Shock Waves 30, 2010). RK shape functions do not interpolate:
// a particle's velocity is sum_I Psi_I(X_K) vhat_I over the coefficients vhat_I, not its own
// coefficient. A velocity g prescribed at the boundary particles B is met when
//   P vhat = g,   P_KI = Psi_I(X_K) (K in B, every I),
// Zhao & Song's J vhat_B = g - G vhat_N with P = [J G]. Of the coefficients that meet it we take
// the nearest to the step's in the lumped masses' metric: impulses lambda_K at the particles of B,
// reaching the coefficients as forces do,
//   vhat <- vhat + M^-1 P^T lambda,   (P M^-1 P^T) lambda = g - P vhat,
// solved each step with P M^-1 P^T factorised once (the kernels do not change in a total-Lagrangian
// run). The impulses are the boundary's reactions: the momentum changes by sum_K lambda_K, and a
// still boundary never adds kinetic energy (the projection in the energy's own metric). Changing
// only the coefficients of B, as J vhat_B = g - G vhat_N does, can add energy: in the hugoniot-3d
// column its coefficients grew to cancel their neighbours' velocities and the run gained 28% (5% in
// the metric).
// Each velocity component has its own set B: the particles that prescribe it. Where a plane holds a
// particle's component (held_at_surface), its row is instead the particle's cell faces on the body's
// surface normal to that component: the velocity is held where the cells' smoothed gradients read
// it. Held at the particles, half a cell inside, the faces were free to move through the plane: a
// lattice column under the hugoniot-3d shock moved sideways at up to 2 km/s (0.46 km/s held on the
// faces), and pressure came out 12% low (1.3%); the rollers are mirror planes now (docs/validation.md,
// "RKPM").
#include "solver/rkpm/kernels.hpp"
#include "solver/rkpm/model.hpp"

#include <Eigen/SparseCholesky>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace kessler::rkpm {

// A surface face that holds velocity component `axis` to particle `particle`'s prescribed value.
struct HeldFace {
  LocalIndex particle = -1;
  int axis = 0;
};

// The surface faces where planes hold the velocity: each face of the body's surface whose normal
// lies along a component that its particle holds at the surface (held_at_surface); `faces` lists them
// for buildKernels (KernelInput::kept_faces), `held` says what each holds.
struct SurfaceHolds {
  std::vector<LocalIndex> faces;
  std::vector<HeldFace> held;
};
SurfaceHolds surfaceHolds(const Model& model);

class VelocityCollocation {
 public:
  VelocityCollocation() = default;
  // Bit a of constrained[K] set: particle K prescribes component a; mass: the coefficients' lumped
  // masses; at_faces: the shape functions at the faces `held` (row r for held[r]). Throws
  // kessler::Error if a component's P M^-1 P^T is singular.
  VelocityCollocation(const Table<double>& psi, std::span<const std::uint8_t> constrained, std::span<const double> mass,
                      const Table<double>& at_faces = {}, std::span<const HeldFace> held = {});

  // Changes the coefficients so that the constrained particles' velocities are `prescribed`.
  void impose(std::span<const Vec3> prescribed, std::span<Vec3> coefficients) const;

 private:
  struct Component {
    std::vector<LocalIndex> source;              // each row's particle, whose prescribed value it holds
    Eigen::SparseMatrix<double> shape, shape_t;  // P and its transpose
    std::shared_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> solver;  // P M^-1 P^T's factors
  };
  std::array<Component, 3> components_;
  Eigen::VectorXd inverse_mass_;
};

}  // namespace kessler::rkpm
