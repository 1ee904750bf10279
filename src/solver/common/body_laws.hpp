#pragma once
// The materials run body by body over the ranges of a method that keeps each body's points together
// (bodyRanges): OTM, SPH and RKPM call the laws through these.
#include "solver/common/particle_state.hpp"

#include <span>
#include <vector>

namespace kessler {

// Material::heat over each body's range: heat[p] joules to point p.
inline void heatBodies(ParticleState& state, std::span<const IndexRange> ranges, std::span<const double> heat) {
  for (std::size_t b = 0; b < state.bodies.size(); ++b) {
    const LocalIndex begin = ranges[b].begin, end = ranges[b].end;
    if (end > begin)
      state.materials[state.bodies[b].material]->heat(
          state.points, begin, end,
          heat.subspan(static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin)));
  }
}

// Material::update over each body's range (throws the law's PointError).
inline void updateBodies(ParticleState& state, std::span<const IndexRange> ranges, double dt) {
  for (std::size_t b = 0; b < state.bodies.size(); ++b)
    state.materials[state.bodies[b].material]->update(state.points, ranges[b].begin, ranges[b].end, dt);
}

}  // namespace kessler
