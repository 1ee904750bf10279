#pragma once
// Sliding contact between bodies (docs/theory.md §11; Zhao & Song, Explosion and Shock Waves
// 30(4), 2010, after the kinematic contact of Hallquist, Goudreau & Benson, CMAME 51:107, 1985).
//
// Each body's surface is a set of triangles whose vertices are its carriers (OTM: its nodes). In a
// step, every surface carrier of one body (a slave) is tested against the triangles of the other
// bodies (the masters), at the positions the step would give them, y = x + du:
// - A slave that has crossed its nearest master triangle (inside its plane by less than the
//   triangle's longest edge, its projection within the triangle) is put back onto the triangle along the triangle's
//   normal n: the slave moves by P n / m_s and each vertex i by -N_i P n / m_i (N_i the barycentric
//   coordinates of the projection), with P = -d / (1/m_s + sum_i N_i^2 / m_i) for the depth d < 0,
//   which closes the gap and leaves the centre of mass where it was.
// - Where slave and contact point approach along n, their normal velocities are made equal by the
//   impulse J = -(v_s - sum_i N_i v_i).n / (1/m_s + sum_i N_i^2 / m_i), given to the slave and taken
//   from the vertices in the same proportions: linear momentum is conserved, and so is angular
//   momentum, the slave and its contact point now coinciding.
// - Coulomb friction: the relative tangential velocity is reduced by an impulse of at most
//   `friction` times J, at most enough to stop the sliding; without friction it is kept.
// - The energy these inelastic exchanges take is the work of their impulses, which contactHeat below
//   counts over a step (OTM and RKPM book it apart: docs/theory.md §11).
// - A slave inside the body beyond an edge or vertex (below the plane of every triangle around its
//   nearest master vertex, its projection on none of them) exchanges its normal velocity with that
//   vertex by the momentum-weighted mean, along the mean of those triangles' normals.
// The slaves are visited in index order, a few times over (a correction moves the vertices that
// other slaves met), so the result is the same for any thread count.
#include "core/exact_sum.hpp"
#include "core/types.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace kessler {

// One step's surfaces: triangles of carrier indices, counter-clockwise seen from outside their body,
// and the carriers on them.
struct ContactSurface {
  std::vector<std::array<LocalIndex, 3>> triangles;
  std::vector<LocalIndex> slaves;  // every vertex of a triangle, once, in index order
};

// The carriers a sliding contact moves: positions at the start of the step, the step's displacement
// and the velocity (both changed), masses, bodies, and the components held by a boundary (bit i:
// component i), which the contact leaves alone. `gap`, if given: per carrier, how far its body's surface lies beyond it
// (a particle method's: half a spacing; OTM's nodes are on it, and give none); a slave then touches
// a triangle when its height above it falls below its own gap and the triangle's (by N_i).
struct SlidingCarriers {
  std::span<const Vec3> x;
  std::span<Vec3> du;
  std::span<Vec3> v;
  std::span<const double> mass;
  std::span<const std::int32_t> body;
  std::span<const std::uint8_t> constrained;
  std::span<const double> gap = {};
};

struct SlidingReport {
  long face_contacts = 0;               // slaves put back onto a master triangle (over all visits)
  long edge_contacts = 0;               // normal velocities exchanged at an edge or vertex
  double deepest_remaining = 0.0;       // after the last visit: the deepest slave below a master triangle, m
  std::vector<std::uint64_t> touching;  // per body: bit b set if it met body b (bodies <= 64)
  // Each contact, in the order made: the slave and the body it met (a debris slave strikes it).
  std::vector<std::pair<LocalIndex, std::int32_t>> met;
};

class SlidingContact {
 public:
  // Without `correct_positions`, a slave found below a master triangle keeps its place and only the
  // velocity exchanges act (a velocity-only kinematic constraint): moving it back creates strain
  // energy that no force paid for, which a method whose surface carriers are not its material's
  // surface (RKPM's coefficients, docs/theory.md §12) cannot afford.
  explicit SlidingContact(double friction, bool correct_positions = true)
      : friction_(friction), correct_positions_(correct_positions) {}

  // Adjusts du and v of the carriers so that no slave ends the step inside a master triangle.
  // `bodies`: the number of bodies, for the touching record.
  SlidingReport apply(const ContactSurface& surface, const SlidingCarriers& carriers, std::size_t bodies) const;

  // Visits of the slaves per step, the last one only measuring.
  static constexpr int visits = 4;

 private:
  double friction_ = 0.0;
  bool correct_positions_ = true;
};

// The heat a contact took in a step (docs/theory.md §11, "Energy"): the work of its impulses
// J_a = m_a (v_a,after - v_a,before) on the carriers, counted as the leapfrog counts a force's work,
// at the mean of the velocities the step starts and ends with: q = -sum_a J_a . (v_a,start +
// v_a,after) / 2, `start(a)` carrier a's velocity before the step's kick. (At the velocities just
// before and after the contact, q would also count the kick a pressed surface takes from its own
// stress every step, which the contact takes off again and no stress power paid.) Summed exactly
// over the first `count` carriers, in index order.
template <class Start>
double contactHeat(std::span<const double> mass, std::span<const Vec3> before, std::span<const Vec3> after,
                   LocalIndex count, Start&& start) {
  ExactSum heat;
  for (LocalIndex a = 0; a < count; ++a) {
    const Vec3 change = after[a] - before[a];
    if (change == Vec3::Zero()) continue;
    heat.add(-mass[a] * change.dot(0.5 * (start(a) + after[a])));
  }
  return heat.value();
}

}  // namespace kessler
