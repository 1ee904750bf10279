#pragma once
// Release of failed material as debris (docs/theory.md §8). A failed point (PointStore::failed:
// fractured by eigenerosion or damage) stays in its body while it bears compression, as a
// hydrocode's failed cell does: a shattered projectile still pushes on the plate it strikes. Once
// it bears none (no pressure, no viscous compression) it is released: it leaves its body as
// debris, flies ballistically and may strike another body (solver/common/debris_contact.hpp).
//
// A released point leaves with the mass-weighted mean velocity of the points of its ball
// B_eps(x_p) that are still part of its body (intact or failed), not with its own: the FLIP-style
// velocity transfer leaves noise on point velocities under shocks (tens of percent of the impact
// speed, invisible while the point moves with the nodes) that would otherwise become its flight
// velocity. The difference m_p (v_p - mean) goes, evenly by mass, to the points of the ball that
// stay, so linear momentum is exact; the kinetic energy the exchange takes becomes internal energy
// of the debris, so the total energy is exact too. A point whose ball keeps nobody (the last of a
// region released at once) takes the mean over the ball's earlier debris as well, and the
// difference goes to those.
//
// The releases run one after another in id order, each ball's sums in id order, over a compact copy
// of the points the balls hold. A distributed run gathers that copy from every rank, so every rank
// computes the same releases in the same order as one process (docs/parallel.md).
//
// A method whose point velocities are not its own but interpolated from its unknowns every step
// (RKPM: from the coefficients, docs/theory.md §12) releases without the exchange: there is no
// transfer noise to take off, and a velocity the release gave a point would be overwritten while the
// heat booked for it stayed, energy made from nothing.
#include "search/cell_list.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/common/particle_state.hpp"

#include <cstdint>
#include <vector>

namespace kessler {

class DebrisRelease {
 public:
  // Whether the points' velocities are the method's own (OTM's, after the transfer from the nodes;
  // SPH's) or interpolated from its unknowns each step (RKPM's).
  enum class Velocities { own, interpolated };
  // erosion_radius: the radius of the ball B_eps as a multiple of the point spacing.
  explicit DebrisRelease(double erosion_radius, Velocities velocities = Velocities::own)
      : erosion_radius_(erosion_radius), exchange_(velocities == Velocities::own) {}
  // Releases every failed point whose stress is zero (it bears no compression), in id order, so
  // that the result depends neither on the thread count nor, with `share` (a distributed run's own
  // points and ranks; collective), on the partition. Returns the number of own points released.
  LocalIndex apply(ParticleState& model, const Share& share = {});

  // One point of a ball, as the releases read and change it.
  struct Member {
    Index id = 0;
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    double mass = 0.0, energy = 0.0;
    double eps = 0.0;  // the ball radius of a releasing point
    std::int32_t body = 0;
    std::uint8_t releasing = 0, debris = 0;
  };

 private:
  // The own points within the ball of a releasing point of their body (`releases`: every rank's
  // releasing points, in id order); `local`: their indices.
  void collect(const PointStore& points, const Share& share, const std::vector<Member>& releases,
               std::vector<Member>& members, std::vector<LocalIndex>& local);
  // The release of members_[k] (docs/theory.md §8), over members_ (in id order).
  void release(std::size_t k);

  double erosion_radius_;
  bool exchange_ = true;  // the velocity exchange with the ball (Velocities::own)
  std::vector<Member> members_;
  CellList cells_;
  std::vector<Vec3> x_;
  std::vector<std::size_t> ball_;  // scratch: one ball's members, in id order
};

}  // namespace kessler
