#pragma once
// SPH's state (docs/theory.md §10): the shared particle state (solver/common/particle_state.hpp),
// whose material points are the particles, and each particle's prescribed velocity components.
#include "solver/common/particle_bodies.hpp"
#include "solver/common/particle_state.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace kessler::sph {

struct Model : ParticleState {
  // Per particle, in store order: bit a set if velocity component a is prescribed, to prescribed_v[a]
  // (fixed faces, the deck's and the verification problems' planes).
  std::vector<std::uint8_t> constrained;
  std::vector<Vec3> prescribed_v;
  // Each particle's linear viscosity coefficient alpha (the viscosity switch, Integrator).
  std::vector<double> viscosity;
  // The finite-element reconstruction (solver/sph/reconstruction.hpp): each body's lattice, and each
  // particle's element on it ({-1, -1, -1} for a particle of a body that is not a lattice).
  std::vector<LatticeFrame> lattices;
  std::vector<std::array<int, 3>> element;
};

// The particles as one store (particles/store_fields.hpp): the point store and the arrays SPH keeps
// beside it per particle, so that a reordering, a migration or a halo moves them together.
struct Particles {
  PointStore& points;
  std::vector<std::uint8_t>& constrained;
  std::vector<Vec3>& prescribed_v;
  std::vector<double>& viscosity;
  std::vector<std::array<int, 3>>& element;
  std::vector<Vec3>& x;
  std::vector<Index>& id;
  LocalIndex& owned;

  explicit Particles(Model& model)
      : points(model.points),
        constrained(model.constrained),
        prescribed_v(model.prescribed_v),
        viscosity(model.viscosity),
        element(model.element),
        x(model.points.x),
        id(model.points.id),
        owned(model.points.owned) {}

  template <class Store, class Visit>
  static void fields(Store& s, Visit&& visit) {
    PointStore::fields(s.points, visit);
    visit("constrained", s.constrained, std::uint8_t{0});
    visit("prescribed_v", s.prescribed_v, Vec3::Zero().eval());
    visit("viscosity", s.viscosity, 0.0);
    visit("element", s.element, std::array<int, 3>{-1, -1, -1});
  }
};

}  // namespace kessler::sph
