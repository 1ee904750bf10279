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
  int assign(const Vec3& x) const;
  std::vector<int> assign(const Vec3& lo, const Vec3& hi) const;
  Box cutBox(int rank) const;

  const Communicator& comm_;
  std::unique_ptr<Zoltan> zoltan_;
  bool balanced_ = false;
  Box bounds_;  // of every rank's points at the last balance
};

// The largest rank's work over the mean (1 when perfectly balanced). Collective.
double imbalance(const Communicator& comm, double work);

}  // namespace kessler::parallel
