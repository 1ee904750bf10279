#pragma once
// SPH's state (docs/theory.md §10): the shared particle state (solver/common/particle_state.hpp),
// whose material points are the particles, and each particle's prescribed velocity components.
#include "solver/common/particle_state.hpp"

#include <cstdint>
#include <vector>

namespace kessler::sph {

struct Model : ParticleState {
  // Per particle, in store order: bit a set if velocity component a is prescribed, to prescribed_v[a]
  // (fixed faces, the deck's and the verification problems' planes).
  std::vector<std::uint8_t> constrained;
  std::vector<Vec3> prescribed_v;
  // Each particle's linear viscosity coefficient alpha (Morris & Monaghan's switch, Integrator).
  std::vector<double> viscosity;
};

}  // namespace kessler::sph
