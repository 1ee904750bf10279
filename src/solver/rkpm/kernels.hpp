#pragma once
// RKPM's shape functions, computed once on the reference configuration (docs/theory.md §12): each
// particle's reproducing kernel values at the particles (which turn coefficients into the physical
// positions and velocities of the particles) and the stabilised conforming nodal integration's
// smoothed gradients (Chen, Wu, Yoon & You, IJNME 50:435, 2001):
//   grad~ Psi_I(X_J) = 1 / V_J  sum over the faces f of cell J of  Psi_I(c_f) A_f n_f,
// the gradient averaged over the particle's cell by the divergence theorem, each face's integral by
// its centroid (exact for the linear fields the kernels reproduce: the smoothed gradients of a
// linear field are its gradient, which is the integration constraint of Chen et al. 2001).
#include "approx/reproducing_kernel.hpp"
#include "core/types.hpp"
#include "solver/common/mirror.hpp"

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace kessler::rkpm {

// A face of a particle's cell (its nodal integration domain, its lattice element; the smoothed
// gradients hold for any closed cell): its area vector out of the cell of `inner`, and its centroid;
// `outer` is the particle whose cell lies on the other side, -1 on the body's surface.
struct CellFace {
  Vec3 area = Vec3::Zero();
  Vec3 centroid = Vec3::Zero();
  LocalIndex inner = -1;
  LocalIndex outer = -1;
};

// A face of the body's surface whose normal lies along `axis` (to round-off): one a plane normal to
// that axis can hold.
inline bool surfaceFaceAlong(const CellFace& f, int axis) {
  const double area = f.area.norm();
  return f.outer < 0 && area > 0.0 && std::abs(f.area[axis]) >= (1.0 - 1e-9) * area;
}

// One row per particle: the particles column[offset[K]] ... column[offset[K + 1] - 1] and a value each.
// A particle near a mirror plane also sees images of particles across it (a symmetry plane's mirrored
// copy of the model that the run leaves out, or a roller's): mirror[e] sets the bits of the axes
// along which entry e's image is reflected (solver/common/mirror.hpp), 0 for the particle itself or
// an image translated between two planes. An image's coefficient is its particle's, reflected so.
template <class T>
struct Table {
  std::vector<LocalIndex> offset;  // rows + 1 entries (none for an empty table)
  std::vector<LocalIndex> column;
  std::vector<std::uint8_t> mirror;
  std::vector<T> value;
  LocalIndex rows() const { return offset.empty() ? 0 : static_cast<LocalIndex>(offset.size()) - 1; }
};

struct Kernels {
  Table<double> psi;       // row K: Psi_I(X_K)
  Table<Vec3> gradient;    // row J: grad~ Psi_I(X_J)
  Table<double> at_faces;  // row r: Psi_I at the centroid of face kept_faces[r]
  // Row K's sum of Psi times its images' shifts (x -> R x + t): the particle's position is
  // sum_I Psi_I(X_K) R xhat_I + shift[K]. Empty when every image's shift is zero (symmetry planes).
  std::vector<Vec3> shift;
  // The points (particles and faces) whose singular moment matrix left them their particle alone
  // (KernelInput::alone_where_singular).
  std::size_t fallbacks = 0;
};

struct KernelInput {
  std::span<const Vec3> reference;              // X_I
  std::span<const int> body;                    // a particle's kernel reaches only its own body's particles
  std::span<const double> support;              // a_I, m
  std::span<const double> volume;               // V_I (the quadrature weights of M), m^3
  std::span<const double> cell_volume;          // the volume of each particle's cell, m^3
  std::span<const CellFace> faces;              // every cell's faces, each once
  std::span<const std::string> bodies;          // the bodies' names, for errors
  MirrorBox mirrors;                            // the problem's mirror planes (symmetry planes, rollers)
  std::span<const LocalIndex> kept_faces = {};  // faces whose values Kernels::at_faces keeps
  // Per particle (empty: none): 1 if its cell is a crack that no kernel reaches across. A kernel value
  // Psi_I(x) is left out where the segment from x to X_I passes through the inside of such a cell
  // (the visibility criterion of meshfree fracture: Belytschko, Lu & Gu, IJNME 37:229, 1994); the
  // cell is taken as the box its faces' centroids span (the lattice's element itself). Rows of the
  // crack's own particles, and of faces between two of its cells or on the surface, see every
  // particle. Images across mirror planes are tested against the crack on this side only.
  std::span<const std::uint8_t> crack = {};
  // After a kernel update (empty before one): each particle's cell is its first cell mapped affinely by
  // cell_F[J], the particle's deformation gradient at the update, about its position X_J then. A face of
  // cell J with first centroid c and area vector a lies at X_J + F_J (c - cell_origin[J]) with area vector
  // det F_J F_J^-T a, and the cell's volume is det F_J cell_volume[J]. A face two cells share is then two
  // faces, one per cell: each cell stays closed, and a linear field's smoothed gradient is still exact.
  std::span<const Mat3> cell_F = {};
  std::span<const Vec3> cell_origin = {};
  // Per particle (empty: none): 1 if it stands alone, its values and its cell's faces' values its own
  // coefficient's only (Psi = 1) and its coefficient in no other row: debris at a kernel update, which
  // flies on by itself and carries no stress.
  std::span<const std::uint8_t> alone = {};
  // At a kernel update, a point whose moment matrix is singular (a few particles left together by
  // erosion) takes its particle's coefficient alone instead of stopping the run (Kernels::fallbacks).
  bool alone_where_singular = false;
};

// Throws kessler::Error naming the body and the position where a moment matrix is singular.
Kernels buildKernels(const KernelInput& in);

// The particles' values from the coefficients, out_K = sum_I Psi_I(X_K) chat_I (an image's
// coefficient reflected): their velocities from vhat, and with Kernels::shift their positions.
void interpolate(const Table<double>& psi, std::span<const Vec3> coefficients, std::span<Vec3> out);
// Two fields at once (positions and velocities), the table read once: out_a, out_b as interpolate
// gives them.
void interpolate(const Table<double>& psi, std::span<const Vec3> a, std::span<const Vec3> b, std::span<Vec3> out_a,
                 std::span<Vec3> out_b);
// The same for particle k alone.
Vec3 valueAt(const Table<double>& psi, std::span<const Vec3> coefficients, LocalIndex k);

// Coefficients whose values at the particles approach `values`, from `guess`: each pass hands the
// residual's impulses m_K (values_K - sum_I Psi_I(X_K) chat_I) to the coefficients through the shape
// functions, chat_I += (1 / m_I) sum_K Psi_I(X_K) m_K r_K (the lumped L2 projection of the residual,
// with the lumped masses m_I = sum_K m_K Psi_I(X_K)). After the first pass the coefficients' momentum
// sum_I m_I chat_I is the particles' sum_K m_K values_K, and every further pass keeps it. Up to
// `passes` passes, while each brings the largest residual down (the result of the first is kept in
// any case): the smooth part of the field converges in a few, a mode from particle to particle, which
// the kernels average away, is left out rather than reproduced by wildly oscillating coefficients.
std::vector<Vec3> interpolatingCoefficients(const Table<double>& psi, std::span<const double> particle_mass,
                                            std::span<const double> mass, std::span<const Vec3> values,
                                            std::span<const Vec3> guess, int passes);

// An impulse on particle k handed to the coefficients as a force is, through the shape functions:
// vhat_I += Psi_I(X_k) impulse / m_I (an image's share reflected onto its particle). The
// coefficients' momentum sum_I m_I vhat_I gains the impulse exactly (the shape functions sum to one).
void spreadImpulse(const Table<double>& psi, std::span<const double> mass, LocalIndex k, const Vec3& impulse,
                   std::span<Vec3> coefficient_v);

}  // namespace kessler::rkpm
