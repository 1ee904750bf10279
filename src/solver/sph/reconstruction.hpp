#pragma once
// The finite-element reconstruction of SPH's particles (docs/theory.md §10; the particle-centroid
// coincident model of Zhang & Jia, on SPH of satellite breakup). Each particle of a lattice body is
// the centroid of a hexahedral element; after every step the elements' nodes are rebuilt from the
// particles:
//   - a node with all 8 of its elements intact: the mean of their particles' positions;
//   - any other node (a body's surface, or beside failed material): the mean, over its intact
//     elements, of the particle's position extrapolated by its own deformation gradient,
//     x_p + F_p (X_a - X_p) (X: reference positions); exact for any affine motion;
//   - a node of failed elements only: the same over all of them (drawn in the output, never judged).
// An intact element fails when its reconstructed shape is too distorted: the smallest scaled
// Jacobian of its eight corners (det of the corner's three edges over the product of their
// lengths: 1 for a cube, the sine of the corner's angle under shear, negative when inverted) below
// the threshold. Its particle becomes loose (PointStore::loose): a free particle, no longer part of
// a trusted fragment, whose material keeps its state and strength (the threshold is a limit of the
// reconstruction, not a fracture criterion). Material failure (eigenerosion, Johnson-Cook damage,
// spall) fails an element too, and its material. Trusted fragments are the connected components of
// intact elements that share a node (the lattice's adjacency; analysis/fragments.hpp).
#include "solver/common/node_cloud.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/sph/model.hpp"

#include <array>
#include <vector>

namespace kessler::sph {

// A hexahedron's quality from its corners' places (by corner: bit 0 +x, 1 +y, 2 +z): the smallest, over
// its corners, of the scaled Jacobian, det of the corner's three edges over the product of their
// lengths (1 for a cube, the sine of the corner's angle under shear, negative when inverted).
double elementQuality(const std::array<Vec3, 8>& x);

class Reconstruction {
 public:
  // The nodes of every lattice body's elements (Model::lattices, Model::element).
  explicit Reconstruction(const Model& model);
  // The nodes from the particles' current state.
  void rebuild(const Model& model);
  // Makes loose every intact particle whose element's quality is below `min_quality` (after
  // rebuild); returns how many (with `share`, of the own particles over every rank: a ghost is
  // judged by its owner).
  LocalIndex failDistorted(Model& model, double min_quality, const Share& share = {});
  // Per particle held, the distance to the farthest intact particle whose element shares a node with
  // its own (0 for a particle without an element, or broken or loose, and with `share` for a
  // ghost). A distributed run's halo sends each particle at least this far (docs/parallel.md, "SPH
  // across ranks"), so that a rank holds every intact neighbour of its own intact elements and
  // rebuilds their nodes as one process.
  std::vector<double> latticeReach(const Model& model, const Share& share = {}) const;
  // One ring of elements further: per particle held, the largest distance to an intact particle
  // whose element shares a node with its own plus that particle's `reach` (the owners' values for
  // ghosts), a bound on the distance to any intact particle one ring beyond what `reach` bounds.
  std::vector<double> extendReach(const Model& model, const std::vector<double>& reach, const Share& share = {}) const;
  // The smallest scaled corner Jacobian of particle p's element at the last failDistorted (1: a cube);
  // NaN for a particle without an element, or broken or loose before it, or a ghost.
  double quality(LocalIndex p) const { return quality_[static_cast<std::size_t>(p)]; }
  NodeCloud cloud() const;
  // The lattice: each node's elements and each element's nodes by corner (bit 0: +x, 1: +y, 2: +z;
  // -1 if none; an element is its particle), and their places in the reference configuration.
  const std::vector<std::array<LocalIndex, 8>>& nodeElements() const { return node_elements_; }
  const std::vector<std::array<LocalIndex, 8>>& elementNodes() const { return element_nodes_; }
  const std::vector<Vec3>& nodeReference() const { return reference_; }
  const std::vector<Vec3>& particleReference() const { return particle_reference_; }

 private:
  std::vector<Index> id_;
  std::vector<std::int32_t> body_;
  std::vector<Vec3> reference_, x_, v_;
  std::vector<double> mass_;  // zero: the nodes carry no mass (the particles do)
  // Each node's elements by the corner the node is of them (bit 0: +x, 1: +y, 2: +z), -1 if none.
  std::vector<std::array<LocalIndex, 8>> node_elements_;
  // Each particle's nodes by corner, -1 for a particle without an element.
  std::vector<std::array<LocalIndex, 8>> element_nodes_;
  std::vector<Vec3> particle_reference_;
  std::vector<double> quality_;
};

}  // namespace kessler::sph
