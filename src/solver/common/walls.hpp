#pragma once
// Rigid walls and prescribed velocity components of the carriers of a body's motion (OTM: its
// nodes; a particle method: its particles). Fixed faces and symmetry planes prescribe a component;
// a wall only stops the motion that would cross it.
#include "core/types.hpp"

#include <cstdint>
#include <span>

namespace kessler {

// A frictionless rigid wall, the plane x[axis] = position: carriers stay on the side `side`
// (+1: x[axis] >= position, -1: x[axis] <= position) and slide freely along it.
struct RigidWall {
  int axis = 2;
  double position = 0.0;
  int side = 1;
};

// How far a particle's matter reaches beyond its centre, in its reference spacings: half, to the faces
// of its cell. A particle method's walls and contact keep that reach from them (SPH's and RKPM's).
constexpr double particle_reach = 0.5;

// The velocity v a carrier at x takes for a step dt: the prescribed components (bit i of
// `constrained` set: component i is prescribed[i]), then no wall crossed by its matter, which
// reaches `reach` beyond it towards the wall (0 for OTM's nodes, which lie on the body's surface;
// half a spacing for a particle, whose cell it is the centre of): the normal velocity that would
// carry that matter through a wall is cut to bring it to the wall at the end of the step.
inline void imposeBoundaries(std::uint8_t constrained, const Vec3& prescribed, std::span<const RigidWall> walls,
                             const Vec3& x, double dt, Vec3& v, double reach = 0.0) {
  for (int i = 0; i < 3; ++i)
    if (constrained & (1u << i)) v[i] = prescribed[i];
  for (const RigidWall& wall : walls) {
    const double gap = x[wall.axis] - wall.position;
    if (wall.side * (gap + dt * v[wall.axis]) < reach) v[wall.axis] = (wall.side * reach - gap) / dt;
  }
}

}  // namespace kessler
