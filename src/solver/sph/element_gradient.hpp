#pragma once
// The reconstructed elements' share of SPH's deviatoric deformation and forces (docs/theory.md §10,
// "The elements' share of the deviator"). On an intact lattice particle that touches no other body,
// the velocity gradient is
//   L = s dev(L_e) + (1 - s) dev(L_sph) + tr(L_sph) I / 3,
// L_e the gradient of the particle's hexahedron (trilinear, at its centre) from its nodes'
// velocities, L_sph SPH's corrected gradient and s the share (SphOptions::element_share). Both are
// exact for a linear velocity field, so L is. The forces are its adjoint: the deviatoric stress's
// share s acts through the hexahedra on their nodes and from the nodes on the particles, the rest of
// the stress through SPH's pairs, so that momentum is exact and the forces' power is the stress
// power. A hexahedron meets the divergence theorem node by node, so a surface's tractions reach the
// particles that carry them, where SPH's pairs are one-sided; the pressure stays SPH's alone (a gas
// has no shear stiffness to hold a hexahedron's zero-energy modes). A hexahedron takes no part when
// its corners have closed below the reconstruction's distortion threshold (elementQuality), or a
// node of it cannot be placed; its particle then takes SPH's gradient alone.
//
// Each node moves with a fixed linear combination of its particles, exact for any affine motion:
//   - a node whose eight elements are intact, counting images across mirror planes: their mean;
//   - any other node: the weighted least-squares linear fit, at the node's reference place, of the
//     intact particles of its elements and of their neighbours (weights exp(-|X - X_a|^2 / delta^2)
//     at reference places X, delta the lattice cell).
// The weights depend on the reference lattice and on which particles are intact: those of the nodes
// within reach of a particle whose state changed are rebuilt (all, when the store's layout or the
// mirrors' images change).
#include "solver/common/mirror.hpp"
#include "solver/sph/model.hpp"
#include "solver/sph/reconstruction.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace kessler::sph {

class ElementGradient {
 public:
  // `min_quality`: a hexahedron below it (elementQuality) takes no part.
  ElementGradient(double share, double min_quality) : share_(share), min_quality_(min_quality) {}
  double share() const { return share_; }
  // The nodes' weights are rebuilt at the next update (the reconstruction's nodes were renumbered).
  void renumbered() { layout_ = -1; }
  // At the current positions (after the search, which gives the mirrors and the contacts): the
  // nodes' weights if the intact particles or the store's layout changed, the nodes' places and each
  // taking part particle's corner gradients. `touches`: the bodies each particle touches (a particle
  // at a contact takes SPH's gradient alone).
  void update(const Model& model, const Reconstruction& reconstruction, const Mirrors& mirrors,
              std::span<const std::uint32_t> touches, long layout);
  // Whether particle p takes the elements' share (at the last update).
  bool takesPart(LocalIndex p) const { return share_ > 0.0 && active_[static_cast<std::size_t>(p)] != 0; }
  // The nodes' velocities from the particles' (before gradient()).
  void moveNodes(std::span<const Vec3> v, const Mirrors& mirrors);
  // Particle p's velocity gradient from L_sph, SPH's (above).
  Mat3 blend(LocalIndex p, const Mat3& L_sph) const;
  // The stress SPH's pairs carry for particle p: all but the elements' share of the deviator.
  Mat3 pairStress(LocalIndex p, const Mat3& stress) const;
  // Adds the elements' forces on the particles to f, N (by the nodes, in a fixed order).
  void addForces(const PointStore& points, const Reconstruction& reconstruction, const Mirrors& mirrors,
                 std::vector<Vec3>& f);

 private:
  struct Weight {
    LocalIndex particle;
    std::uint8_t image;  // a code of the mirrors (0: the particle itself)
    double weight;
  };
  // The weights of the nodes marked in `dirty` (all when it is empty).
  void weigh(const Model& model, const Reconstruction& reconstruction, const Mirrors& mirrors,
             const std::vector<std::uint8_t>& dirty);

  double share_, min_quality_;
  std::vector<std::vector<Weight>> weights_;  // per node
  std::vector<Vec3> x_, v_, force_;           // per node
  std::vector<Mat3> stress_;                  // per particle: s V dev(sigma) (addForces)
  std::vector<std::array<Vec3, 8>> corner_gradient_;
  std::vector<std::array<LocalIndex, 8>> nodes_;
  std::vector<std::uint8_t> active_, intact_;
  long layout_ = -1;
  std::size_t images_ = 0;
};

}  // namespace kessler::sph
