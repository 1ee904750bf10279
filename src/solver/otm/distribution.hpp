#pragma once
// A rank's part of a distributed OTM run (docs/parallel.md, "The distributed step"): the points and
// nodes in its subdomain, which it owns, and ghosts, copies of the other ranks' entries that its
// own entries reach. The integrator computes every entry it holds; the owners' values replace what
// it got wrong for ghosts (refresh), so that after each refresh every entry a rank holds is bitwise
// what one process holds for it.
//
// The halos are fetched again before every search, deep enough that each own node's sums and each
// own point's stencils are whole (points within one support radius of the subdomain, nodes within
// two), and the points and nodes that left a subdomain move to their new owner then.
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/partition.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/otm/model.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace kessler::otm {

class Distribution {
 public:
  explicit Distribution(const parallel::Communicator& comm);

  // Keeps this rank's part of a model that every rank built alike: RCB cuts of the points (each
  // weighted by one), and the points and nodes in this rank's subdomain. No ghosts yet (rebuild).
  void split(Model& model);
  // Moves each own point and node that left its subdomain to the rank whose subdomain now holds it,
  // and fetches the ghosts for searches of radius up to `support` (a point's row holds the nodes
  // within its search), erosion balls of `erosion_radius` times a point's spacing, and debris
  // contacts reaching up to `contact_reach` (solver/common/debris_contact.hpp). `volume_rate` (per
  // point; zeros if it has another size) travels with the points. Collective; the connectivity is
  // stale afterwards (the search rebuilds it, for the points searched()).
  void rebuild(Model& model, std::vector<double>& volume_rate, double support, double erosion_radius,
               double contact_reach);

  // The whole run as one process holds it, on rank 0 (nullopt elsewhere): every rank's own points
  // and nodes in id order and the shared bodies, materials and links (what output and analysis
  // read), and with `rows` the connectivity and LME multipliers (what a checkpoint adds; zero
  // multipliers and no connectivity without). Collective.
  std::optional<Model> gather(const Model& model, bool rows) const;

  // The largest rank's work over the mean at the last rebuild (its own points, each weighted by the
  // entries of its row and a share for the point itself: ownWork), the largest so far, and how many
  // times the points were cut afresh (parallel::Rebalance).
  double imbalance() const { return balance_.imbalance(); }
  double largestImbalance() const { return balance_.largestImbalance(); }
  int rebalances() const { return balance_.count(); }

  // After a phase that got ghosts wrong: the owners' values of one array, or of every array of a store.
  template <class T>
  void refreshPoints(std::vector<T>& values) const {
    points_.refresh(values);
  }
  template <class T>
  void refreshNodes(std::vector<T>& values) const {
    nodes_.refresh(values);
  }
  void refreshPoints(PointStore& points) const { points_.refreshFields(points); }
  void refreshNodes(NodeStore& nodes) const { nodes_.refreshFields(nodes); }

  const parallel::Communicator& comm() const { return comm_; }
  // Per point and per node held, 1 for a ghost.
  std::span<const std::uint8_t> ghostPoints() const { return points_.ghostMask(); }
  std::span<const std::uint8_t> ghostNodes() const { return nodes_.ghostMask(); }
  // Per point held, 1 for those the search must give a row: the own points, and the ghosts within
  // the last rebuild's support of the subdomain, whose rows may hold own nodes. The other ghosts are
  // held for what they are, not for what they move (erosion balls, debris contact).
  std::span<const std::uint8_t> searched() const { return searched_; }
  // What sums and minima over the points count, and the ranks they run over.
  Share pointShare() const { return {points_.ghostMask(), &comm_}; }
  Share nodeShare() const { return {nodes_.ghostMask(), &comm_}; }
  // This rank's own points and its ghosts, at the last rebuild.
  LocalIndex ownPoints() const { return own_points_; }
  LocalIndex ghostPointCount() const { return points_.ghosts(); }
  LocalIndex ghostNodeCount() const { return nodes_.ghosts(); }
  // The steps whose halos were fetched afresh, and those whose ghosts were kept (points' halo).
  long haloFetches() const { return points_.fetches(); }
  long haloKeeps() const { return points_.keeps(); }

 private:
  const parallel::Communicator& comm_;
  // Each of the own points' (`own`, in order) work in the last step, in row entries (for the balance).
  std::vector<double> ownWork(const Model& model, const std::vector<LocalIndex>& own) const;

  parallel::Partition partition_;
  parallel::Halo points_, nodes_;
  parallel::Rebalance balance_;
  LocalIndex own_points_ = 0;
  std::vector<std::uint8_t> searched_;
};

}  // namespace kessler::otm
