#pragma once
// RKPM's state (docs/theory.md §12): the shared particle state (solver/common/particle_state.hpp),
// whose material points are the particles at their physical positions and velocities, and beside it
// the particles' coefficients, their reference positions and their cells. A particle's physical
// position is sum_I Psi_I(X_K) xhat_I over the coefficients xhat_I, which the equations of motion
// advance; the two differ because the shape functions do not interpolate.
#include "solver/common/particle_state.hpp"
#include "solver/rkpm/kernels.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace kessler::rkpm {

inline constexpr std::uint8_t held_at_surface = 8;

struct Model : ParticleState {
  // Per particle: bit a set if velocity component a is prescribed, to prescribed_v[a] (fixed faces,
  // the deck's and the verification problems' planes), imposed by velocity collocation. Bit 3 + a
  // (held_at_surface << a) as well: a plane holds component a on the particle's cell faces that lie
  // on the body's surface normal to a, not at the particle (VelocityCollocation).
  std::vector<std::uint8_t> constrained;
  std::vector<Vec3> prescribed_v;
  // X_I: the kernels' centres, where the particles were at the last kernel update (at the start, where
  // they started; docs/theory.md §12, "Kernel updates").
  std::vector<Vec3> reference;
  std::vector<Vec3> coefficient_x;  // xhat_I
  std::vector<Vec3> coefficient_v;  // vhat_I
  std::vector<double> cell_volume;  // each particle's cell (its nodal integration domain), m^3
  std::vector<CellFace> faces;      // the cells' faces, each once
  // The bodies' surfaces for the sliding contact between them (solver/rkpm/surface.hpp): triangles
  // of particles, counter-clockwise seen from outside, over the particles that are not debris; none
  // for a single body.
  std::vector<std::array<LocalIndex, 3>> surface;
  // Each particle's lattice element (i, j, k) in its body, the surface's source ({-1, -1, -1} for a
  // particle of a checkpoint that did not save them).
  std::vector<std::array<int, 3>> element;
  // Per particle: 1 if it was broken before the first step, a crack the deck or problem made, which
  // no kernel reaches across (KernelInput::crack); empty if none was.
  std::vector<std::uint8_t> crack;
  // After a kernel update (both empty before one): where the particles started, which the cells (faces,
  // cell_volume) still describe, and each particle's deformation gradient at the last update, which maps
  // its first cell onto its cell at the update (KernelInput::cell_F).
  std::vector<Vec3> origin;
  std::vector<Mat3> reference_F;
  // Per particle, after a kernel update: 1 if it was debris then, standing alone in the kernels
  // (KernelInput::alone); empty before one.
  std::vector<std::uint8_t> alone;
};

}  // namespace kessler::rkpm
