#pragma once
// Subdomains by recursive coordinate bisection (Zoltan's RCB: Berger & Bokhari, IEEE Trans.
// Computers 36:570, 1987; docs/parallel.md): the points of every rank, each with its work as
// weight, are cut by planes normal to the axes until each rank's box holds an equal share of the
// work. The cuts are kept, so that any position or box can be assigned afterwards (a point that
// moved, the halo a rank needs). On one process everything belongs to rank 0 and Zoltan is not
// called.
#include "core/types.hpp"
#include "parallel/communicator.hpp"

#include <memory>
#include <span>
#include <vector>

namespace kessler::parallel {

struct Box {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  bool contains(const Vec3& x) const { return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all(); }
};

class Partition {
 public:
  explicit Partition(const Communicator& comm);
  ~Partition();
  Partition(const Partition&) = delete;
  Partition& operator=(const Partition&) = delete;

  // Cuts the points of all ranks (x, their ids, unique over the ranks, and their work, > 0) into
  // one subdomain per rank, and returns the rank each of this rank's points belongs to. Collective.
  std::vector<int> balance(std::span<const Vec3> x, std::span<const Index> ids, std::span<const double> work);

  // The rank whose subdomain holds x (anywhere in space: the outer subdomains reach to infinity).
  int owner(const Vec3& x) const;
  // The ranks whose subdomains meet the box [lo, hi] (this rank's own included where it does).
  std::vector<int> ranksMeeting(const Vec3& lo, const Vec3& hi) const;
  // The subdomain of a rank, its outer faces clipped to the box of all points at the last balance.
  Box subdomain(int rank) const;
  // The region of space owner() gives a rank: its subdomain with the outer faces at +-infinity
  // (the whole of space on one process).
  Box region(int rank) const;

  struct Zoltan;  // Zoltan's state (opaque here: its callbacks are defined with it)

 private:
  // Zoltan's part (reached only with more than one rank): the cuts, the rank of a position, the
  // ranks a box meets, a rank's box as cut (outer faces at +-DBL_MAX).
  void cut(std::span<const Vec3> x, std::span<const Index> ids, std::span<const double> work);
  void partitionOnce();
  void create();
  int assign(const Vec3& x) const;
  std::vector<int> assign(const Vec3& lo, const Vec3& hi) const;
  Box cutBox(int rank) const;

  const Communicator& comm_;
  std::unique_ptr<Zoltan> zoltan_;
  bool balanced_ = false;
  bool directions_chosen_ = false;  // at the first cut (Partition::cut)
  Box bounds_;                      // of every rank's points at the last balance
};

// The largest rank's work over the mean (1 when perfectly balanced). Collective.
double imbalance(const Communicator& comm, double work);

// When a distributed run's entries are cut afresh (docs/parallel.md, "Balance"). An impact moves its
// work around (a crater's points gather neighbours, debris has few), so the balance of the first cut
// drifts: the entries are cut afresh, where they are now and each weighted by its work in the last
// step, once the imbalance passes both `at` and the balance the last cut reached by a twentieth (a
// cut can only part a plate between its layers of points, so it may do no better than the one it
// replaces).
class Rebalance {
 public:
  static constexpr double at = 1.1;
  // This rank's own work in the last step; true, on every rank, when the entries are to be cut
  // afresh. Collective.
  bool due(const Communicator& comm, double own_work);
  // After a cut: the work of each own entry and the rank the cut gave it (the balance it reached,
  // from exact integer sums). Collective.
  void cut(const Communicator& comm, std::span<const double> work, std::span<const int> owner);
  // The largest rank's work over the mean at the last due(), and the largest so far.
  double imbalance() const { return imbalance_; }
  double largestImbalance() const { return largest_imbalance_; }
  // How many cuts afresh.
  int count() const { return count_; }

 private:
  double imbalance_ = 1.0, largest_imbalance_ = 1.0;
  double cut_balance_ = 1.0;
  int count_ = 0;
};

}  // namespace kessler::parallel
