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
#include "search/cell_list.hpp"
#include "solver/common/particle_state.hpp"

#include <vector>

namespace kessler {

class DebrisRelease {
 public:
  // erosion_radius: the radius of the ball B_eps as a multiple of the point spacing.
  explicit DebrisRelease(double erosion_radius) : erosion_radius_(erosion_radius) {}
  // Releases every failed point whose stress is zero (it bears no compression), serially in point
  // order so that the result does not depend on the thread count. Returns the number released.
  LocalIndex apply(ParticleState& model);

 private:
  // The points of the releasing bodies near the releasing points: those still in their body, and
  // the earlier debris.
  void collect(const PointStore& points);
  void release(PointStore& points, LocalIndex p, double eps) const;

  double erosion_radius_;
  std::vector<std::uint8_t> releasing_;      // per point: released in this call
  std::vector<std::uint8_t> body_releases_;  // per body: has a point released in this call
  CellList body_cells_, debris_cells_;
  std::vector<Vec3> body_x_, debris_x_;
  std::vector<LocalIndex> body_points_, debris_;
};

}  // namespace kessler
