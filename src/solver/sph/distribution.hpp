#pragma once
// A rank's part of a distributed SPH run (docs/parallel.md, "SPH across ranks"): the particles in its
// subdomain, which it owns, and ghosts, copies of the other ranks' particles that its own reach. As
// OTM's (solver/otm/distribution.hpp): the integrator computes every particle it holds, and the
// owners' values replace what it got wrong for ghosts (refresh), so that every own particle is
// bitwise what one process holds for it. The store holds its part of the whole in id order (the
// halo merges ghosts among the own particles), which is the one process's order: each particle's
// pairs are listed and summed in the same order.
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/partition.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/sph/model.hpp"

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace kessler::sph {

// The integrator's per-particle arrays that travel with the particles (sized as the store): the last
// step's volume rate (the time step's bound) and the reach of each particle's lattice neighbours
// (Reconstruction::latticeReach).
struct Carried {
  std::vector<double>& volume_rate;
  std::vector<double>& lattice_reach;
};

// Particles may cross a mirror plane (debris), and pair with the images of particles far from
// them: a particle's place in the partition and the halo is its position folded into the model's
// side of the planes (Mirrors::fold; |x_a| for a symmetry plane normal to axis a). Folding brings no
// two particles further apart than they or their images are (|(|a| - |b|)| <= |a -+ b|), so every
// reach below holds for images too.

class Distribution {
 public:
  Distribution(const parallel::Communicator& comm, const MirrorBox& mirrors);

  // Keeps this rank's part of a model that every rank built alike: RCB cuts of the particles (each
  // weighted by one), and the particles in this rank's subdomain. No ghosts yet (rebuild).
  void split(Model& model, Carried carried);
  // Moves each own particle that left its subdomain to the rank whose subdomain now holds it (or
  // cuts afresh past the imbalance, each weighted by `work`, per particle held), then fetches the
  // ghosts that other ranks' particles reach: reach(p) for each own particle p after the move.
  // Returns true when the store's order changed (a migration or ghosts fetched afresh), false when
  // the ghosts stayed in their slots and took their owners' values. Collective.
  bool rebuild(Model& model, Carried carried, std::span<const double> work,
               const std::function<double(LocalIndex)>& reach);

  // The whole run as one process holds it, on rank 0 (nullopt elsewhere): every rank's own
  // particles in id order and the shared bodies, materials, links and lattices. Collective.
  std::optional<Model> gather(const Model& model) const;

  // After a phase that got ghosts wrong: the owners' values of one array, or of every particle array.
  template <class T>
  void refresh(std::vector<T>& values) const {
    halo_.refresh(values);
  }
  void refresh(Model& model) const;

  const parallel::Communicator& comm() const { return comm_; }
  // What sums and minima over the particles count (the own ones), and the ranks they run over.
  Share share() const { return {halo_.ghostMask(), &comm_}; }
  LocalIndex ownParticles() const { return own_; }
  LocalIndex ghostParticles() const { return halo_.ghosts(); }
  long haloFetches() const { return halo_.fetches(); }
  long haloKeeps() const { return halo_.keeps(); }
  // The largest rank's work over the mean at the last rebuild, the largest so far, and how many
  // times the particles were cut afresh (parallel::Rebalance).
  double imbalance() const { return balance_.imbalance(); }
  double largestImbalance() const { return balance_.largestImbalance(); }
  int rebalances() const { return balance_.count(); }
  // How many times the store's order changed (split and rebuild): indices found before a change
  // are stale after it.
  long layout() const { return layout_; }

 private:
  const parallel::Communicator& comm_;
  parallel::Partition partition_;
  parallel::Halo halo_;
  parallel::Rebalance balance_;
  Mirrors mirrors_;           // the mirror planes (for folding)
  std::vector<Vec3> folded_;  // per particle held, its folded position (a field while it travels)
  LocalIndex own_ = 0;
  long layout_ = 0;
};

}  // namespace kessler::sph
